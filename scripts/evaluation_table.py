#!/usr/bin/env python3
"""Prints the results table of docs/evaluation.md from batch outputs.

    scripts/evaluation_table.py RUNS_DIR

RUNS_DIR holds one folder per batch (directly, as scripts/campaign.sh
writes them, or under RUNS_DIR/runs/), named <kind>-<behaviour> with kind
os<N> (open sea, N targets) or tss<D> (TSS, D targets per nm), each with the
summary.json and run.json that `vorrt batch` writes; times.txt beside them
(lines "<folder> <seconds> s") gives the wall time.
"""
import json
import os
import sys


def pct(x):
    return f"{100 * x:.1f} %"


def rule_cell(rules, number):
    for rule in rules:
        if rule["rule"] == number and rule["applicable"]:
            return f"{100 * rule['rate']:.0f} % ({rule['applicable']})"
    return "-"


def main():
    root = sys.argv[1]
    times = {}
    path = os.path.join(root, "times.txt")
    if os.path.exists(path):
        for line in open(path):
            parts = line.split()
            if len(parts) >= 2 and parts[1].isdigit():
                times[parts[0]] = int(parts[1])
    order = []
    for behaviour in ["constant", "colregs", "noisy", "sudden-turn"]:
        for kind in ["os2", "os4", "os8", "os16", "tss1", "tss3"]:
            order.append(f"{kind}-{behaviour}")
    print("| scenarios | behaviour | runs | success | collision | clearance violated | compliant | r13 | r14 | r15 | r16 | r17 | min dist p1 / p10 / p50 (m) | overhead p50 / p90 (%) | planning ms per call p50 / p99 | replans p50 / p90 | failed plans (runs with any) | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name in order:
        summary_path = os.path.join(root, name, "summary.json")
        if not os.path.exists(summary_path):
            summary_path = os.path.join(root, "runs", name, "summary.json")
        if not os.path.exists(summary_path):
            continue
        s = json.load(open(summary_path))
        kind, behaviour = name.split("-", 1)
        label = f"open sea, {kind[2:]} targets" if kind.startswith("os") else f"TSS westbound, {kind[3:]}/nm"
        md, oh, pt, rp = s["min_distance_m"], s["path_overhead_pct"], s["planning_time_per_plan_ms"], s["replans"]
        print(
            f"| {label} | {behaviour} | {s['count']} | {pct(s['success_rate'])} | {pct(s['collision_rate'])} | "
            f"{pct(s['clearance_violation_rate'])} | {pct(s['compliance_rate'])} | "
            + " | ".join(rule_cell(s["rules"], n) for n in range(13, 18))
            + f" | {md['p1']:.0f} / {md['p10']:.0f} / {md['p50']:.0f} | {oh['p50']:.1f} / {oh['p90']:.1f} | "
            f"{pt['p50']:.2f} / {pt['p99']:.1f} | {rp['p50']:.0f} / {rp['p90']:.0f} | "
            f"{s['failed_plans']} ({s['runs_with_failed_plans']}) | {times.get(name, '?')} |"
        )
    print()
    print("| scenarios | behaviour | runs | largest rate of turn max (°/s) | reversals p50 / p90 | course change p50 / p90 (°/nm) | give-way encounters | readily apparent | begun early | runs departing from the rules |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name in order:
        summary_path = os.path.join(root, name, "summary.json")
        if not os.path.exists(summary_path):
            summary_path = os.path.join(root, "runs", name, "summary.json")
        if not os.path.exists(summary_path):
            continue
        s = json.load(open(summary_path))
        if "turn_reversals" not in s:
            continue
        kind, behaviour = name.split("-", 1)
        label = f"open sea, {kind[2:]} targets" if kind.startswith("os") else f"TSS westbound, {kind[3:]}/nm"
        rate, rev, cc = s["max_turn_rate_deg_s"], s["turn_reversals"], s["course_change_deg_per_nm"]
        share = lambda x: "-" if x is None else pct(x)
        print(
            f"| {label} | {behaviour} | {s['count']} | {rate['max']:.2f} | {rev['p50']:.0f} / {rev['p90']:.0f} | "
            f"{cc['p50']:.1f} / {cc['p90']:.1f} | {s['give_way_encounters']} | {share(s['give_way_apparent_rate'])} | "
            f"{share(s['give_way_early_rate'])} | {s['runs_with_rule_departures']} |"
        )


if __name__ == "__main__":
    main()
