#!/usr/bin/env python3
"""Closed-loop runs of the peer `colregs-planner` (PyPI) on vorrt's 22 Imazu cases.

Not a build dependency of vorrt: a measuring aid for docs/performance.md.
Needs the peer in the running Python (`pip install colregs-planner`, tested
with 0.1.3); everything else is the standard library.

For each crates/scenarios/fixtures/imazu/imazu_NN.ron (read here: positions, courses, speeds,
lengths, goals, d_th and the simulation section) ownship is driven by the
peer's Kuwata velocity-obstacle policy (`VOPolicyKuwata`, built by the
peer's own `make_vo_policy` with `policy_type="vo_kuwata"`), with COLREGs
roles from the peer's `ColregsClassifier` updated every step (the wiring of
the peer's `vo_rollout`), and moves through the peer's default motion model
(`ct_decoupled_ar`: constant-turn model behind a proportional heading
controller). The targets move as vorrt's closed loop moves them
(`ConstantToGoal`: straight for the goal at constant speed, stopping on it).

Same simulated set-up as `vorrt simulate`: the fixture's time step
(`simulation.time_step_s`, default 5 s) and time limit
(`simulation.max_duration_s`, default 3 x ownship's straight-line time);
the run ends when ownship is within the goal tolerance (100 m, vorrt's
`planner.goal_tolerance_m` default) of its goal or has passed it along the
route (the peer has no goal, it follows the route line), or at the limit.

Writes DIR/<case>/trajectory.csv in the format of vorrt's trajectory.csv
(docs/report-format.md: time_s,vessel,east_m,north_m,course_deg,speed_kn,
ownship first at every step, numbers in full precision) and DIR/summary.csv: per case the wall-clock
time of the whole closed loop, the time of the policy calls (classifier
update and `select_action`, mean and largest), steps, simulated time, whether
ownship arrived, and the smallest distance to any target (between reference
points, at the recorded steps, as vorrt's examples/imazu_timing.rs measures
it) against d_th and d_th between hulls (d_th plus half the sum of the
lengths). The table is also printed.

Usage:
    python3 scripts/peers/colregs_planner_imazu.py OUT_DIR [--fixtures DIR]
        [--repeats N] [--d-pass-m M] [--d-coll-m M] [--responsive-targets]
"""

from __future__ import annotations

import argparse
import csv
import math
import re
import statistics
from decimal import Decimal
import sys
import time
from dataclasses import dataclass
from pathlib import Path

NM_M = 1852.0
KN_MPS = 1852.0 / 3600.0
GOAL_TOLERANCE_M = 100.0  # vorrt's planner.goal_tolerance_m default
DEFAULT_TIME_STEP_S = 5.0  # vorrt's simulation.time_step_s default
DEFAULT_CLEARANCE_M = 200.0  # vorrt's planner.clearance_m default (d_th)


@dataclass
class Vessel:
    """One vessel of a fixture, in vorrt's local frame (east, north), SI."""

    name: str
    east_m: float
    north_m: float
    course_deg: float
    speed_mps: float
    length_m: float
    goal: tuple[float, float] | None  # (east_m, north_m)


@dataclass
class Case:
    """What the closed loop needs from one fixture."""

    name: str
    ownship: Vessel
    targets: list[Vessel]
    clearance_m: float
    time_step_s: float
    max_duration_s: float


# --------------------------------------------------------------------------
# Reading the RON fixtures (only the fields the Imazu files use)
# --------------------------------------------------------------------------


def _strip_comments(text: str) -> str:
    return re.sub(r"//[^\n]*", "", text)


def _block(text: str, start: int) -> str:
    """The text inside the parentheses that open at or after `start`."""
    open_at = text.index("(", start)
    depth = 0
    for i in range(open_at, len(text)):
        if text[i] == "(":
            depth += 1
        elif text[i] == ")":
            depth -= 1
            if depth == 0:
                return text[open_at + 1 : i]
    raise ValueError("unbalanced parentheses")


def _number(block: str, field: str) -> float | None:
    m = re.search(rf"\b{field}\s*:\s*(-?[0-9.eE+-]+)", block)
    return float(m.group(1)) if m else None


def _pair(block: str, field: str) -> tuple[float, float] | None:
    m = re.search(rf"\b{field}\s*:\s*(?:Some\s*\()?\s*\(\s*(-?[0-9.eE+-]+)\s*,\s*(-?[0-9.eE+-]+)\s*\)", block)
    return (float(m.group(1)), float(m.group(2))) if m else None


def _vessel(block: str, path: Path) -> Vessel:
    name = re.search(r'\bname\s*:\s*"([^"]*)"', block)
    start_nm, start_m = _pair(block, "start_nm"), _pair(block, "start_m")
    goal_nm, goal_m = _pair(block, "goal_nm"), _pair(block, "goal_m")
    course, speed, length = (_number(block, f) for f in ("course_deg", "speed_kn", "length_m"))
    if name is None or (start_nm is None and start_m is None) or course is None or speed is None:
        raise ValueError(f"{path}: a Vessel without name, start, course_deg or speed_kn")
    start = start_m if start_m is not None else (start_nm[0] * NM_M, start_nm[1] * NM_M)
    goal = goal_m if goal_m is not None else (
        (goal_nm[0] * NM_M, goal_nm[1] * NM_M) if goal_nm is not None else None
    )
    return Vessel(name.group(1), start[0], start[1], course, speed * KN_MPS,
                  length if length is not None else 0.0, goal)


def load_case(path: Path) -> Case:
    text = _strip_comments(path.read_text())
    name = re.search(r'Scenario\s*\(\s*name\s*:\s*"([^"]*)"', text)
    own_at = text.index("ownship:")
    ownship = _vessel(_block(text, own_at), path)
    targets_at = text.index("targets:")
    list_open = text.index("[", targets_at)
    depth, list_end = 0, None
    for i in range(list_open, len(text)):
        depth += {"[": 1, "]": -1}.get(text[i], 0)
        if depth == 0:
            list_end = i
            break
    targets_text = text[list_open:list_end]
    targets = [_vessel(_block(targets_text, m.start()), path)
               for m in re.finditer(r"\bVessel\s*\(", targets_text)]
    planner = _block(text, text.index("planner:")) if "planner:" in text else ""
    simulation = _block(text, text.index("simulation:")) if "simulation:" in text else ""
    clearance = _number(planner, "clearance_m") or DEFAULT_CLEARANCE_M
    dt = _number(simulation, "time_step_s") or DEFAULT_TIME_STEP_S
    if ownship.goal is None:
        raise ValueError(f"{path}: ownship has no goal")
    straight_s = math.dist((ownship.east_m, ownship.north_m), ownship.goal) / ownship.speed_mps
    max_duration = _number(simulation, "max_duration_s") or 3.0 * straight_s
    return Case(name.group(1) if name else path.stem, ownship, targets, clearance, dt, max_duration)


# --------------------------------------------------------------------------
# The closed loop
# --------------------------------------------------------------------------


def _full(x: float) -> str:
    """As Rust's `{}` writes an f64 (vorrt's trajectory.csv): the shortest
    decimal that reads back as the same number, positional, no trailing
    `.0` on whole numbers."""
    x = float(x)
    if x.is_integer() and abs(x) < 1e15:
        return ("-" if math.copysign(1.0, x) < 0 else "") + str(abs(int(x)))
    return format(Decimal(repr(x)), "f")


class MovingTarget:
    """vorrt's `ConstantToGoal` target: straight for its goal, stops on it."""

    def __init__(self, v: Vessel) -> None:
        self.east, self.north = v.east_m, v.north_m
        self.course_rad = math.radians(v.course_deg)
        self.speed = v.speed_mps
        self.goal = v.goal

    def step(self, dt: float) -> None:
        if self.goal is not None and (self.east, self.north) == self.goal:
            self.speed = 0.0
            return
        if self.goal is not None:
            de, dn = self.goal[0] - self.east, self.goal[1] - self.north
            self.course_rad = math.atan2(de, dn) % (2 * math.pi)
            if math.hypot(de, dn) <= self.speed * dt:
                self.east, self.north = self.goal
                self.speed = 0.0
                return
        self.east += self.speed * math.sin(self.course_rad) * dt
        self.north += self.speed * math.cos(self.course_rad) * dt


def run_case(case: Case, d_pass_m: float, d_coll_m: float, responsive_targets: bool) -> dict:
    """One closed-loop run; returns the tracks, timings and distances."""
    from colregs_planner.colregs_graph.colregs_classifier import ColregsClassifier
    from colregs_planner.colregs_graph.colregs_graph import apply_responsiveness
    from colregs_planner.motion_models.adapters import build_adapter
    from colregs_planner.prediction.vo_rollout import VOAgentConfig, make_vo_policy
    from colregs_planner.vessel.state import InitialState, Intent, VesselState

    dt = case.time_step_s
    own = case.ownship
    heading = math.radians(own.course_deg)
    n_targets = len(case.targets)
    started = time.perf_counter()
    config = VOAgentConfig(policy_type="vo_kuwata", d_pass=d_pass_m, d_coll=d_coll_m,
                           nominal_psi=heading, ref_speed=own.speed_mps,
                           origin_north=own.north_m, origin_east=own.east_m)
    policy = make_vo_policy(config, own_vessel_idx=0,
                            other_vessel_indices=list(range(1, n_targets + 1)))
    adapter = build_adapter(config.rollout_model, dt, k_psi=config.k_psi, tau_speed=config.tau_speed)
    own_state = adapter.init(InitialState(north=own.north_m, east=own.east_m,
                                          speed=own.speed_mps, heading=heading))
    classifier = ColregsClassifier()
    intents = {0: Intent.RESPONSIVE}
    intents.update({i: Intent.RESPONSIVE if responsive_targets else Intent.NON_RESPONSIVE
                    for i in range(1, n_targets + 1)})
    targets = [MovingTarget(t) for t in case.targets]
    goal = own.goal
    route = (goal[0] - own.east_m, goal[1] - own.north_m)
    route_m = math.hypot(*route)
    unit = (route[0] / route_m, route[1] / route_m)

    rows: list[tuple] = []  # (time, vessel index, east, north, course_rad, speed)
    call_s: list[float] = []
    t, arrival = 0.0, None
    steps = round(case.max_duration_s / dt)
    for k in range(steps + 1):
        t = k * dt
        rows.append((t, 0, own_state.east, own_state.north, own_state.psi, own_state.speed))
        for i, tg in enumerate(targets, start=1):
            rows.append((t, i, tg.east, tg.north, tg.course_rad, tg.speed))
        along = (own_state.east - own.east_m) * unit[0] + (own_state.north - own.north_m) * unit[1]
        if math.dist((own_state.east, own_state.north), goal) <= GOAL_TOLERANCE_M or along >= route_m:
            arrival = t
            break
        if k == steps:
            break
        observed = {0: own_state}
        for i, tg in enumerate(targets, start=1):
            observed[i] = VesselState(north=tg.north, east=tg.east, psi=tg.course_rad, speed=tg.speed)
        call_started = time.perf_counter()
        graph = apply_responsiveness(classifier.update(observed), intents)
        policy.set_colregs_graph(graph)
        action = policy.select_action(own_state, [observed[i] for i in range(1, n_targets + 1)])
        call_s.append(time.perf_counter() - call_started)
        own_state = adapter.step(action, dt)
        for tg in targets:
            tg.step(dt)
    wall_s = time.perf_counter() - started

    # Smallest distance between reference points, per target, at the steps.
    per_step = n_targets + 1
    min_dist, min_hull_margin = math.inf, math.inf
    for s in range(0, len(rows), per_step):
        o = rows[s]
        for i in range(1, per_step):
            tg = rows[s + i]
            d = math.hypot(tg[2] - o[2], tg[3] - o[3])
            min_dist = min(min_dist, d)
            half_lengths = 0.5 * (own.length_m + case.targets[i - 1].length_m)
            min_hull_margin = min(min_hull_margin, d - half_lengths)
    return {
        "rows": rows, "wall_s": wall_s, "call_s": call_s, "arrival_s": arrival,
        "simulated_s": t, "min_distance_m": min_dist, "min_hull_distance_m": min_hull_margin,
    }


def write_trajectory(path: Path, case: Case, rows: list[tuple]) -> None:
    names = [case.ownship.name] + [t.name for t in case.targets]
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["time_s", "vessel", "east_m", "north_m", "course_deg", "speed_kn"])
        for t, i, east, north, course_rad, speed in rows:
            w.writerow([_full(t), names[i], _full(east), _full(north),
                        _full(math.degrees(course_rad) % 360.0), _full(speed / KN_MPS)])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out_dir", type=Path, help="folder for <case>/trajectory.csv and summary.csv")
    parser.add_argument("--fixtures", type=Path,
                        default=Path(__file__).resolve().parents[2] / "crates" / "scenarios" / "fixtures" / "imazu")
    parser.add_argument("--repeats", type=int, default=1,
                        help="runs per case; the median wall time is reported (default 1)")
    parser.add_argument("--d-pass-m", type=float, default=None,
                        help="peer's desired passing distance; default d_th plus half the sum of "
                             "the two longest lengths (vorrt keeps d_th between hulls)")
    parser.add_argument("--d-coll-m", type=float, default=None,
                        help="peer's hard collision radius; default half the sum of the two "
                             "longest lengths (hull contact)")
    parser.add_argument("--responsive-targets", action="store_true",
                        help="let the peer assume the targets follow COLREGs (default: it is told "
                             "they hold course, which they do, as vorrt predicts them)")
    args = parser.parse_args()
    try:
        import colregs_planner
    except ImportError:
        print("colregs-planner is not installed: pip install colregs-planner", file=sys.stderr)
        return 2
    paths = sorted(args.fixtures.glob("imazu_*.ron"))
    if not paths:
        print(f"{args.fixtures}: no imazu_*.ron", file=sys.stderr)
        return 2
    args.out_dir.mkdir(parents=True, exist_ok=True)
    header = ["case", "wall_ms", "policy_calls", "call_mean_ms", "call_max_ms", "simulated_s",
              "time_step_s", "arrived", "min_distance_m", "min_hull_distance_m", "d_th_m",
              "d_th_kept_between_hulls", "d_pass_m", "d_coll_m"]
    summary = []
    print(",".join(header))
    for path in paths:
        case = load_case(path)
        longest = sorted([case.ownship.length_m] + [t.length_m for t in case.targets])[-2:]
        half_lengths = 0.5 * sum(longest)
        d_pass = args.d_pass_m if args.d_pass_m is not None else case.clearance_m + half_lengths
        d_coll = args.d_coll_m if args.d_coll_m is not None else half_lengths
        runs = [run_case(case, d_pass, d_coll, args.responsive_targets)
                for _ in range(max(1, args.repeats))]
        run = runs[-1]
        write_trajectory(args.out_dir / case.name / "trajectory.csv", case, run["rows"])
        calls_ms = [s * 1e3 for s in run["call_s"]]
        row = [case.name, f"{statistics.median(r['wall_s'] for r in runs) * 1e3:.1f}", len(calls_ms),
               f"{statistics.fmean(calls_ms):.3f}" if calls_ms else "",
               f"{max(calls_ms):.3f}" if calls_ms else "",
               f"{run['simulated_s']:.0f}", f"{case.time_step_s:g}", run["arrival_s"] is not None,
               f"{run['min_distance_m']:.1f}", f"{run['min_hull_distance_m']:.1f}",
               f"{case.clearance_m:g}", run["min_hull_distance_m"] >= case.clearance_m,
               f"{d_pass:g}", f"{d_coll:g}"]
        summary.append(row)
        print(",".join(str(x) for x in row), flush=True)
    with (args.out_dir / "summary.csv").open("w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(summary)
    total_ms = sum(float(r[1]) for r in summary)
    kept = sum(1 for r in summary if r[11])
    print(f"total wall {total_ms:.1f} ms over {len(summary)} cases; d_th kept between hulls in "
          f"{kept} of {len(summary)} (colregs-planner {colregs_planner.__version__})",
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
