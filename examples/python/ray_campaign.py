"""A vorrt Monte Carlo campaign as Ray tasks, one per shard, merged by
``vorrt merge`` (the command line's merge: it refuses shards of different
batches and missing shards), giving the rows of the single-machine ``vorrt
batch`` of the same seed.

    pip install './python[ray]'
    python examples/python/ray_campaign.py --generate open-sea --targets 2 \
        --count 40 --seed 1 --shards 4 --out out/ray-campaign
    # merged rows, summary and plots in out/ray-campaign/merged/

Each task runs ``vorrt batch ... --shard i/n --jobs 1`` in-process
(``vorrt.main``, the GIL released) in a scratch folder on its worker and
returns the shard's files (``rows.csv``, ``run.json``), so no shared file
system is needed; the driver writes them under ``OUT/shards/`` and merges.
``--address`` joins a running cluster (``ray start --head`` on one node,
``ray start --address=HEAD:6379`` on the others); without it a local Ray is
started with ``--num-cpus`` workers. docs/python.md says how a 10^6-run
campaign is laid out and what a run costs.
"""

import argparse
import os
import sys
import tempfile
from pathlib import Path
from typing import Dict, List

import ray

import vorrt

SHARD_FILES = ("rows.csv", "run.json", "summary.json")


@ray.remote(num_cpus=1)
def run_shard(batch_args: List[str], index: int, count: int) -> Dict[str, bytes]:
    """One shard of the batch: ``vorrt batch BATCH_ARGS --shard index/count``."""
    with tempfile.TemporaryDirectory(prefix=f"vorrt-shard-{index}-") as scratch:
        out = os.path.join(scratch, "out")
        code = vorrt.main(
            ["batch", *batch_args, "--shard", f"{index}/{count}", "--jobs", "1", "--out", out]
        )
        if code != 0:
            raise RuntimeError(f"shard {index}/{count}: vorrt batch exited {code}")
        return {name: Path(out, name).read_bytes() for name in SHARD_FILES}


def campaign(batch_args: List[str], shards: int, out: Path) -> Path:
    """Runs the batch as ``shards`` Ray tasks and merges them into
    ``OUT/merged``; gives that folder."""
    futures = [run_shard.remote(batch_args, index, shards) for index in range(shards)]
    dirs = []
    for index, files in enumerate(ray.get(futures)):
        shard_dir = out / "shards" / f"{index:04d}"
        shard_dir.mkdir(parents=True, exist_ok=True)
        for name, data in files.items():
            (shard_dir / name).write_bytes(data)
        dirs.append(str(shard_dir))
    merged = out / "merged"
    code = vorrt.main(["merge", *dirs, "--out", str(merged)])
    if code != 0:
        raise RuntimeError(f"vorrt merge exited {code}")
    return merged


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--generate", default="open-sea", choices=["open-sea", "tss"])
    parser.add_argument("--targets", type=int, default=2, help="open sea: targets per scenario")
    parser.add_argument("--density", type=float, help="TSS: targets per nm of lane")
    parser.add_argument("--behaviour", default="constant")
    parser.add_argument("--count", type=int, default=40)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--shards", type=int, default=4)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--address", help="a running Ray cluster [default: start a local one]")
    parser.add_argument("--num-cpus", type=int, default=2, help="CPUs of the local Ray")
    args = parser.parse_args(argv)
    batch_args = ["--generate", args.generate, "--count", str(args.count)]
    batch_args += ["--seed", str(args.seed), "--behaviour", args.behaviour]
    if args.generate == "open-sea":
        batch_args += ["--targets", str(args.targets)]
    elif args.density is not None:
        batch_args += ["--density", str(args.density)]
    if args.address:
        ray.init(address=args.address)
    else:
        ray.init(num_cpus=args.num_cpus, include_dashboard=False)
    try:
        merged = campaign(batch_args, args.shards, args.out)
    finally:
        ray.shutdown()
    print(f"merged {args.shards} shards into {merged}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
