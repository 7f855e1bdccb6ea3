"""The Python overhead of a campaign: the same N runs driven from Python
(``vorrt.generate`` then ``vorrt.simulate`` per scenario, each run's report
read as a dict: ``report.json`` written and parsed, which the batch does not
do) and by ``vorrt batch --jobs 1``,
both on one core, in CPU seconds (the process's own for Python, the
child's for the CLI), alternating ROUNDS times. docs/performance.md
records a run.

    pip install ./python            # a release build
    cargo build --release --bin vorrt
    python examples/python/overhead.py --count 1000 --cli target/release/vorrt
"""

import argparse
import resource
import subprocess
import sys
import tempfile
import time
from typing import List, Tuple

import vorrt


def python_campaign(count: int, seed: int, targets: int) -> Tuple[float, float, int]:
    """CPU and wall seconds of the campaign from Python, and its goals reached."""
    cpu, wall = time.process_time(), time.perf_counter()
    reached = 0
    for scenario in vorrt.generate("open-sea", targets=targets, count=count, seed=seed):
        run = vorrt.simulate(scenario)
        reached += run.report["reached_goal"]
    return time.process_time() - cpu, time.perf_counter() - wall, reached


def cli_campaign(cli: str, count: int, seed: int, targets: int) -> Tuple[float, float, int]:
    """CPU and wall seconds of ``vorrt batch --jobs 1``, and its goals reached."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall = time.perf_counter()
    with tempfile.TemporaryDirectory() as out:
        subprocess.run(
            [cli, "batch", "--generate", "open-sea", "--targets", str(targets),
             "--count", str(count), "--seed", str(seed), "--jobs", "1", "--out", out],
            check=True, capture_output=True,
        )
        wall = time.perf_counter() - wall
        with open(f"{out}/rows.csv") as rows:
            header = rows.readline().strip().split(",")
            column = header.index("reached_goal")
            reached = sum(line.split(",")[column] == "true" for line in rows)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    return cpu, wall, reached


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--targets", type=int, default=2)
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--cli", required=True, help="the vorrt binary (a release build)")
    args = parser.parse_args(argv)
    best_py, best_cli = None, None
    for round_ in range(args.rounds):
        cli = cli_campaign(args.cli, args.count, args.seed, args.targets)
        py = python_campaign(args.count, args.seed, args.targets)
        assert py[2] == cli[2], f"goals reached differ: Python {py[2]}, CLI {cli[2]}"
        print(f"round {round_}: CLI {cli[0]:.2f} s CPU ({cli[1]:.2f} s wall), "
              f"Python {py[0]:.2f} s CPU ({py[1]:.2f} s wall); goals {py[2]}/{args.count}")
        best_cli = cli if best_cli is None or cli[0] < best_cli[0] else best_cli
        best_py = py if best_py is None or py[0] < best_py[0] else best_py
    overhead = 100.0 * (best_py[0] - best_cli[0]) / best_cli[0]
    print(f"best of {args.rounds}: CLI {best_cli[0]:.2f} s, Python {best_py[0]:.2f} s CPU: "
          f"Python overhead {overhead:+.1f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
