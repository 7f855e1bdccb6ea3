#!/usr/bin/env python3
"""Summarise criterion's results for docs/performance.md.

Reads every target/criterion/**/new/{benchmark,estimates}.json, prints a
Markdown table (median, median absolute deviation, 95 % confidence interval
of the median, mean) in a fixed order of suites, and writes the
plan-time-against-targets plot as a hand-written SVG.

    python3 scripts/bench_report.py [CRITERION_DIR] [SVG_PATH]

Defaults: target/criterion and docs/plan_scaling_targets.svg. Standard
library only.
"""

import json
import math
import os
import sys


def fmt(ns):
    """A duration in nanoseconds, in the unit that suits it."""
    for unit, scale in (("s", 1e9), ("ms", 1e6), ("µs", 1e3)):
        if ns >= scale:
            return f"{ns / scale:.3g} {unit}"
    return f"{ns:.3g} ns"


def load(root):
    results = []
    for directory, _, files in os.walk(root):
        if os.path.basename(directory) != "new" or "estimates.json" not in files:
            continue
        with open(os.path.join(directory, "benchmark.json")) as f:
            benchmark = json.load(f)
        with open(os.path.join(directory, "estimates.json")) as f:
            estimates = json.load(f)
        results.append((order(benchmark["full_id"]), benchmark["full_id"], estimates))
    results.sort()
    return [(full_id, estimates) for _, full_id, estimates in results]


GROUPS = [
    "geometry/",
    "colregs/",
    "jfs/",
    "plan/",
    "plan_scaling/targets/",
    "plan_scaling/nodes_per_phase/",
    "nearest_index/",
    "closed_loop/",
]


def order(full_id):
    """Suites in the order they are documented; numbers in numeric order."""
    group = next(
        (i for i, prefix in enumerate(GROUPS) if full_id.startswith(prefix)), len(GROUPS)
    )
    parts = [int(part) if part.isdigit() else part for part in full_id.split("/")]
    return (group, [(0, part, "") if isinstance(part, int) else (1, 0, part) for part in parts])


def table(results):
    lines = [
        "| benchmark | median | MAD | 95 % CI of median | mean |",
        "|---|---:|---:|---|---:|",
    ]
    for full_id, e in results:
        median = e["median"]
        ci = median["confidence_interval"]
        lines.append(
            f"| `{full_id}` | {fmt(median['point_estimate'])} "
            f"| {fmt(e['median_abs_dev']['point_estimate'])} "
            f"| {fmt(ci['lower_bound'])} – {fmt(ci['upper_bound'])} "
            f"| {fmt(e['mean']['point_estimate'])} |"
        )
    return "\n".join(lines)


def svg(points, path):
    """Median plan time (ms) against targets, log-log, with a linear
    reference through the first point."""
    width, height = 640, 420
    left, right, top, bottom = 70, 20, 40, 60
    xs = [math.log2(n) for n, _, _, _ in points]
    all_ms = [v for _, m, lo, hi in points for v in (m, lo, hi)]
    first_n, first_ms = points[0][0], points[0][1]
    reference = [(n, first_ms * n / first_n) for n, _, _, _ in points]
    all_ms += [ms for _, ms in reference]
    y_lo = math.floor(math.log10(min(all_ms)))
    y_hi = math.ceil(math.log10(max(all_ms)))

    def px(n):
        span = max(xs) - min(xs) or 1
        return left + (math.log2(n) - min(xs)) / span * (width - left - right)

    def py(ms):
        return top + (y_hi - math.log10(ms)) / (y_hi - y_lo) * (height - top - bottom)

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="12">',
        f'<rect width="{width}" height="{height}" fill="white"/>',
        f'<text x="{width / 2}" y="20" text-anchor="middle" font-size="14">'
        "plan_scaling/targets: median plan time against number of targets</text>",
    ]
    for decade in range(y_lo, y_hi + 1):
        for mult in (1, 2, 5):
            ms = mult * 10**decade
            if decade == y_hi and mult > 1:
                continue
            y = py(ms)
            out.append(
                f'<line x1="{left}" x2="{width - right}" y1="{y:.1f}" y2="{y:.1f}" '
                f'stroke="{"#bbb" if mult == 1 else "#eee"}"/>'
            )
            out.append(
                f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end">{ms:g}</text>'
            )
    for n, _, _, _ in points:
        x = px(n)
        out.append(
            f'<line x1="{x:.1f}" x2="{x:.1f}" y1="{top}" y2="{height - bottom}" stroke="#eee"/>'
        )
        out.append(
            f'<text x="{x:.1f}" y="{height - bottom + 16}" text-anchor="middle">{n}</text>'
        )
    out.append(
        f'<text x="{width / 2}" y="{height - 18}" text-anchor="middle">'
        "targets (log scale)</text>"
    )
    out.append(
        f'<text x="18" y="{height / 2}" text-anchor="middle" '
        f'transform="rotate(-90 18 {height / 2})">median plan time, ms (log scale)</text>'
    )
    ref = " ".join(f"{px(n):.1f},{py(ms):.1f}" for n, ms in reference)
    out.append(
        f'<polyline points="{ref}" fill="none" stroke="#999" stroke-dasharray="6 4"/>'
    )
    line = " ".join(f"{px(n):.1f},{py(m):.1f}" for n, m, _, _ in points)
    out.append(f'<polyline points="{line}" fill="none" stroke="#1f77b4" stroke-width="2"/>')
    for n, m, lo, hi in points:
        x = px(n)
        out.append(
            f'<line x1="{x:.1f}" x2="{x:.1f}" y1="{py(hi):.1f}" y2="{py(lo):.1f}" '
            'stroke="#1f77b4"/>'
        )
        out.append(f'<circle cx="{x:.1f}" cy="{py(m):.1f}" r="3.5" fill="#1f77b4"/>')
    lx, ly = left + 12, top + 14
    out.append(
        f'<line x1="{lx}" x2="{lx + 24}" y1="{ly}" y2="{ly}" stroke="#1f77b4" stroke-width="2"/>'
        f'<text x="{lx + 30}" y="{ly + 4}">median (bars: 95 % CI of the median)</text>'
    )
    out.append(
        f'<line x1="{lx}" x2="{lx + 24}" y1="{ly + 18}" y2="{ly + 18}" stroke="#999" '
        f'stroke-dasharray="6 4"/><text x="{lx + 30}" y="{ly + 22}">'
        "linear in targets, through the 1-target point</text>"
    )
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "target/criterion"
    svg_path = sys.argv[2] if len(sys.argv) > 2 else "docs/plan_scaling_targets.svg"
    results = load(root)
    print(table(results))
    points = []
    for full_id, e in results:
        prefix = "plan_scaling/targets/"
        if full_id.startswith(prefix):
            ci = e["median"]["confidence_interval"]
            points.append(
                (
                    int(full_id[len(prefix):]),
                    e["median"]["point_estimate"] / 1e6,
                    ci["lower_bound"] / 1e6,
                    ci["upper_bound"] / 1e6,
                )
            )
    points.sort()
    if points:
        svg(points, svg_path)
        print(f"\nwrote {svg_path}", file=sys.stderr)


if __name__ == "__main__":
    main()
