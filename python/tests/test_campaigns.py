"""Campaigns on distributed engines, run here with small counts: the Ray
example (tasks over shards on a local Ray of 2 CPUs) and the Slurm job array
(its tasks run one after another with SLURM_ARRAY_TASK_ID/COUNT set), each
merged by `vorrt merge` and compared with the single-machine `vorrt batch`
of the same seed."""

import csv
import importlib.util
import json
import os
import subprocess

from conftest import ROOT, cli, cli_command, require

BATCH = ["--generate", "open-sea", "--targets", "2", "--count", "6", "--seed", "3"]
# Wall-clock columns and fields: they vary from run to run.
WALL_CLOCK = {"planning_time_ms", "planning_time_per_plan_ms"}


def rows(path):
    with open(path, newline="") as file:
        table = list(csv.DictReader(file))
    for row in table:
        for column in WALL_CLOCK:
            row.pop(column)
    return table


def summary(path):
    data = json.loads(path.read_text())
    for key in WALL_CLOCK:
        data.pop(key)
    return data


def single_machine(tmp_path):
    out = tmp_path / "single"
    result = cli("batch", *BATCH, "--jobs", "1", "--out", out)
    assert result.returncode == 0, result.stderr
    return out


def test_ray_campaign_equals_the_single_machine_batch(tmp_path):
    ray = require("ray")
    spec = importlib.util.spec_from_file_location(
        "ray_campaign", ROOT / "examples" / "python" / "ray_campaign.py"
    )
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    ray.init(num_cpus=2, include_dashboard=False)
    try:
        merged = example.campaign(BATCH, 3, tmp_path / "ray")
    finally:
        ray.shutdown()
    single = single_machine(tmp_path)
    assert len(list((tmp_path / "ray" / "shards").iterdir())) == 3
    assert rows(merged / "rows.csv") == rows(single / "rows.csv")
    assert len(rows(merged / "rows.csv")) == 6
    assert summary(merged / "summary.json") == summary(single / "summary.json")
    info = json.loads((merged / "run.json").read_text())
    assert info["merged_shards"] == ["0/3", "1/3", "2/3"]


def test_slurm_array_run_locally_equals_the_single_machine_batch(tmp_path):
    command = cli_command()
    if len(command) > 1:
        # The scripts call one binary: build it and name it.
        subprocess.run(["cargo", "build", "--quiet", "--bin", "vorrt"], cwd=ROOT, check=True)
        binary = str(ROOT / "target" / "debug" / "vorrt")
    else:
        binary = command[0]
    out = tmp_path / "slurm"
    env = {**os.environ, "VORRT": binary}
    result = subprocess.run(
        ["bash", ROOT / "scripts" / "slurm" / "run_local.sh", "4", out, *BATCH],
        env=env, capture_output=True, check=False,
    )
    assert result.returncode == 0, result.stderr
    single = single_machine(tmp_path)
    shards = sorted(p.name for p in (out / "shards").iterdir())
    assert shards == ["000000", "000001", "000002", "000003"]
    info = json.loads((out / "shards" / "000002" / "run.json").read_text())
    assert info["shard"] == "2/4" and "--jobs" in info["command"]
    assert rows(out / "merged" / "rows.csv") == rows(single / "rows.csv")
    assert summary(out / "merged" / "summary.json") == summary(single / "summary.json")


def test_slurm_script_refuses_to_run_outside_an_array(tmp_path):
    env = {k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}
    result = subprocess.run(
        ["bash", ROOT / "scripts" / "slurm" / "campaign.sbatch", tmp_path / "x"],
        env=env, capture_output=True, check=False,
    )
    assert result.returncode != 0
    assert b"job array" in result.stderr
