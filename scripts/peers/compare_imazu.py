#!/usr/bin/env python3
"""Table of vorrt against colregs-planner on the Imazu cases, for docs/performance.md.

Reads rounds made alternately in one session:
    DIR/vorrt_<N>.csv          cargo run --release --example imazu_timing -- 3 1 > DIR/vorrt_<N>.csv
    DIR/peer_<N>/summary.csv   python3 scripts/peers/colregs_planner_imazu.py DIR/peer_<N>
and prints a Markdown table: per case the median over the rounds of vorrt's
and the peer's wall time of the whole closed loop, their ratio, the simulated
time of each, the ratio per simulated hour, vorrt's planner calls and the
peer's policy calls (mean time per call), and both smallest distances.

    python3 scripts/peers/compare_imazu.py DIR

Standard library only.
"""

import csv
import glob
import os
import statistics
import sys


def rows(path):
    with open(path, newline="") as f:
        return {r["case"]: r for r in csv.DictReader(f)}


def ratio_text(ratio):
    return f"{ratio:.2f}" if ratio < 1 else f"{ratio:.1f}" if ratio < 10 else f"{ratio:.0f}"


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    vorrt = [rows(p) for p in sorted(glob.glob(os.path.join(root, "vorrt_*.csv")))]
    peer = [rows(p) for p in sorted(glob.glob(os.path.join(root, "peer_*", "summary.csv")))]
    if not vorrt or not peer:
        sys.exit(f"{root}: needs vorrt_<N>.csv and peer_<N>/summary.csv")
    cases = sorted(c for c in peer[0] if c != "total")
    med = lambda runs, case, key: statistics.median(float(r[case][key]) for r in runs)
    print(f"rounds: vorrt {len(vorrt)}, peer {len(peer)}\n")
    print("| case | peer ms | vorrt ms | peer/vorrt | simulated s (peer, vorrt) | per simulated hour | "
          "vorrt planner calls (retries) | peer call mean ms | peer min distance m (hulls) | vorrt min distance m |")
    print("|---|---:|---:|---:|---|---:|---|---:|---|---:|")
    totals = {"peer": 0.0, "vorrt": 0.0, "peer_h": 0.0, "vorrt_h": 0.0}
    ratios = []
    for case in cases:
        p_ms, v_ms = med(peer, case, "wall_ms"), med(vorrt, case, "wall_ms")
        p_s, v_s = float(peer[-1][case]["simulated_s"]), float(vorrt[-1][case]["simulated_s"])
        totals["peer"] += p_ms
        totals["vorrt"] += v_ms
        totals["peer_h"] += p_s / 3600
        totals["vorrt_h"] += v_s / 3600
        ratio = p_ms / v_ms
        ratios.append(ratio)
        hourly = (p_ms / p_s) / (v_ms / v_s)
        last_p, last_v = peer[-1][case], vorrt[-1][case]
        print(f"| {case} | {p_ms:.0f} | {v_ms:.1f} | {ratio_text(ratio)} | {p_s:.0f}, {v_s:.0f} | {ratio_text(hourly)} | "
              f"{last_v['planner_calls']} ({last_v['retry']}) | {med(peer, case, 'call_mean_ms'):.2f} | "
              f"{float(last_p['min_distance_m']):.1f} ({float(last_p['min_hull_distance_m']):.1f}) | "
              f"{float(last_v['min_distance_m']):.0f} |")
    total_ratio = totals["peer"] / totals["vorrt"]
    hourly = (totals["peer"] / totals["peer_h"]) / (totals["vorrt"] / totals["vorrt_h"])
    print(f"| **total** | {totals['peer']:.0f} | {totals['vorrt']:.0f} | {ratio_text(total_ratio)} | "
          f"{totals['peer_h'] * 3600:.0f}, {totals['vorrt_h'] * 3600:.0f} | {ratio_text(hourly)} | | | | |")
    print(f"\nmedian per-case ratio {statistics.median(ratios):.0f}; cases at least 50x: "
          f"{sum(r >= 50 for r in ratios)} of {len(ratios)}")
    dearest = max(cases, key=lambda c: med(vorrt, c, "wall_ms"))
    rest = [c for c in cases if c != dearest]
    p_rest = sum(med(peer, c, "wall_ms") for c in rest)
    v_rest = sum(med(vorrt, c, "wall_ms") for c in rest)
    print(f"without {dearest} (vorrt's dearest case): peer {p_rest:.0f} ms, vorrt {v_rest:.0f} ms, "
          f"ratio {p_rest / v_rest:.1f}")


if __name__ == "__main__":
    main()
