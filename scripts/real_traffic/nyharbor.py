#!/usr/bin/env python3
"""Real AIS traffic judged by `vorrt judge`: the first hour of New York
Harbor on 2020-06-30 (MarineCadastre AIS, shipped by the PyPI package
`tracktable-data`, BSD-2; never committed here).

    python3 -m venv target/data-venv && target/data-venv/bin/pip install tracktable-data
    python3 scripts/real_traffic/nyharbor.py --vorrt target/release/vorrt-cli \
        --csv "$(target/data-venv/bin/python -c 'import tracktable_data, pathlib; print(pathlib.Path(tracktable_data.__file__).parent / "python_example_data/NYHarbor_2020_06_30_first_hour.csv")')" \
        --out out/nyharbor

The data's columns: BaseDateTime, LON, LAT, MMSI, SOG, COG, Heading,
VesselName, IMO, CallSign, VesselType, Status, Length, Width, Draft, Cargo,
TranscieverClass, ETA. Two quirks are undone here: COG is the AIS 12-bit
field read as signed (a negative value v is v + 409.6; 360.0, AIS "not
available", shows as -49.6), and Heading 511 is "not available".

Four measurements (docs/real-traffic.md), each a set of `vorrt judge` runs,
one pair of vessels per run, in a CSV that `vorrt judge` reads
(time,vessel,lat_deg,lon_deg,course_deg,speed_kn,length_m,status,ship_type):

1. straight: every pair of moving vessels that come within 1 nm, with
   ownship replaced by a straight constant-speed track at its own fix times
   carrying jitter like the data's (3 m 1 sigma per axis, one fix in ten
   15 m; seeded): any turn finding is the judge's invention;
2. at rest: a moving vessel and one reporting "at anchor" or "moored"
   within 1 nm: the share classed crossing, head-on or overtaking;
3. real pairs: the real tracks of (1): rate-of-turn findings for vessels
   whose limit is not known, and the encounter verdicts;
4. cut: the real pairs of (3) with every track cut at the closest
   approach: an unfinished encounter must be undecided, not passed.

`--sea-room-m M` passes the harbour's sea room to `vorrt judge` (decision
50: the risk-of-collision distance is then at most a quarter of it, never
under d_th between the hulls); `--real-only` judges the real pairs (3)
alone. The summary counts the real pairs' findings by kind.
"""

import argparse
import csv
import json
import math
import random
import subprocess
from collections import Counter, defaultdict
from datetime import datetime, timezone
from pathlib import Path

NM_M = 1852.0
MOVING_KN = 2.0
CLOSE_M = NM_M
TURN_FINDINGS = {
    "port_turn",
    "small_alterations",
    "stand_on_turned_to_port",
    "port_turn_toward_vessel",
}
# Rule 16's action findings and rule 15's crossing ahead (decision 42).
ACTION_FINDINGS = {"no_action", "late_action", "action_not_apparent", "alteration_not_held"}
CLASSES = {"crossing_give_way", "crossing_stand_on", "head_on", "overtaking", "being_overtaken"}


def cog_deg(raw):
    """The AIS COG as degrees, or None where not available."""
    value = float(raw)
    if value < 0:
        value += 409.6
    if value >= 360.0 - 1e-6:
        return None
    return value


def read(path):
    """Fixes per MMSI: (unix s, lat, lon, cog or None, sog kn), static data."""
    fixes = defaultdict(list)
    static = {}
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            mmsi = row["MMSI"]
            stamp = datetime.fromisoformat(row["BaseDateTime"]).replace(tzinfo=timezone.utc)
            status = row["Status"].strip()
            fixes[mmsi].append(
                (
                    stamp.timestamp(),
                    float(row["LAT"]),
                    float(row["LON"]),
                    cog_deg(row["COG"]),
                    float(row["SOG"]),
                    int(float(status)) if status else None,
                )
            )
            length = row["Length"].strip()
            vessel_type = row["VesselType"].strip()
            static[mmsi] = {
                "name": (row["VesselName"].strip() or mmsi).replace(",", " "),
                "length_m": float(length) if length and float(length) > 0 else None,
                "ship_type": int(float(vessel_type)) if vessel_type else None,
            }
    for track in fixes.values():
        track.sort()
    return fixes, static


def local_m(lat0, lat, lon0, lon):
    """Equirectangular metres east and north of (lat0, lon0): enough here."""
    east = math.radians(lon - lon0) * 6371000.0 * math.cos(math.radians(lat0))
    north = math.radians(lat - lat0) * 6371000.0
    return east, north


def position_at(track, time_s):
    """Interpolated (lat, lon) at time_s within the track, else None."""
    if time_s < track[0][0] or time_s > track[-1][0]:
        return None
    for a, b in zip(track, track[1:]):
        if a[0] <= time_s <= b[0]:
            u = 0.0 if b[0] == a[0] else (time_s - a[0]) / (b[0] - a[0])
            return a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2])
    return track[-1][1], track[-1][2]


def closest(own, target):
    """(distance m, time s) of the closest approach on a 10 s grid, or None."""
    start = max(own[0][0], target[0][0])
    end = min(own[-1][0], target[-1][0])
    if end - start < 600.0:
        return None
    best = None
    time_s = start
    while time_s <= end:
        a, b = position_at(own, time_s), position_at(target, time_s)
        east, north = local_m(a[0], b[0], a[1], b[1])
        distance = math.hypot(east, north)
        if best is None or distance < best[0]:
            best = (distance, time_s)
        time_s += 10.0
    return best


def median_sog(track):
    values = sorted(fix[4] for fix in track)
    return values[len(values) // 2]


def mode_status(track):
    counts = defaultdict(int)
    for fix in track:
        if fix[5] is not None:
            counts[fix[5]] += 1
    return max(counts, key=counts.get) if counts else None


def write_pair(path, vessels, static):
    """One `vorrt judge` CSV of the given (name, fixes) tracks."""
    with open(path, "w", newline="") as handle:
        out = csv.writer(handle)
        out.writerow(
            ["time", "vessel", "lat_deg", "lon_deg", "course_deg", "speed_kn", "length_m", "status", "ship_type"]
        )
        for mmsi, track in vessels:
            info = static[mmsi]
            for time_s, lat, lon, cog, sog, status in track:
                stamp = datetime.fromtimestamp(time_s, tz=timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
                out.writerow(
                    [
                        stamp,
                        f"{info['name']} ({mmsi})",
                        f"{lat:.6f}",
                        f"{lon:.6f}",
                        "" if cog is None else f"{cog:.1f}",
                        f"{sog:.1f}",
                        "" if info["length_m"] is None else f"{info['length_m']:.0f}",
                        "" if status is None else status,
                        "" if info["ship_type"] is None else info["ship_type"],
                    ]
                )


def straight(track, rng):
    """A straight constant-speed track from the first fix to the last at the
    same fix times, with jitter like the data's."""
    (t0, lat0, lon0, *_), (t1, lat1, lon1, *_) = track[0], track[-1]
    east, north = local_m(lat0, lat1, lon0, lon1)
    course = math.degrees(math.atan2(east, north)) % 360.0
    speed_kn = math.hypot(east, north) / (t1 - t0) * 3600.0 / NM_M
    result = []
    for time_s, *_rest in track:
        u = (time_s - t0) / (t1 - t0)
        sigma = 15.0 if rng.random() < 0.1 else 3.0
        de, dn = u * east + rng.gauss(0, sigma), u * north + rng.gauss(0, sigma)
        lat = lat0 + math.degrees(dn / 6371000.0)
        lon = lon0 + math.degrees(de / (6371000.0 * math.cos(math.radians(lat0))))
        result.append((time_s, lat, lon, course, speed_kn, 0))
    return result


SEA_ROOM = []


def judge(vorrt, csv_path, ownship, out_dir):
    """Runs `vorrt judge`; returns judgement.json, or None when it refused
    or judged no target (the pair's tracks overlap too little)."""
    run = subprocess.run(
        [vorrt, "judge", str(csv_path), "--ownship", ownship, "--out", str(out_dir), *SEA_ROOM],
        capture_output=True,
        text=True,
    )
    path = Path(out_dir) / "judgement.json"
    if run.returncode not in (0, 1) or not path.exists():
        return None
    judgement = json.loads(path.read_text())
    return judgement if judgement.get("targets") else None


def findings(judgement):
    return [
        name
        for target in judgement.get("targets", [])
        for name in (finding.get("kind") if isinstance(finding, dict) else finding for finding in target.get("findings", []))
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--vorrt", required=True, help="the vorrt binary")
    parser.add_argument("--csv", required=True, help="NYHarbor_2020_06_30_first_hour.csv")
    parser.add_argument("--out", required=True, help="output folder")
    parser.add_argument("--seed", type=int, default=31)
    parser.add_argument("--sea-room-m", type=float, help="the sea room given to vorrt judge (decision 50)")
    parser.add_argument("--real-only", action="store_true", help="judge the real pairs only")
    args = parser.parse_args()
    if args.sea_room_m is not None:
        SEA_ROOM.extend(["--sea-room-m", str(args.sea_room_m)])
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    fixes, static = read(args.csv)
    moving = sorted(m for m, t in fixes.items() if len(t) >= 8 and median_sog(t) >= MOVING_KN)
    resting = sorted(m for m, t in fixes.items() if len(t) >= 8 and mode_status(t) in (1, 5))
    rng = random.Random(args.seed)
    pairs = []
    for i, a in enumerate(moving):
        for b in moving[i + 1 :]:
            near = closest(fixes[a], fixes[b])
            if near and near[0] < CLOSE_M:
                pairs.append((a, b, near))
    rest_pairs = []
    for a in moving:
        for b in resting:
            near = closest(fixes[a], fixes[b])
            if near and near[0] < CLOSE_M:
                rest_pairs.append((a, b, near))
    counts = defaultdict(int)
    counts["moving_vessels"] = len(moving)
    counts["resting_vessels"] = len(resting)
    details = []
    kinds = Counter()
    for index, (a, b, near) in enumerate(pairs):
        own_name = f"{static[a]['name']} ({a})"
        # 1: straight ownship with jitter.
        path = out / f"straight-{index:03}.csv"
        if args.real_only:
            path = None
        straight_track = straight(fixes[a], rng)
        judgement = None
        if path is not None:
            write_pair(path, [(a, straight_track), (b, fixes[b])], static)
            judgement = judge(args.vorrt, path, own_name, out / f"straight-{index:03}")
        if judgement is not None:
            counts["straight_judged"] += 1
            invented = sorted(TURN_FINDINGS & set(findings(judgement)))
            counts["straight_with_turn_finding"] += bool(invented)
            counts["straight_turn_rate_finding"] += bool(judgement["path_quality"]["findings"])
        # 3: the real pair.
        path = out / f"real-{index:03}.csv"
        write_pair(path, [(a, fixes[a]), (b, fixes[b])], static)
        judgement = judge(args.vorrt, path, own_name, out / f"real-{index:03}")
        if judgement is None:
            continue
        counts["real_judged"] += 1
        counts["real_turn_rate_finding"] += bool(judgement["path_quality"]["findings"])
        counts["real_turn_rate_finding_length_unknown"] += bool(judgement["path_quality"]["findings"]) and static[
            a
        ]["length_m"] is None
        counts["real_length_unknown"] += static[a]["length_m"] is None
        target = judgement["targets"][0]
        counts["real_encounters"] += target["encounter"] != "none"
        counts["real_with_finding"] += bool(findings(judgement))
        kinds.update(set(findings(judgement)))
        counts["real_turn_finding"] += bool(TURN_FINDINGS & set(findings(judgement)))
        counts["real_action_finding"] += bool(ACTION_FINDINGS & set(findings(judgement)))
        counts["real_no_action"] += "no_action" in findings(judgement)
        counts["real_crossed_ahead"] += "crossed_ahead" in findings(judgement)
        counts["real_undecided"] += len(judgement.get("undecided", []))
        # Why (decision 49; older binaries give no reason).
        why = target.get("undecided") or ""
        counts["real_undecided_not_reported"] += why.startswith("target not reported")
        counts["real_undecided_still_closing"] += why.startswith("still closing")
        details.append(
            {
                "pair": [own_name, target["name"]],
                "closest_m": round(near[0]),
                "encounter": target["encounter"],
                "findings": findings(judgement),
                "turn_rate": judgement["path_quality"],
                "undecided": target.get("undecided") or judgement.get("undecided"),
            }
        )
        # 4: cut at the closest approach.
        cut = [(m, [fix for fix in fixes[m] if fix[0] <= near[1]]) for m in (a, b)]
        if not args.real_only and min(len(track) for _, track in cut) >= 3:
            path = out / f"cut-{index:03}.csv"
            write_pair(path, cut, static)
            judgement = judge(args.vorrt, path, own_name, out / f"cut-{index:03}")
            if judgement is not None and judgement["targets"][0]["encounter"] != "none":
                counts["cut_encounters"] += 1
                counts["cut_undecided"] += bool(judgement.get("undecided"))
                counts["cut_undecided_not_reported"] += (judgement["targets"][0].get("undecided") or "").startswith(
                    "target not reported"
                )
                counts["cut_called_safe"] += (not judgement.get("undecided")) and judgement["targets"][0][
                    "clearance_kept"
                ]
    # 2: moving vessel and one at rest.
    for index, (a, b, near) in enumerate([] if args.real_only else rest_pairs):
        path = out / f"rest-{index:03}.csv"
        write_pair(path, [(a, fixes[a]), (b, fixes[b])], static)
        judgement = judge(args.vorrt, path, f"{static[a]['name']} ({a})", out / f"rest-{index:03}")
        if judgement is None:
            continue
        counts["rest_judged"] += 1
        counts["rest_classed_encounter"] += judgement["targets"][0]["encounter"] in CLASSES
        why = judgement["targets"][0].get("undecided") or ""
        counts["rest_status_contradicts_motion"] += "status contradicts motion" in why
        counts["rest_undecided"] += bool(judgement.get("undecided"))
    counts["pairs_within_1nm"] = len(pairs)
    counts["rest_pairs_within_1nm"] = len(rest_pairs)
    summary = {
        "counts": dict(sorted(counts.items())),
        "real_pairs_by_finding": dict(sorted(kinds.items())),
        "pairs": details,
    }
    (out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    for key, value in sorted(counts.items()):
        print(f"{key:42} {value}")
    for key, value in sorted(kinds.items()):
        print(f"real pairs with {key:25} {value}")


if __name__ == "__main__":
    main()
