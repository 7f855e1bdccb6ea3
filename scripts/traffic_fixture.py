#!/usr/bin/env python3
"""Writes a scenario of ownship among N vessels spread over open water
(decision 33, issue 24: many vessels, most never within reach of ownship).

Ownship sails 8 nm north at 12 kn from the origin; N targets start anywhere
in the square of half-side H nm (default 12) centred on ownship's route (at
least 1 nm from ownship's start), on any course at 5 to 15 kn, holding it.
Deterministic for a seed (`python3 scripts/traffic_fixture.py N SEED [H]`):

    python3 scripts/traffic_fixture.py 100 7 > crates/scenarios/fixtures/traffic/traffic_100.ron
    python3 scripts/traffic_fixture.py 256 7 > crates/scenarios/fixtures/traffic/traffic_256.ron
"""
import math
import random
import sys


def main() -> None:
    count, seed = int(sys.argv[1]), int(sys.argv[2])
    half_nm = float(sys.argv[3]) if len(sys.argv) > 3 else 12.0
    rng = random.Random(seed)
    lines = [
        f"// Ownship among {count} vessels on steady courses over open water, most never",
        "// within reach of it (decision 33: the checks skip those exactly). Written by",
        f"// `python3 scripts/traffic_fixture.py {count} {seed} {half_nm:g}`; not embedded in the library.",
        "Scenario(",
        f'    name: "traffic_{count}",',
        f'    description: "Ownship 8 nm north among {count} vessels spread over {2 * half_nm:g} nm x {2 * half_nm:g} nm on steady courses (scripts/traffic_fixture.py {count} {seed} {half_nm:g}).",',
        "    ownship: Vessel(",
        '        name: "ownship",',
        "        start_nm: (0.0, 0.0),",
        "        course_deg: 0.0,",
        "        speed_kn: 12.0,",
        "        length_m: 100.0,",
        "        goal_nm: (0.0, 8.0),",
        "    ),",
        "    targets: [",
    ]
    placed = 0
    while placed < count:
        x, y = rng.uniform(-half_nm, half_nm), rng.uniform(4.0 - half_nm, 4.0 + half_nm)
        if math.hypot(x, y) < 1.0:
            continue
        course = rng.uniform(0.0, 360.0)
        speed = rng.uniform(5.0, 15.0)
        placed += 1
        lines.append(
            f'        Vessel(name: "T{placed:03}", start_nm: ({x:.3f}, {y:.3f}), '
            f"course_deg: {course:.1f}, speed_kn: {speed:.1f}, length_m: 150.0, "
            "behaviour: ConstantVelocity),"
        )
    lines += ["    ],", ")"]
    print("\n".join(lines))


if __name__ == "__main__":
    main()
