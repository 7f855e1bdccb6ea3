#!/usr/bin/env python3
"""Prints the open issues' "Done when" criteria beside their targets, from
the batch folders that scripts/done_when.sh writes (each with rows.csv;
times.txt beside them: "<folder> <wall s> <user s> <system s>").

    python3 scripts/done_when.py OUT

Issue 24 (open sea): collisions, d_th kept, port return turns onto a
port-side vessel (`port_turn_toward_vessel`), runs with no finding, median
path overhead, goal reached. Issue 22 (coastal and TSS): groundings,
collisions, d_th kept, square lane crossings, runs in a separation zone,
median path overhead of TSS crossings. A criterion is "met" or "NOT met".
"""
import csv
import os
import statistics
import sys


def rows(folder):
    path = os.path.join(folder, "rows.csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def true(row, key):
    return row.get(key, "").strip().lower() == "true"


def number(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        return None


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else float("nan")


def verdict(ok):
    return "met" if ok else "NOT met"


def times(root):
    found = {}
    path = os.path.join(root, "times.txt")
    if os.path.exists(path):
        for line in open(path):
            parts = line.split()
            if len(parts) >= 4:
                found[parts[0]] = (float(parts[1]), float(parts[2]) + float(parts[3]))
    return found


def open_sea(root, clock):
    print("## Issue 24: open sea\n")
    print("| targets | behaviour | runs | collisions | d_th kept | port return onto a port-side vessel (runs) | no finding | path overhead p50 | goal reached | wall s | CPU s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    verdicts = []
    for behaviour in ["constant", "colregs"]:
        for n in [2, 4, 8, 16]:
            name = f"os{n}-{behaviour}"
            got = rows(os.path.join(root, name))
            if not got:
                continue
            runs = len(got)
            collisions = sum(true(r, "collision") for r in got)
            kept = sum(not true(r, "clearance_violation") for r in got) / runs
            port = sum("port_turn_toward_vessel" in r.get("violations", "") for r in got)
            clean = sum(true(r, "compliant") for r in got) / runs
            overhead = median(number(r, "path_overhead_pct") for r in got)
            goal = sum(true(r, "reached_goal") for r in got)
            wall, cpu = clock.get(name, (float("nan"), float("nan")))
            print(f"| {n} | {behaviour} | {runs} | {collisions} | {100 * kept:.1f} % | {port} | {100 * clean:.1f} % | {overhead:.1f} % | {goal} | {wall:.0f} | {cpu:.0f} |")
            verdicts += [
                (f"os{n} {behaviour}: 0 collisions", collisions == 0),
                (f"os{n} {behaviour}: d_th kept >= 99.5 %", kept >= 0.995),
                (f"os{n} {behaviour}: no port return turn", port == 0),
                (f"os{n} {behaviour}: no finding >= {90 if n <= 8 else 75} %", clean >= (0.90 if n <= 8 else 0.75)),
                (f"os{n} {behaviour}: path overhead p50 <= {5 if n <= 8 else 10} %", overhead <= (5 if n <= 8 else 10)),
                (f"os{n} {behaviour}: every run reaches its goal", goal == runs),
            ]
    return verdicts


def coastal_and_tss(root, clock):
    print("\n## Issue 22: coastal waters and traffic separation schemes\n")
    print("| campaign | behaviour | runs | groundings | collisions | d_th kept | lane crossings | square | runs in a zone | path overhead p50 | goal reached | wall s | CPU s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    verdicts = []
    everything = []
    tss_overheads = []
    crossings = square = zone_runs = 0
    for behaviour in ["constant", "colregs"]:
        for name in [f"coastal{n}" for n in [1, 2, 4, 8]] + ["tss-westbound", "tss-two-way"]:
            folder = f"{name}-{behaviour}"
            got = rows(os.path.join(root, folder))
            if not got:
                continue
            everything += got
            runs = len(got)
            ground = sum(true(r, "grounding") for r in got)
            collisions = sum(true(r, "collision") for r in got)
            kept = sum(not true(r, "clearance_violation") for r in got) / runs
            lane = sum(int(number(r, "lane_crossings") or 0) for r in got)
            sq = sum(int(number(r, "lane_crossings_square") or 0) for r in got)
            zone = sum((number(r, "separation_zone_entries") or 0) > 0 for r in got)
            overhead = median(number(r, "path_overhead_pct") for r in got)
            goal = sum(true(r, "reached_goal") for r in got)
            if name.startswith("tss"):
                tss_overheads += [number(r, "path_overhead_pct") for r in got]
            crossings, square, zone_runs = crossings + lane, square + sq, zone_runs + zone
            wall, cpu = clock.get(folder, (float("nan"), float("nan")))
            share = f"{100 * sq / lane:.1f} %" if lane else "-"
            print(f"| {name} | {behaviour} | {runs} | {ground} | {collisions} | {100 * kept:.1f} % | {lane} | {share} | {zone} | {overhead:.1f} % | {goal} | {wall:.0f} | {cpu:.0f} |")
    if everything:
        runs = len(everything)
        kept = sum(not true(r, "clearance_violation") for r in everything) / runs
        verdicts += [
            ("coastal+TSS: 0 groundings", sum(true(r, "grounding") for r in everything) == 0),
            ("coastal+TSS: 0 collisions", sum(true(r, "collision") for r in everything) == 0),
            ("coastal+TSS: d_th kept >= 99 %", kept >= 0.99),
            ("TSS: lane crossings square >= 95 %", crossings > 0 and square / crossings >= 0.95),
            ("TSS: no run in a separation zone", zone_runs == 0),
            ("TSS: path overhead p50 <= 15 %", median(tss_overheads) <= 15),
        ]
        print(f"\nAll {runs} runs: d_th kept in {100 * kept:.1f} %; TSS path overhead p50 {median(tss_overheads):.1f} %.")
    return verdicts


def main():
    root = sys.argv[1]
    clock = times(root)
    verdicts = open_sea(root, clock) + coastal_and_tss(root, clock)
    print("\n## Criteria\n")
    for text, ok in verdicts:
        print(f"- {verdict(ok)}: {text}")


if __name__ == "__main__":
    main()
