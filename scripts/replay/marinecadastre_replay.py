#!/usr/bin/env python3
"""A MarineCadastre AIS CSV (BaseDateTime,LON,LAT,MMSI,SOG,COG,...) into a
vorrt replay (decision 40): SCENARIO.ron plus SCENARIO.tracks.csv, ownship
MMSI from its first report (goal: its last position), every other vessel
seen by then within --range-nm following its recorded track.

    python3 scripts/replay/marinecadastre_replay.py AIS.csv --ownship MMSI --out DIR/NAME.ron

    python3 scripts/replay/marinecadastre_replay.py AIS.csv --ownship MMSI --out DIR/NAME.ron \
        --land-geojson LAND.geojson --land-clearance-m 100

Vessels first seen after ownship's start are left out (a recording cannot
say where they were before), and so are vessels inside d_th of ownship at
the start (vorrt check refuses such a scenario). With --land-geojson (a land
GeoJSON written by `vorrt coast`, e.g. the committed
crates/scenarios/fixtures/coastal/new_york_harbor_ne10m.geojson) the
scenario names that land, and vessels whose start position lies inside it
are left out (moored at a pier the 1:10m coast draws as land; vorrt check
refuses a target on land). Ownship's service speed is the median of its
recorded speeds over ground while making way (decision 48). Where its
recorded track shows it turning faster than the planner's default limit
(0.5 deg/s, `vorrt_jfs::MAX_DEFAULT_TURN_RATE_RAD_S`, a large ship's), the
largest rate of turn between two consecutive reports making way is its
`max_turn_rate_deg_s` (decision 52: JUSTINE, a 26 m tug, turned round at
1.3 deg/s; at 0.5 deg/s no turn round fits the channel she was in).
Standard library only.
"""

import argparse
import csv
import json
import math
import os
import statistics
import sys
from collections import defaultdict
from datetime import datetime, timezone

EARTH_RADIUS_M = 6_371_008.8
DEFAULT_LENGTH_M = 50.0
D_TH_M = 200.0
# Below this a vessel is not making way and its speed is no service speed
# (knots; the observed judgement's MAKING_WAY_MPS, crates/colregs/src/observed/noise.rs).
MAKING_WAY_KN = 0.5


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
    # MarineCadastre writes the AIS 12-bit COG field read as signed: a
    # negative value v is v + 409.6 (so AIS 360.0, "not available", shows as
    # -49.6); 360 and above is "not available" (docs/real-traffic.md, the
    # same reading as scripts/real_traffic/nyharbor.py).
    if cog is None:
        return None
    if cog < 0:
        cog += 409.6
    return None if not 0 <= cog < 360 - 1e-6 else cog


def speed(sog):
    return None if sog is None or sog < 0 or sog >= 102.3 else sog


def service_speed_kn(reports):
    """Ownship's service speed (decision 48): the median of its recorded
    speeds over ground from the run's start to its last report, counting
    only reports making way; None when it never made way."""
    moving = [s for s in (speed(r[4]) for r in reports) if s is not None and s >= MAKING_WAY_KN]
    return round(statistics.median(moving), 2) if moving else None


def land_rings(path):
    """Every ring (outer and holes) of the polygons of a land GeoJSON, as
    lists of (lon, lat)."""
    with open(path) as file:
        data = json.load(file)
    features = data["features"] if data.get("type") == "FeatureCollection" else [data]
    rings = []
    for feature in features:
        geometry = feature.get("geometry", feature)
        polygons = {"Polygon": [geometry["coordinates"]], "MultiPolygon": geometry["coordinates"]}
        for polygon in polygons.get(geometry["type"], []):
            rings.extend([(p[0], p[1]) for p in ring] for ring in polygon)
    return rings


def on_land(rings, lat, lon):
    """Even-odd rule over every ring: inside an outer ring and not in a hole.
    A filter for leaving targets out only; vorrt check judges land itself."""
    inside = False
    for ring in rings:
        for (x1, y1), (x2, y2) in zip(ring, ring[1:] + ring[:1]):
            if (y1 > lat) != (y2 > lat) and lon < x1 + (lat - y1) * (x2 - x1) / (y2 - y1):
                inside = not inside
    return inside


def ron_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


# The planner's default rate of turn never exceeds this (deg/s;
# vorrt_jfs::motion::MAX_DEFAULT_TURN_RATE_RAD_S).
MAX_DEFAULT_TURN_RATE_DEG_S = 0.5


def recorded_turn_rate_deg_s(reports):
    """The largest rate of turn ownship's recorded track shows (decision
    52): the change of course over ground between two consecutive reports,
    both making way with a course available, over the time between them;
    None when it is no more than the planner's default limit (which then
    stands) or no pair qualifies. A lower bound of what the vessel can do:
    the fixes are about a minute apart."""
    largest = 0.0
    for before, after in zip(reports, reports[1:]):
        dt_s = after[0] - before[0]
        courses = course(before[3]), course(after[3])
        speeds = speed(before[4]), speed(after[4])
        if dt_s <= 0 or None in courses or None in speeds or min(speeds) < MAKING_WAY_KN:
            continue
        turn_deg = abs((courses[1] - courses[0] + 180.0) % 360.0 - 180.0)
        largest = max(largest, turn_deg / dt_s)
    return round(largest, 2) if largest > MAX_DEFAULT_TURN_RATE_DEG_S else None


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
    parser.add_argument(
        "--land-geojson",
        help="land GeoJSON (from vorrt coast) the scenario names in land_geojson, relative to its folder",
    )
    parser.add_argument(
        "--land-clearance-m",
        type=float,
        help="the scenario's land_clearance_m [default: vorrt's, 0.25 nm]",
    )
    args = parser.parse_args()
    vessels, names, lengths = read(args.ais_csv)
    rings = land_rings(args.land_geojson) if args.land_geojson else []
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
        elif rings and on_land(rings, before[-1][1], before[-1][2]):
            left_out["on the chart's land at the start"] += 1
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
    # The human's speed over the passage, not at the start report (decision 48).
    service_kn = service_speed_kn([r for r in own if r[0] >= start_s])
    own_start = start if service_kn is None else start[:4] + (service_kn,)
    turn_rate = recorded_turn_rate_deg_s([r for r in own if r[0] >= start_s])
    own_extra = f", goal_lat_lon: ({last[1]}, {last[2]})"
    if turn_rate is not None:
        own_extra += f", max_turn_rate_deg_s: {turn_rate}"
    ownship = vessel_ron(used[args.ownship], args.ownship, own_start, lengths.get(args.ownship, DEFAULT_LENGTH_M),
                         own_extra)
    land = ""
    if args.land_geojson:
        folder = os.path.dirname(os.path.abspath(args.out))
        land += f"    land_geojson: {ron_string(os.path.relpath(os.path.abspath(args.land_geojson), folder))},\n"
    if args.land_clearance_m is not None:
        land += f"    land_clearance_m: {args.land_clearance_m},\n"
    with open(args.out, "w") as file:
        file.write(
            f"// Replay of {args.ais_csv} by scripts/replay/marinecadastre_replay.py: ownship MMSI {args.ownship}\n"
            f"// from its report at {start_time} to its last position; {len(kept)} vessels on their recorded tracks.\n"
            f"// Service speed {own_start[4]} kn: the median of its recorded speeds making way"
            f" (decision 48; {speed(start[4])} kn at the start report).\n"
            + (f"// Rate of turn {turn_rate} deg/s: the largest its recorded track shows (decision 52).\n"
               if turn_rate is not None else "")
            + "// Left out: " + (", ".join(f"{n} {why}" for why, n in sorted(left_out.items())) or "none") + ".\n"
            f"Scenario(\n    name: \"replay-{args.ownship}\",\n    ownship: {ownship},\n    targets: [\n"
            + "".join(f"        {t},\n" for t in targets)
            + f"    ],\n{land}    start_time: \"{start_time}\",\n    recorded_tracks: \"{tracks_name}\",\n)\n"
        )
    print(f"wrote {args.out} and {tracks_path}: {len(kept)} targets; left out: {dict(left_out)}")


if __name__ == "__main__":
    main()
