#!/usr/bin/env python3
"""Before → after tables of two campaigns, for docs/evaluation.md.

    scripts/compare_campaigns.py BEFORE_DIR AFTER_DIR

Each directory holds the batch folders of a campaign (`vorrt batch --out
DIR/<name>`, each with its rows.csv): os<N>-constant-250 for N in 1, 2, 4, 8
(issue 11's 1000 constant-target runs, 250 each) and <kind>-<behaviour> for
the rest (kind os<N> or tss<D>, as scripts/campaign.sh names them). Rows
missing from either directory are left out. Standard library only.
"""
import csv
import os
import statistics
import sys


def rows(root, name):
    with open(os.path.join(root, name, "rows.csv"), newline="") as f:
        return list(csv.DictReader(f))


def figures(runs):
    count = len(runs)
    true = lambda key: sum(r[key] == "true" for r in runs)
    give_way = sum(int(r["give_way_encounters"]) for r in runs)
    share = lambda key: 100 * sum(int(r[key]) for r in runs) / give_way if give_way else 0.0
    safe = sum(
        r["reached_goal"] == "true" and r["clearance_violation"] != "true" and r["collision"] != "true"
        for r in runs
    )
    return {
        "success": 100 * safe / count,
        "collisions": true("collision"),
        "dth": true("clearance_violation"),
        "goal": true("reached_goal"),
        "rate": max(float(r["max_turn_rate_deg_s"]) for r in runs),
        "reversals": statistics.median(float(r["turn_reversals"]) for r in runs),
        "course_change": statistics.median(float(r["course_change_deg_per_nm"]) for r in runs),
        "apparent": share("give_way_apparent"),
        "early": share("give_way_early"),
        "no_finding": 100 * true("compliant") / count,
        "departing": sum(r["rule_departures"] not in ("", "0") for r in runs),
        "planning_ms": statistics.mean(float(r["planning_time_ms"]) for r in runs),
    }


def constant_row(label, a, b):
    return (
        f"| {label} | {a['success']:.1f} → {b['success']:.1f} % | {a['collisions']} → {b['collisions']} "
        f"| {a['dth']} → {b['dth']} | {a['rate']:.2f} → {b['rate']:.2f}°/s "
        f"| {a['reversals']:.0f} → {b['reversals']:.0f} | {a['course_change']:.1f} → {b['course_change']:.1f}°/nm "
        f"| {a['apparent']:.1f} → {b['apparent']:.1f} % | {a['early']:.1f} → {b['early']:.1f} % "
        f"| {a['no_finding']:.1f} → {b['no_finding']:.1f} % | {a['departing']} → {b['departing']} |"
    )


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    before, after = sys.argv[1], sys.argv[2]
    present = lambda name: all(os.path.exists(os.path.join(d, name, "rows.csv")) for d in (before, after))
    print("Constant targets, 250 runs each:\n")
    print(
        "| targets | success | collisions | d_th broken | largest rate of turn | reversals p50 "
        "| course change p50 | readily apparent | begun early | no finding | runs departing from the rules |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    all_before, all_after = [], []
    for targets in (1, 2, 4, 8):
        name = f"os{targets}-constant-250"
        if not present(name):
            continue
        a, b = rows(before, name), rows(after, name)
        all_before += a
        all_after += b
        print(constant_row(str(targets), figures(a), figures(b)))
    if all_before:
        print(constant_row(f"all {len(all_after)}", figures(all_before), figures(all_after)))
    print("\nEvery other row, 1000 runs each:\n")
    print(
        "| scenarios | behaviour | collisions | d_th broken | goal reached | no finding "
        "| runs departing from the rules | planning ms per run, mean |"
    )
    print("|---|---|---|---|---|---|---|---|")
    for behaviour in ("colregs", "noisy", "sudden-turn", "constant"):
        for kind in ("os2", "os4", "os8", "os16", "tss1", "tss3"):
            name = f"{kind}-{behaviour}"
            if not present(name):
                continue
            a, b = figures(rows(before, name)), figures(rows(after, name))
            label = f"open sea, {kind[2:]} targets" if kind.startswith("os") else f"TSS westbound, {kind[3:]}/nm"
            print(
                f"| {label} | {behaviour} | {a['collisions']} → {b['collisions']} | {a['dth']} → {b['dth']} "
                f"| {a['goal']} → {b['goal']} | {a['no_finding']:.1f} → {b['no_finding']:.1f} % "
                f"| {a['departing']} → {b['departing']} | {a['planning_ms']:.0f} → {b['planning_ms']:.0f} |"
            )


if __name__ == "__main__":
    main()
