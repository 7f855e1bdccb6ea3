"""Tests of the vorrt Python package (`pip install ./python pytest`, then
`pytest python/tests -q` from the repository root).

The CLI comparison runs the `vorrt` command: the binary named by the
VORRT_CLI environment variable (`.ci/run` sets target/debug/vorrt), else
`cargo run --quiet --bin vorrt --` in the repository.
"""

import copy
import os
import re
import subprocess
from pathlib import Path

import pytest

import vorrt

ROOT = Path(__file__).resolve().parents[2]
CROSSING = ROOT / "crates" / "scenarios" / "fixtures" / "paper" / "crossing.ron"


def cli(*args):
    binary = os.environ.get("VORRT_CLI")
    command = [binary] if binary else ["cargo", "run", "--quiet", "--bin", "vorrt", "--"]
    result = subprocess.run(
        command + list(args), cwd=ROOT, capture_output=True, check=True
    )
    return result.stdout


# The one wall-clock field of the plan JSON, blanked before comparing bytes.
PLANNING_TIME = re.compile(rb'"planning_time_s": [0-9.eE+-]+')


def without_wall_clock(report):
    report = copy.deepcopy(report)
    del report["planning"]["total_planning_time_s"]
    return report


@pytest.fixture(scope="module")
def crossing():
    return vorrt.Scenario.load(CROSSING)


def test_load_and_round_trip(crossing):
    assert crossing.name == "crossing"
    assert crossing.source.endswith("crossing.ron")
    again = vorrt.Scenario.from_ron(crossing.to_ron(), "again.ron")
    assert again.name == "crossing"
    assert again.to_ron() == crossing.to_ron()


def test_simulate_reaches_goal(crossing):
    run = vorrt.simulate(crossing, seed=1)
    assert run.reached_goal is True
    report = run.report
    assert report["reached_goal"] is True
    assert report["reached_goal_safely"] is True
    assert report["collision"] is False
    assert report["scenario"] == "crossing"
    assert report["seed"] == 1
    assert report["min_distance_m"] >= report["d_th_m"]
    assert [t["name"] for t in report["targets"]] == ["TS1"]
    tracks = run.tracks
    assert set(tracks) == {"time_s", "vessel", "east_m", "north_m", "course_deg", "speed_kn"}
    rows = len(tracks["time_s"])
    assert rows > 100 and all(len(column) == rows for column in tracks.values())
    assert tracks["vessel"][0] == "ownship" and tracks["vessel"][1] == "TS1"


def test_closed_loop_by_hand_matches_simulate(crossing):
    loop = vorrt.ClosedLoop(crossing, 1)
    first = loop.state()
    assert first["time_s"] == 0.0 and first["status"] == "running"
    assert first["plan_waypoints"] == [], "no plan before the first decision"
    assert loop.step() is True
    assert loop.state()["plan_waypoints"], "the first step plans"
    steps = 1
    while loop.step():
        steps += 1
    assert loop.state()["status"] == "reached_goal"
    assert loop.step() is False
    by_hand = loop.finish()
    run = vorrt.simulate(crossing, seed=1)
    assert steps > 0
    assert by_hand.reached_goal and run.reached_goal
    assert without_wall_clock(by_hand.report) == without_wall_clock(run.report)
    assert list(by_hand.tracks["east_m"]) == list(run.tracks["east_m"])
    assert list(by_hand.tracks["north_m"]) == list(run.tracks["north_m"])
    with pytest.raises(RuntimeError):
        loop.step()


def test_bad_scenario_names_the_field():
    text = CROSSING.read_text().replace("speed_kn: 12.0", "speed_kn: -5.0", 1)
    with pytest.raises(vorrt.ScenarioError, match=r"bad\.ron: ownship.*speed_kn"):
        vorrt.Scenario.from_ron(text, "bad.ron")
    text = CROSSING.read_text().replace("speed_kn: 12.0", 'speed_kn: "fast"', 1)
    with pytest.raises(vorrt.ScenarioError, match=r"typo\.ron:\d+:\d+: ownship\.speed_kn"):
        vorrt.Scenario.from_ron(text, "typo.ron")
    with pytest.raises(vorrt.ScenarioError, match="no-such-file.ron"):
        vorrt.Scenario.load("no-such-file.ron")


def test_plan_agrees_with_cli_byte_for_byte(crossing):
    expected = cli("plan", str(CROSSING.relative_to(ROOT)), "--seed", "1")
    previous = os.getcwd()
    try:
        os.chdir(ROOT)
        scenario = vorrt.Scenario.load(str(CROSSING.relative_to(ROOT)))
    finally:
        os.chdir(previous)
    text = (vorrt.plan_json(scenario, seed=1) + "\n").encode()
    assert len(PLANNING_TIME.findall(expected)) == 1
    assert PLANNING_TIME.sub(b"", text) == PLANNING_TIME.sub(b"", expected)
    plan = vorrt.plan(scenario, seed=1)
    assert plan["seed"] == 1 and plan["waypoints"]
    assert plan["scenario_file"] == "crates/scenarios/fixtures/paper/crossing.ron"
    other = vorrt.plan(crossing, seed=1)
    for one in (plan, other):
        del one["statistics"]["planning_time_s"]
    assert plan == {**other, "scenario_file": plan["scenario_file"]}
