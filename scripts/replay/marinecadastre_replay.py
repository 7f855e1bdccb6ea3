#!/usr/bin/env python3
"""A MarineCadastre AIS CSV (BaseDateTime,LON,LAT,MMSI,SOG,COG,...) into a
vorrt replay (decision 40): SCENARIO.ron plus SCENARIO.tracks.csv, ownship
MMSI from its first report (goal: its last position), every other vessel
seen by then within --range-nm following its recorded track.

    python3 scripts/replay/marinecadastre_replay.py AIS.csv --ownship MMSI --out DIR/NAME.ron

Vessels first seen after ownship's start are left out (a recording cannot
say where they were before), and so are vessels inside d_th of ownship at
the start (vorrt check refuses such a scenario). Standard library only.
"""

import argparse
import csv
import math
import sys
from collections import defaultdict
from datetime import datetime, timezone

EARTH_RADIUS_M = 6_371_008.8
DEFAULT_LENGTH_M = 50.0
D_TH_M = 200.0


def unix_s(text):
    return datetime.fromisoformat(text).replace(tzinfo=timezone.utc).timestamp()


def local_m(origin, lat, lon):
    """East and north of (lat, lon) from origin, metres (equirectangular:
    a check for the range filter only; vorrt projects the positions itself)."""
    east = math.radians(lon - origin[1]) * EARTH_RADIUS_M * math.cos(math.radians(origin[0]))
    north = math.radians(lat - origin[0]) * EARTH_RADIUS_M
    return east, north


def number(text, default=None):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return default
    return value if math.isfinite(value) else default


def read(path):
    vessels = defaultdict(list)
    names, lengths = {}, {}
    with open(path, newline="") as file:
        for row in csv.DictReader(file):
            mmsi = row["MMSI"].strip()
            lat, lon = number(row["LAT"]), number(row["LON"])
            if lat is None or lon is None:
                continue
            vessels[mmsi].append(
                (unix_s(row["BaseDateTime"]), lat, lon, number(row["COG"]), number(row["SOG"]))
            )
            names.setdefault(mmsi, (row.get("VesselName") or "").strip() or f"MMSI {mmsi}")
            length = number(row.get("Length"))
            if length and length > 0:
                lengths[mmsi] = min(length, 1000.0)
    for reports in vessels.values():
        reports.sort()
    return vessels, names, lengths


def course(cog):
    # MarineCadastre writes COG in (-360, 360]; 360 and above "not available".
    return None if cog is None or abs(cog) >= 360 else cog % 360


def speed(sog):
    return None if sog is None or sog < 0 or sog >= 102.3 else sog


def ron_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def vessel_ron(name, mmsi, report, length_m, extra=""):
    _, lat, lon, cog, sog = report
    return (
        f"Vessel(name: {ron_string(name)}, course_deg: {course(cog) or 0.0}, "
        f"speed_kn: {speed(sog) or 0.0}, length_m: {length_m}, start_lat_lon: ({lat}, {lon}), "
        f"mmsi: {mmsi}{extra})"
    )


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ais_csv")
    parser.add_argument("--ownship", required=True, help="ownship's MMSI")
    parser.add_argument("--out", required=True, help="the scenario to write, NAME.ron")
    parser.add_argument("--range-nm", type=float, default=5.0)
    parser.add_argument(
        "--start-after-s",
        type=float,
        default=300.0,
        help="start at ownship's first report this long after the file's first (so that most vessels have reported)",
    )
    args = parser.parse_args()
    vessels, names, lengths = read(args.ais_csv)
    own = vessels.get(args.ownship)
    if not own:
        sys.exit(f"{args.ais_csv}: MMSI {args.ownship} is not in the file")
    first_s = min(reports[0][0] for reports in vessels.values())
    start = next((r for r in own if r[0] >= first_s + args.start_after_s), own[0])
    start_s, origin = start[0], (start[1], start[2])
    start_time = datetime.fromtimestamp(start_s, timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    last = own[-1]
    kept, left_out = [], defaultdict(int)
    for mmsi, reports in vessels.items():
        if mmsi == args.ownship:
            continue
        before = [report for report in reports if report[0] <= start_s]
        if not before:
            left_out["first seen after ownship's start"] += 1
            continue
        east, north = local_m(origin, before[-1][1], before[-1][2])
        distance = math.hypot(east, north)
        if distance > args.range_nm * 1852:
            left_out[f"beyond {args.range_nm} nm"] += 1
        elif distance < D_TH_M + 100:
            left_out["inside d_th of ownship at the start"] += 1
        else:
            kept.append(mmsi)
    stem = args.out.rsplit("/", 1)[-1].removesuffix(".ron")
    tracks_name = f"{stem}.tracks.csv"
    tracks_path = args.out[: len(args.out) - len(stem) - 4] + tracks_name
    used = {args.ownship: names[args.ownship]}
    for mmsi in kept:
        name = names[mmsi]
        used[mmsi] = name if name not in used.values() else f"{name} ({mmsi})"
    with open(tracks_path, "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["vessel", "mmsi", "time_s", "lat_deg", "lon_deg", "course_deg", "speed_kn"])
        for mmsi, name in used.items():
            previous = None
            # Ownship's (the human's) track from the report the run starts at.
            from_s = start_s if mmsi == args.ownship else -math.inf
            for time, lat, lon, cog, sog in vessels[mmsi]:
                if time < from_s or (previous is not None and time <= previous):
                    continue
                previous = time
                fields = [course(cog), speed(sog)]
                writer.writerow([name, mmsi, time - start_s, lat, lon] + ["" if v is None else v for v in fields])
    targets = []
    for mmsi in kept:
        report = [r for r in vessels[mmsi] if r[0] <= start_s][-1]
        targets.append(vessel_ron(used[mmsi], mmsi, report, lengths.get(mmsi, DEFAULT_LENGTH_M), ", behaviour: Recorded"))
    ownship = vessel_ron(used[args.ownship], args.ownship, start, lengths.get(args.ownship, DEFAULT_LENGTH_M),
                         f", goal_lat_lon: ({last[1]}, {last[2]})")
    with open(args.out, "w") as file:
        file.write(
            f"// Replay of {args.ais_csv} by scripts/replay/marinecadastre_replay.py: ownship MMSI {args.ownship}\n"
            f"// from its report at {start_time} to its last position; {len(kept)} vessels on their recorded tracks.\n"
            "// Left out: " + (", ".join(f"{n} {why}" for why, n in sorted(left_out.items())) or "none") + ".\n"
            f"Scenario(\n    name: \"replay-{args.ownship}\",\n    ownship: {ownship},\n    targets: [\n"
            + "".join(f"        {t},\n" for t in targets)
            + f"    ],\n    start_time: \"{start_time}\",\n    recorded_tracks: \"{tracks_name}\",\n)\n"
        )
    print(f"wrote {args.out} and {tracks_path}: {len(kept)} targets; left out: {dict(left_out)}")


if __name__ == "__main__":
    main()
