"""The extension module of vorrt (PyO3), re-exported by ``vorrt``.

Reports and plans are the command line's: ``Run.report`` holds what ``vorrt
simulate`` writes to ``report.json``, ``plan`` what ``vorrt plan FILE``
prints (see ``docs/report-format.md``). Distances are metres, times
seconds, angles degrees clockwise from north, speeds knots.

A ``seed`` of ``None`` means, as on the command line, the scenario's own
seed, else 1. The GIL is released while Rust works.
"""

from os import PathLike
from typing import Any, Dict, List, Optional, Union

__version__: str

class ScenarioError(Exception):
    """A scenario (or tracks, or generator options) could not be read or is
    invalid; the message names the file and the field
    (``crossing.ron: ownship.speed_kn ...``)."""

class PlanningError(Exception):
    """The planner found no plan, or its settings are invalid."""

class Scenario:
    """A scenario: ownship, targets, planner settings (RON or JSON)."""

    @staticmethod
    def load(path: Union[str, "PathLike[str]"]) -> "Scenario":
        """Reads and validates the scenario file at ``path``: JSON when it
        ends in ``.json``, RON in ``.ron``, else by its content; an error
        says which format failed. Raises ScenarioError."""
    @staticmethod
    def from_ron(text: str, source: str = "<string>") -> "Scenario":
        """Parses and validates RON text; ``source`` names it in errors."""
    @staticmethod
    def from_json(text: str, source: str = "<string>") -> "Scenario":
        """Parses and validates JSON text (the RON fields, tuples as lists)."""
    @staticmethod
    def from_dict(data: Dict[str, Any], source: str = "<dict>") -> "Scenario":
        """Validates a scenario given as a dict (``to_dict``'s form)."""
    def to_ron(self) -> str:
        """The scenario as RON text; ``from_ron`` reads it back."""
    def to_json(self) -> str:
        """The scenario as JSON text; ``from_json`` reads it back."""
    def to_dict(self) -> Dict[str, Any]:
        """The scenario as a dict of plain values (its JSON form)."""
    def with_seed(self, seed: Optional[int]) -> "Scenario":
        """A copy with planner seed ``seed`` (``None`` removes it)."""
    @property
    def name(self) -> str:
        """The scenario's name."""
    @property
    def source(self) -> str:
        """The file (or source name) it was read from."""
    @property
    def seed(self) -> Optional[int]:
        """The planner seed the scenario asks for, if any."""
    @property
    def is_geographic(self) -> bool:
        """Whether positions are latitudes and longitudes."""

class Run:
    """A finished closed-loop run."""

    @property
    def report(self) -> Dict[str, Any]:
        """The content of ``report.json``, as ``vorrt simulate`` writes it."""
    @property
    def tracks(self) -> Any:
        """The columns of ``trajectory.csv`` (``time_s``, ``vessel``,
        ``east_m``, ``north_m``, ``course_deg``, ``speed_kn``, ``length_m``,
        and ``lat_deg``, ``lon_deg`` for a geographic scenario; one row per
        vessel per step, ownship first): a pandas DataFrame, or a dict of
        numpy arrays without pandas. Built on each access."""
    @property
    def findings(self) -> List[Dict[str, Optional[str]]]:
        """The COLREGs findings: dicts of ``target`` (``None`` for
        ownship's track) and ``finding``."""
    @property
    def reached_goal(self) -> bool:
        """Whether ownship reached its goal."""
    def report_json(self) -> str:
        """``report.json`` as the command line writes it (without the final
        line end)."""
    def trajectory_csv(self) -> str:
        """``trajectory.csv`` as the command line writes it, byte for byte."""

def simulate(scenario: Scenario, seed: Optional[int] = None) -> Run:
    """Simulates the scenario in closed loop and evaluates the run, as
    ``vorrt simulate FILE --seed SEED``. Raises ScenarioError on invalid
    planner settings."""

def plan(scenario: Scenario, seed: Optional[int] = None) -> Dict[str, Any]:
    """The plan ``vorrt plan FILE --seed SEED`` prints, as a dict. Raises
    PlanningError when no plan is found."""

def plan_json(scenario: Scenario, seed: Optional[int] = None) -> str:
    """The same plan as the JSON text the command line prints, byte for
    byte (without the final line end)."""

def generate(
    kind: str,
    *,
    targets: Optional[int] = None,
    count: int = 1,
    seed: int = 1,
    behaviour: str = "constant",
    density_per_nm: Optional[float] = None,
    direction: str = "westbound",
    lane_width_nm: float = 1.0,
    shard: Optional[str] = None,
) -> List[Scenario]:
    """The scenarios ``vorrt batch --generate KIND`` runs (``kind``:
    ``open-sea``, with ``targets``; ``coastal``, with ``targets`` (default 1); or ``tss``, with ``density_per_nm``),
    each carrying the seed the batch simulates it with, so ``simulate``
    repeats its row. ``behaviour``: ``constant``, ``colregs``, ``noisy``,
    ``sudden-turn``; ``shard``: ``"i/n"``. Raises ScenarioError."""

def judge_csv(
    text: str,
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
) -> str:
    """``judgement.json`` (without the final line end) of ``vorrt judge``
    for tracks in the CSV of ``trajectory.csv``; ``vorrt.judge`` takes a
    DataFrame. Raises ScenarioError, or ValueError for a bad option."""

def main(args: List[str]) -> int:
    """Runs the command line ``vorrt ARGS...`` in this process (what it
    prints goes to this process's output) and gives its exit code."""

class ClosedLoop:
    """A closed-loop run held at its present moment, stepped by hand;
    stepping it to the end and ``finish()`` gives the run ``simulate``
    gives."""

    def __init__(self, scenario: Scenario, seed: Optional[int] = None) -> None: ...
    def step(self) -> bool:
        """One time step; False when the run had already finished."""
    def state(self) -> Dict[str, Any]:
        """The present moment: ``time_s``, ``step``, ``status``
        (``running``, ``reached_goal`` or ``out_of_time``), ``ownship`` and
        ``targets`` (dicts of ``name``, ``east_m``, ``north_m``,
        ``course_deg``, ``speed_kn``, ``length_m``), ``evasive`` and
        ``plan_waypoints`` (the plan in force)."""
    def is_finished(self) -> bool:
        """Whether the run has finished."""
    def finish(self) -> Run:
        """Ends the run here (a run stopped early has not reached its goal);
        the loop cannot be used after."""

class CommandedRun:
    """A run whose ownship makes the course and speed it is given each
    step (the engine of ``vorrt.gym``); the targets move by their
    behaviours. Ownship turns and changes speed at the planner's motion
    model's rates; it has arrived within ``goal_tolerance_m`` of its goal."""

    def __init__(
        self, scenario: Scenario, seed: Optional[int] = None, goal_tolerance_m: float = 100.0
    ) -> None: ...
    def step(self, course_deg: float, speed_kn: float) -> str:
        """One time step making ``course_deg`` and ``speed_kn``; the status
        after it. Raises ValueError for a command out of range or a
        finished run."""
    def state(self) -> Dict[str, Any]:
        """``time_s``, ``status``, ``goal_east_m``, ``goal_north_m``,
        ``ownship`` and ``targets`` (as in ``ClosedLoop.state``)."""
    def report(self) -> Dict[str, Any]:
        """The run so far judged by the one evaluation (``report.json``'s
        fields; the planner's are zero)."""
    def trajectory_csv(self) -> str:
        """``trajectory.csv`` of the run so far."""
