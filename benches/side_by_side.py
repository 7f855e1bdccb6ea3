#!/usr/bin/env python3
"""Table of a side-by-side criterion run (benches/side_by_side.sh).

Reads OUT_DIR/<old|new>/round<N>/**/new/{benchmark,estimates}.json and prints
a Markdown table: per benchmark id the median of the per-round medians for
the old and the new checkout, the new/old ratio of each round (rounds pair
runs made minutes apart) and their median, and for every `<id>_instant`
the ratio of `<id>` to it (what the turn-rate-limited plan costs over the
paper's instantaneous turns, in the new checkout).

    python3 benches/side_by_side.py [OUT_DIR]     # default target/side_by_side

Standard library only.
"""

import json
import os
import statistics
import sys


def fmt(ns):
    for unit, scale in (("s", 1e9), ("ms", 1e6), ("µs", 1e3)):
        if ns >= scale:
            return f"{ns / scale:.3g} {unit}"
    return f"{ns:.3g} ns"


def load(root):
    """{side: {round: {full_id: median_ns}}}"""
    data = {}
    for side in ("old", "new"):
        side_dir = os.path.join(root, side)
        if not os.path.isdir(side_dir):
            continue
        for round_name in sorted(os.listdir(side_dir)):
            medians = data.setdefault(side, {}).setdefault(round_name, {})
            for directory, _, files in os.walk(os.path.join(side_dir, round_name)):
                if os.path.basename(directory) != "new" or "estimates.json" not in files:
                    continue
                with open(os.path.join(directory, "benchmark.json")) as f:
                    full_id = json.load(f)["full_id"]
                with open(os.path.join(directory, "estimates.json")) as f:
                    medians[full_id] = json.load(f)["median"]["point_estimate"]
    return data


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join("target", "side_by_side")
    data = load(root)
    old, new = data.get("old", {}), data.get("new", {})
    ids = sorted({i for r in new.values() for i in r} | {i for r in old.values() for i in r})
    print(f"rounds: old {len(old)}, new {len(new)}\n")
    print("| benchmark | old median | new median | new/old per round | new/old (median) |")
    print("|---|---:|---:|---|---:|")
    for full_id in ids:
        olds = [r[full_id] for r in old.values() if full_id in r]
        news = [r[full_id] for r in new.values() if full_id in r]
        ratios = [new[k][full_id] / old[k][full_id] for k in sorted(new)
                  if k in old and full_id in new[k] and full_id in old[k]]
        print(f"| `{full_id}` | {fmt(statistics.median(olds)) if olds else '—'} | "
              f"{fmt(statistics.median(news)) if news else '—'} | "
              f"{', '.join(f'{r:.2f}' for r in ratios) if ratios else '—'} | "
              f"{statistics.median(ratios):.2f} |" if ratios else
              f"| `{full_id}` | {fmt(statistics.median(olds)) if olds else '—'} | "
              f"{fmt(statistics.median(news)) if news else '—'} | — | — |")
    instant = [i for i in ids if i.endswith("_instant")]
    if instant:
        print("\n| benchmark (new) | turn-rate-limited | instantaneous | ratio per round | ratio (median) |")
        print("|---|---:|---:|---|---:|")
        for inst in instant:
            base = inst[: -len("_instant")]
            pairs = [(r[base], r[inst]) for r in (new[k] for k in sorted(new))
                     if base in r and inst in r]
            if not pairs:
                continue
            ratios = [b / i for b, i in pairs]
            print(f"| `{base}` | {fmt(statistics.median(b for b, _ in pairs))} | "
                  f"{fmt(statistics.median(i for _, i in pairs))} | "
                  f"{', '.join(f'{r:.2f}' for r in ratios)} | {statistics.median(ratios):.2f} |")


if __name__ == "__main__":
    main()
