"""COLREGs-compliant path planning for ships, from Python.

The Rust crates of vorrt (velocity obstacles + RRT with joint forward
simulation) built as an extension module with PyO3. Reports and plans are
the command line's: ``Run.report`` holds what ``vorrt simulate`` writes to
``report.json``, ``plan`` what ``vorrt plan FILE`` prints, ``judge`` what
``vorrt judge`` writes to ``judgement.json`` (see ``docs/report-format.md``
and ``docs/python.md``). Distances are metres, times seconds, angles degrees
clockwise from north, speeds knots.

A ``seed`` of ``None`` means, as on the command line, the scenario's own
seed, else 1. The GIL is released while Rust works.

Optional extras: ``pandas`` (``Run.tracks`` as a ``DataFrame``), ``numpy``,
``gym`` (``vorrt.gym``, a Gymnasium environment), ``ray`` (the campaign
example).
"""

import json
from typing import Any, Dict, List, Optional

from ._tables import findings as _findings
from ._tables import table_to_csv as _table_to_csv
from ._vorrt import (
    ClosedLoop,
    CommandedRun,
    PlanningError,
    Run,
    Scenario,
    ScenarioError,
    __version__,
    generate,
    judge_csv,
    main,
    plan,
    plan_json,
    simulate,
)

__all__ = [
    "ClosedLoop",
    "CommandedRun",
    "Judgement",
    "PlanningError",
    "Run",
    "Scenario",
    "ScenarioError",
    "__version__",
    "generate",
    "judge",
    "judge_csv",
    "main",
    "plan",
    "plan_json",
    "simulate",
]


class Judgement:
    """The verdict of ``vorrt judge`` on recorded tracks: ``report`` is the
    whole ``judgement.json`` as a dict (the fields of ``report.json``, with
    ``safe_and_compliant`` and the judge's ``input`` section)."""

    def __init__(self, judgement_json: str) -> None:
        self._json = judgement_json
        self.report: Dict[str, Any] = json.loads(judgement_json)

    @property
    def safe_and_compliant(self) -> bool:
        """No collision, d_th kept and no COLREGs finding (``vorrt judge``'s
        exit code 0)."""
        return bool(self.report["safe_and_compliant"])

    @property
    def findings(self) -> List[Dict[str, Optional[str]]]:
        """The COLREGs findings: dicts of ``target`` (``None`` for ownship's
        track) and ``finding``."""
        return _findings(self.report)

    def judgement_json(self) -> str:
        """``judgement.json`` as ``vorrt judge`` writes it (without the
        final line end)."""
        return self._json

    def __repr__(self) -> str:
        return f"Judgement(safe_and_compliant={self.safe_and_compliant})"


def judge(
    tracks: Any,
    scenario: Optional[Scenario] = None,
    *,
    source: str = "<tracks>",
    ownship: Optional[str] = None,
    d_th_m: Optional[float] = None,
    step_s: Optional[float] = None,
    max_gap_s: Optional[float] = None,
    goal_tolerance_m: Optional[float] = None,
    length_m: Optional[float] = None,
    max_turn_rate_deg_s: Optional[float] = None,
    max_speed_kn: Optional[float] = None,
) -> Judgement:
    """Judges any planner's recorded tracks with the one evaluation, as
    ``vorrt judge --format csv`` does.

    ``tracks`` is a pandas ``DataFrame`` (or a dict of columns, or CSV text)
    with the columns of ``trajectory.csv``: ``time_s``, ``vessel``, and
    ``east_m``/``north_m`` or ``lat_deg``/``lon_deg`` (``course_deg``,
    ``speed_kn``, ``length_m`` optional). ``scenario`` gives ownship's goal,
    the lengths, d_th and the rules; without it one is synthesized from the
    tracks. The keyword options are ``vorrt judge``'s. Raises
    ``ScenarioError`` naming ``source`` and what is wrong.
    """
    return Judgement(
        judge_csv(
            _table_to_csv(tracks),
            scenario,
            source=source,
            ownship=ownship,
            d_th_m=d_th_m,
            step_s=step_s,
            max_gap_s=max_gap_s,
            goal_tolerance_m=goal_tolerance_m,
            length_m=length_m,
            max_turn_rate_deg_s=max_turn_rate_deg_s,
            max_speed_kn=max_speed_kn,
        )
    )
