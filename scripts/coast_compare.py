#!/usr/bin/env python3
"""Compare two land GeoJSON files (as `vorrt coast` writes them).

Prints the Hausdorff distance between the two coastlines (their polygons'
boundaries) and, for each straight route given, the least distance from it
to each file's land. Distances are metres in a local equirectangular frame
about the centre of the first file's polygons: good to a fraction of a
percent over the tens of kilometres of a scenario's box.

Needs shapely (`pip install shapely`); not used by the build or CI.

    python3 scripts/coast_compare.py A.geojson B.geojson \
        --route 40.560,-74.028:40.655,-74.060
"""

import argparse
import json
import math
import sys

try:
    import shapely
    import shapely.geometry as sg
    from shapely.ops import unary_union
except ImportError:  # pragma: no cover - a tool's message, not a test
    sys.exit("coast_compare.py needs shapely: pip install shapely")


def load(path):
    with open(path, encoding="utf-8") as file:
        collection = json.load(file)
    return unary_union([sg.shape(feature["geometry"]) for feature in collection["features"]])


def frame_about(geometry):
    west, south, east, north = geometry.bounds
    lat0, lon0 = 0.5 * (south + north), 0.5 * (west + east)
    # Metres per degree on WGS84 at lat0 (meridian and parallel).
    phi = math.radians(lat0)
    per_lat = 111132.92 - 559.82 * math.cos(2 * phi) + 1.175 * math.cos(4 * phi)
    per_lon = 111412.84 * math.cos(phi) - 93.5 * math.cos(3 * phi)

    def to_m(geometry):
        # shapely.transform hands the coordinates over as an N x 2 array.
        return shapely.transform(
            geometry, lambda xy: (xy - (lon0, lat0)) * (per_lon, per_lat))

    return to_m


def parse_route(text):
    ends = []
    for end in text.split(":"):
        lat, lon = (float(part) for part in end.split(","))
        ends.append((lon, lat))
    if len(ends) != 2:
        raise argparse.ArgumentTypeError(f"route {text!r} is not LAT,LON:LAT,LON")
    return sg.LineString(ends)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("first")
    parser.add_argument("second")
    parser.add_argument("--route", type=parse_route, action="append", default=[],
                        help="LAT,LON:LAT,LON, a straight route to measure against both")
    args = parser.parse_args()
    first, second = load(args.first), load(args.second)
    to_m = frame_about(first)
    first_m, second_m = to_m(first), to_m(second)
    hausdorff_m = first_m.boundary.hausdorff_distance(second_m.boundary)
    print(f"Hausdorff distance between the coastlines: {hausdorff_m:.0f} m")
    for route in args.route:
        route_m = to_m(route)
        print(f"route {list(route.coords)}: {first_m.distance(route_m):.0f} m from {args.first}, "
              f"{second_m.distance(route_m):.0f} m from {args.second}")


if __name__ == "__main__":
    main()
