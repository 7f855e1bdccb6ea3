"""COLREGs-compliant path planning for ships, from Python.

The Rust crates of vorrt (velocity obstacles + RRT with joint forward
simulation) built as an extension module with PyO3. Reports and plans are
the command line's: ``Run.report`` holds what ``vorrt simulate`` writes to
``report.json``, ``plan`` what ``vorrt plan FILE`` prints (see
``docs/report-format.md``). Distances are metres, times seconds, angles
degrees clockwise from north, speeds knots.

A ``seed`` of ``None`` means, as on the command line, the scenario's own seed,
else 1.
"""

from os import PathLike
from typing import Any, Dict, Optional, Union

__version__: str

class ScenarioError(Exception):
    """A scenario could not be read or is invalid; the message names the
    file and the field (``crossing.ron: ownship.speed_kn ...``)."""

class PlanningError(Exception):
    """The planner found no plan, or its settings are invalid."""

class Scenario:
    """A scenario: ownship, targets, planner settings (RON files only)."""

    @staticmethod
    def load(path: Union[str, "PathLike[str]"]) -> "Scenario":
        """Reads and validates the scenario file at ``path`` (RON).

        Raises ScenarioError."""
    @staticmethod
    def from_ron(text: str, source: str = "<string>") -> "Scenario":
        """Parses and validates RON text; ``source`` names it in errors.

        Raises ScenarioError."""
    def to_ron(self) -> str:
        """The scenario as RON text; ``from_ron`` reads it back."""
    @property
    def name(self) -> str:
        """The scenario's name."""
    @property
    def source(self) -> str:
        """The file (or source name) it was read from."""

class Run:
    """A finished closed-loop run."""

    @property
    def report(self) -> Dict[str, Any]:
        """The content of ``report.json``, as ``vorrt simulate`` writes it."""
    @property
    def tracks(self) -> Dict[str, Any]:
        """The columns of ``trajectory.csv``: ``time_s``, ``vessel``,
        ``east_m``, ``north_m``, ``course_deg``, ``speed_kn``; one row per
        vessel per step, ownship first. Lists, or numpy arrays when numpy
        is installed."""
    @property
    def reached_goal(self) -> bool:
        """Whether ownship reached its goal."""
    def report_json(self) -> str:
        """``report.json`` as the command line writes it (without the final
        line end)."""

def simulate(scenario: Scenario, seed: Optional[int] = None) -> Run:
    """Simulates the scenario in closed loop and evaluates the run (the GIL
    is released meanwhile). Raises ScenarioError on invalid planner
    settings."""

def plan(scenario: Scenario, seed: Optional[int] = None) -> Dict[str, Any]:
    """The plan ``vorrt plan FILE --seed SEED`` prints, as a dict (the GIL
    is released while planning). Raises PlanningError when no plan is
    found."""

def plan_json(scenario: Scenario, seed: Optional[int] = None) -> str:
    """The same plan as the JSON text the command line prints, byte for
    byte (without the final line end)."""

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

