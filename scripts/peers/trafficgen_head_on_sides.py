#!/usr/bin/env python3
"""On which side ownship passes the head-on targets of trafficgen situations.

    python3 scripts/peers/trafficgen_head_on_sides.py VORRT SCENARIO_DIR OUT_DIR

SCENARIO_DIR holds the scenarios `trafficgen_scenarios.py` wrote (their
names end in the situation's kind, e.g. `-HO-CR-GW`; the targets are named
TS1, TS2, ... in the kind's order). Each situation with a head-on target
is run with `VORRT simulate` (into OUT_DIR/<name>/), and the head-on
target's side is read at the closest approach from `trajectory.csv`: on
ownship's port side as ownship then heads (port to port, rule 14(a)) or on
its starboard side. The generator defines the encounter from the start, 10-20
minutes before the closest approach, where vorrt's evaluation latches it only
within MTD (decision 72). Prints every starboard-to-starboard pass and a
count; exits 0.
"""
import csv
import math
import os
import subprocess
import sys
from pathlib import Path


def kinds(name):
    """The encounter kinds of a situation's targets, in order (HO, CR-GW, ...)."""
    parts = name.split("-")[3:]
    out, i = [], 0
    while i < len(parts):
        if parts[i] == "HO":
            out.append("HO")
            i += 1
        else:
            out.append("-".join(parts[i : i + 2]))
            i += 2
    return out


def side_at_closest(trajectory, target):
    """(distance m, True where the target lies on ownship's port side) at
    the closest approach."""
    rows = list(csv.DictReader(open(trajectory)))
    own = [r for r in rows if r["vessel"] == "ownship"]
    other = [r for r in rows if r["vessel"] == target]
    best = None
    for o, t in zip(own, other):
        dx = float(t["east_m"]) - float(o["east_m"])
        dy = float(t["north_m"]) - float(o["north_m"])
        distance = math.hypot(dx, dy)
        if best is None or distance < best[0]:
            course = math.radians(float(o["course_deg"]))
            # Heading (sin, cos) crossed with the relative position: > 0 to port.
            best = (distance, math.sin(course) * dy - math.cos(course) * dx > 0.0)
    return best


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    vorrt, scenarios, out = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    out.mkdir(parents=True, exist_ok=True)
    total, starboard = 0, []
    for path in sorted(scenarios.glob("*.ron")):
        name = path.stem
        situation = kinds(name)
        if "HO" not in situation:
            continue
        run = out / name
        subprocess.run(
            [vorrt, "simulate", str(path), "--out", str(run)],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            check=False,
        )
        trajectory = run / "trajectory.csv"
        if not os.path.exists(trajectory):
            print(f"{name}: no trajectory written", file=sys.stderr)
            continue
        for index, kind in enumerate(situation):
            if kind != "HO":
                continue
            total += 1
            distance, to_port = side_at_closest(trajectory, f"TS{index + 1}")
            if not to_port:
                starboard.append((name, f"TS{index + 1}", distance))
    for name, target, distance in starboard:
        print(f"{name} {target}: passed starboard to starboard, {distance:.0f} m")
    print(f"{total} head-on targets; {len(starboard)} passed starboard to starboard")
    return 0


if __name__ == "__main__":
    sys.exit(main())
