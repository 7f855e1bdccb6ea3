"""Tests of the vorrt Python package (`pip install './python[all]'`, then
`pytest python/tests -q` from the repository root); see conftest.py for the
CLI they compare with.
"""

import copy
import os
import re

import pytest
from conftest import CROSSING, ROOT
from conftest import cli as run_cli

import vorrt


def cli(*args):
    return run_cli(*args).stdout


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
    assert list(tracks.keys()) == [
        "time_s", "vessel", "east_m", "north_m", "course_deg", "speed_kn", "length_m"
    ]
    rows = len(tracks["time_s"])
    assert rows > 100 and all(len(tracks[column]) == rows for column in tracks.keys())
    assert tracks["vessel"][0] == "ownship" and tracks["vessel"][1] == "TS1"
    assert run.findings == []


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


# The wall-clock field of report.json, blanked before comparing bytes.
TOTAL_PLANNING_TIME = re.compile(rb'"total_planning_time_s": [0-9.eE+-]+')


def test_simulate_agrees_with_cli_byte_for_byte(crossing, tmp_path):
    out = tmp_path / "sim"
    result = run_cli("simulate", CROSSING.relative_to(ROOT), "--seed", "3", "--out", out)
    assert result.returncode == 0, result.stderr
    previous = os.getcwd()
    try:
        os.chdir(ROOT)
        scenario = vorrt.Scenario.load(str(CROSSING.relative_to(ROOT)))
    finally:
        os.chdir(previous)
    run = vorrt.simulate(scenario, seed=3)
    expected = (out / "report.json").read_bytes()
    got = (run.report_json() + "\n").encode()
    assert len(TOTAL_PLANNING_TIME.findall(expected)) == 1
    assert TOTAL_PLANNING_TIME.sub(b"", got) == TOTAL_PLANNING_TIME.sub(b"", expected)
    assert run.trajectory_csv().encode() == (out / "trajectory.csv").read_bytes()


def test_json_scenarios_and_dicts(crossing, tmp_path):
    data = crossing.to_dict()
    assert data["name"] == "crossing" and data["ownship"]["speed_kn"] == 12.0
    assert vorrt.Scenario.from_dict(data) == crossing
    path = tmp_path / "crossing.json"
    path.write_text(crossing.to_json())
    loaded = vorrt.Scenario.load(path)
    assert loaded == crossing and loaded.source.endswith("crossing.json")
    assert vorrt.Scenario.from_json(crossing.to_json()) == crossing
    data["ownship"]["speed_kn"] = "fast"
    with pytest.raises(vorrt.ScenarioError, match=r"^mine:1:\d+: ownship\.speed_kn: invalid type"):
        vorrt.Scenario.from_dict(data, "mine")
    # The command line reads JSON too, and says which format failed.
    assert run_cli("check", path).returncode == 0
    bad = tmp_path / "bad.json"
    bad.write_text(crossing.to_ron())
    result = run_cli("check", bad, check=False)
    assert result.returncode == 2
    assert b"bad.json" in result.stderr and b"read as JSON" in result.stderr


def test_seed_and_copies(crossing):
    assert crossing.seed == 1 and crossing.with_seed(None).seed is None
    seeded = crossing.with_seed(5)
    assert seeded.seed == 5 and seeded != crossing
    assert vorrt.simulate(seeded).report["seed"] == 5


def test_judge_a_dataframe_as_the_cli_judges_the_file(crossing, tmp_path):
    run = vorrt.simulate(crossing, seed=1)
    csv_path = tmp_path / "trajectory.csv"
    csv_path.write_text(run.trajectory_csv())
    out = tmp_path / "judge"
    result = run_cli("judge", csv_path, "--scenario", CROSSING, "--out", out)
    assert result.returncode == 0, result.stderr
    expected = (out / "judgement.json").read_bytes()
    judgement = vorrt.judge(run.tracks, crossing, source=str(csv_path))
    assert (judgement.judgement_json() + "\n").encode() == expected
    assert judgement.safe_and_compliant is True and judgement.findings == []
    assert judgement.report["input"]["tracks_file"] == str(csv_path)
    # Without a scenario one is synthesized; without ownship's track nothing.
    assert vorrt.judge(run.tracks).report["input"]["scenario_file"] is None
    with pytest.raises(vorrt.ScenarioError, match="mine"):
        vorrt.judge({"time_s": [0.0, 5.0], "vessel": ["a", "a"]}, source="mine")
    with pytest.raises(TypeError):
        vorrt.judge(42)
    with pytest.raises(ValueError, match="d_th_m"):
        vorrt.judge(run.tracks, d_th_m=-1.0)


def test_judge_finds_what_the_evaluation_finds():
    head_on = vorrt.Scenario.load(ROOT / "crates/scenarios/fixtures/paper/head_on.ron")
    run = vorrt.CommandedRun(head_on, 1)
    state = run.state()
    course = state["ownship"]["course_deg"]
    while run.step(course, state["ownship"]["speed_kn"]) == "running":
        pass
    judgement = vorrt.judge(run.trajectory_csv(), head_on)
    assert judgement.safe_and_compliant is False
    assert judgement.findings, judgement.report
    assert {f["target"] for f in judgement.findings} <= {None, "TS1"}


def test_generate_gives_the_cli_scenarios(tmp_path):
    scenarios = vorrt.generate("open-sea", targets=2, count=3, seed=9)
    assert [len(s.to_dict()["targets"]) for s in scenarios] == [2, 2, 2]
    assert all(s.seed is not None for s in scenarios)
    out = tmp_path / "gen"
    assert run_cli("generate", "open-sea", "--targets", "2", "--count", "3", "--seed", "9",
                   "--out", out).returncode == 0
    files = sorted(out.glob("*.ron"))
    # The files carry the seed the batch runs each with, as the scenarios do.
    assert [f.read_text() for f in files] == [s.to_ron() for s in scenarios]
    odd = vorrt.generate("open-sea", targets=2, count=3, seed=9, shard="1/2")
    assert [s.name for s in odd] == [scenarios[1].name]
    tss = vorrt.generate("tss", density_per_nm=1.0, count=1, seed=2, behaviour="colregs")
    assert tss[0].to_dict()["targets"]
    with pytest.raises(vorrt.ScenarioError, match="lake"):
        vorrt.generate("lake")
    with pytest.raises(vorrt.ScenarioError, match="targets"):
        vorrt.generate("open-sea", count=1)


def test_main_runs_the_command_line_in_process(tmp_path):
    out = tmp_path / "batch"
    code = vorrt.main(["batch", "--generate", "open-sea", "--targets", "1", "--count", "2",
                       "--jobs", "1", "--out", str(out)])
    assert code == 0 and (out / "rows.csv").exists()
    assert vorrt.main(["no-such-command"]) == 2


def test_commanded_run_refuses_bad_commands(crossing):
    run = vorrt.CommandedRun(crossing, 1)
    with pytest.raises(ValueError, match="speed_mps"):
        run.step(0.0, -3.0)
    with pytest.raises(vorrt.ScenarioError, match="goal_tolerance_m"):
        vorrt.CommandedRun(crossing, 1, goal_tolerance_m=0.0)
    assert run.step(0.0, 12.0) == "running"
    assert run.state()["time_s"] == 5.0
    assert run.report()["duration_s"] == 5.0


def test_geographic_tracks_have_lat_lon():
    channel = vorrt.Scenario.load(ROOT / "crates/scenarios/fixtures/geo/channel_ais.ron")
    assert channel.is_geographic
    loop = vorrt.ClosedLoop(channel, 1)
    for _ in range(3):
        loop.step()
    tracks = loop.finish().tracks
    assert {"lat_deg", "lon_deg"} <= set(tracks.keys())
