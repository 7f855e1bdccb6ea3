#!/usr/bin/env python3
"""Encounter situations from DNV's traffic generator, as vorrt scenarios.

    python scripts/peers/trafficgen_scenarios.py OUT_DIR [--per-kind N] [--seed S] [--behaviour B]

Not a build dependency of vorrt: a source of encounters drawn as another
tool draws them, for docs/evaluation.md. Needs the generator in the running
Python (`pip install trafficgen`, tested with 0.9.1).

Runs `trafficgen` (DNV's ship traffic generator) on the situation kinds
below, with one own ship (100 m, 12 kn, north from 58.5° N
10.5° E) and target ships of 80-200 m, and writes each generated situation
twice: as trafficgen wrote it (OUT_DIR/trafficgen/*.json) and as a
geographic vorrt scenario (OUT_DIR/scenarios/*.ron), every vessel steering
from its first to its last trafficgen waypoint at its trafficgen speed (the
targets with vorrt's behaviour B if given, e.g. `Colregs`: they then obey
the rules toward ownship; docs/scenario-format.md). Run them with

    vorrt batch --dir OUT_DIR/scenarios --out runs/trafficgen

Every random choice of trafficgen is drawn from Python's `random`, seeded
here with S (default 11), so the same S gives the same situations.
trafficgen's own encounter settings are used (its package's
settings/encounter_settings.json); vector times are 10-20 minutes, so that
each situation begins 10-20 minutes before the closest approach of every
target to ownship's straight course.
"""

import argparse
import json
import random
import tempfile
from pathlib import Path

# (kind, encounter types): one to three targets, every encounter type.
KINDS = [
    ("HO", ["head-on"]),
    ("CR-GW", ["crossing-give-way"]),
    ("CR-SO", ["crossing-stand-on"]),
    ("OT-GW", ["overtaking-give-way"]),
    ("OT-SO", ["overtaking-stand-on"]),
    ("HO-CR-GW", ["head-on", "crossing-give-way"]),
    ("CR-GW-CR-SO", ["crossing-give-way", "crossing-stand-on"]),
    ("OT-GW-HO", ["overtaking-give-way", "head-on"]),
    ("CR-SO-OT-SO", ["crossing-stand-on", "overtaking-stand-on"]),
    ("HO-CR-GW-CR-SO", ["head-on", "crossing-give-way", "crossing-stand-on"]),
    ("OT-GW-CR-GW-CR-SO", ["overtaking-give-way", "crossing-give-way", "crossing-stand-on"]),
    ("CR-GW-CR-GW-HO", ["crossing-give-way", "crossing-give-way", "head-on"]),
]

OWN_SHIP = {"id": 1, "name": "own ship", "mmsi": 257000001, "shipType": "Cargo",
            "dimensions": {"length": 100.0, "width": 16.0}, "sogMin": 5.0, "sogMax": 17.0}
TARGET_SHIPS = [
    {"name": f"target {length:.0f} m", "mmsi": 257000100 + index, "shipType": "Cargo",
     "dimensions": {"length": length, "width": length / 6.5}, "sogMin": 5.0, "sogMax": 17.0}
    for index, length in enumerate([80.0, 120.0, 150.0, 200.0])
]
OWN_START = {"lat": 58.5, "lon": 10.5}
OWN_SPEED_KN = 12.0


def write_inputs(root, per_kind):
    """Situation, own-ship and target-ship inputs, in trafficgen's file layout."""
    situations = root / "situations"
    targets = root / "target_ships"
    situations.mkdir()
    targets.mkdir()
    for kind, encounters in KINDS:
        situation = {
            "title": kind,
            "description": f"{kind}: {', '.join(encounters)}",
            "numSituations": per_kind,
            "ownShip": {"initial": {"position": OWN_START, "sog": OWN_SPEED_KN, "cog": 0.0, "heading": 0.0}},
            "encounters": [{"desiredEncounterType": kind_of, "vectorTime": [10.0, 20.0]} for kind_of in encounters],
        }
        (situations / f"{kind}.json").write_text(json.dumps(situation, indent=1))
    (root / "own_ship.json").write_text(json.dumps(OWN_SHIP, indent=1))
    for index, ship in enumerate(TARGET_SHIPS):
        (targets / f"target_{index}.json").write_text(json.dumps(ship, indent=1))


def vessel(name, ship, length_m, behaviour=None):
    """A vorrt `Vessel(...)` from a trafficgen ship: first to last waypoint."""
    waypoints = ship["waypoints"]
    first, last = waypoints[0]["position"], waypoints[-1]["position"]
    initial = ship["initial"]
    speed_kn = initial.get("sog", waypoints[0].get("leg", {}).get("sog"))
    course_deg = initial.get("cog", initial.get("heading", 0.0)) % 360.0
    return (
        f'Vessel(name: "{name}", start_lat_lon: ({first["lat"]:.8f}, {first["lon"]:.8f}), '
        f"course_deg: {course_deg:.4f}, speed_kn: {speed_kn:.4f}, length_m: {length_m:.1f}, "
        f'goal_lat_lon: ({last["lat"]:.8f}, {last["lon"]:.8f})'
        + (f", behaviour: {behaviour}" if behaviour else "")
        + ")"
    )


def scenario(name, situation, behaviour=None):
    """The vorrt scenario (RON text) of one trafficgen situation."""
    own = situation["ownShip"]
    own_length = own.get("static", {}).get("dimensions", {}).get("length", OWN_SHIP["dimensions"]["length"])
    targets = []
    for index, ship in enumerate(situation.get("targetShips", [])):
        length = ship.get("static", {}).get("dimensions", {}).get("length", 100.0)
        targets.append("        " + vessel(f"TS{index + 1}", ship, length, behaviour) + ",")
    return "\n".join([
        f"// {situation.get('description', name)} (trafficgen {situation.get('trafficgenVersion', '')}).",
        "Scenario(",
        f'    name: "{name}",',
        f'    description: "DNV trafficgen: {situation.get("description", name)}",',
        "    ownship: " + vessel("ownship", own, own_length) + ",",
        "    targets: [",
        *targets,
        "    ],",
        ")",
        "",
    ])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("--per-kind", type=int, default=5, help="situations of each kind (default 5)")
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--behaviour", help="the targets' vorrt behaviour (default: ConstantToGoal)")
    args = parser.parse_args()
    import trafficgen
    from trafficgen.ship_traffic_generator import generate_traffic_situations
    from trafficgen.write_traffic_situation_to_file import write_traffic_situations_to_json_file

    settings = Path(trafficgen.__file__).parent / "settings" / "encounter_settings.json"
    random.seed(args.seed)
    generated = args.out / "trafficgen"
    scenarios = args.out / "scenarios"
    scenarios.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as temporary:
        root = Path(temporary)
        write_inputs(root, args.per_kind)
        situations = generate_traffic_situations(
            root / "situations", root / "own_ship.json", root / "target_ships", settings
        )
    write_traffic_situations_to_json_file(situations, generated)
    written = 0
    for path in sorted(generated.glob("*.json")):
        situation = json.loads(path.read_text())
        # trafficgen keeps a situation even where it found no target for an
        # encounter; such a situation is left out.
        if len(situation.get("targetShips", [])) == 0:
            continue
        name = f"trafficgen-s{args.seed}-{path.stem.split('_')[-1]}-{situation.get('title', 'situation')}"
        (scenarios / f"{name}.ron").write_text(scenario(name, situation, args.behaviour))
        written += 1
    print(f"{len(situations)} situations generated, {written} scenarios written to {scenarios}")


if __name__ == "__main__":
    main()
