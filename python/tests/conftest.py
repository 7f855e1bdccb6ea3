"""Shared helpers of the vorrt Python tests.

The CLI comparisons run the `vorrt` command: the binary named by the
VORRT_CLI environment variable (`.ci/run` sets target/debug/vorrt), else
`cargo run --quiet --bin vorrt --` in the repository. With
VORRT_REQUIRE_EXTRAS=1 (set by `.ci/run`) a missing optional dependency
(pandas, gymnasium, ray) fails its tests instead of skipping them.
"""

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CROSSING = ROOT / "crates" / "scenarios" / "fixtures" / "paper" / "crossing.ron"


def cli_command():
    binary = os.environ.get("VORRT_CLI")
    return [binary] if binary else ["cargo", "run", "--quiet", "--bin", "vorrt", "--"]


def cli(*args, check=True):
    result = subprocess.run(
        cli_command() + [str(arg) for arg in args], cwd=ROOT, capture_output=True, check=False
    )
    if check and result.returncode not in (0, 1):
        raise AssertionError(f"vorrt {args} exited {result.returncode}: {result.stderr!r}")
    return result


def require(module):
    """The optional module, else a skip (a failure under VORRT_REQUIRE_EXTRAS=1)."""
    if os.environ.get("VORRT_REQUIRE_EXTRAS") == "1":
        return __import__(module)
    return pytest.importorskip(module)
