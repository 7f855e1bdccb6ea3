"""A Gymnasium environment of COLREGs encounters (``pip install
'./python[gym]'``): the agent commands ownship's course and speed, the
targets move by their scenario behaviours, and the run is judged by vorrt's
one evaluation (the ``report.json`` of ``vorrt simulate``). Decision 34 in
``docs/decisions/`` records the spaces and the reward.

Action (``Box(-1, 1, (2,))``): ``a[0]`` the course change asked, times
``max_course_change_deg`` (positive to starboard), from ownship's present
course; ``a[1]`` the speed, from 0 (``-1``) to the scenario's service speed
(``+1``). Ownship turns and changes speed at the planner's motion model's
rates (``vorrt.CommandedRun``), so a command is reached over some steps.

Observation (``Box``, ``5 + 6 * max_targets`` float32): the goal relative
to ownship (east, north, metres), ownship's course as sine and cosine, its
speed in knots; then per target slot: its position relative to ownship
(east, north, metres), course sine and cosine, speed in knots, and 1 (0 for
an empty slot, all zeros). Targets beyond ``max_targets`` are left out.

Reward per step (weights in ``RewardWeights``): ``progress`` times the
kilometres gained toward the goal; minus ``clearance`` times how far inside
d_th the nearest target is (``1 - distance / d_th`` when closer than d_th);
minus ``time`` per step; plus ``goal`` on arrival. When the episode ends
(arrival, the scenario's time limit, or ``max_episode_steps``), the one
evaluation judges the whole run: minus ``finding`` per COLREGs finding,
minus ``collision`` for a collision, minus ``clearance_violation`` when
d_th was not kept. ``info["report"]`` then holds that report.
"""

import math
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import gymnasium
import numpy as np
from gymnasium import spaces

from . import ClosedLoop, CommandedRun, Scenario, generate

# A speed above any scenario's (the format's limit is 60 kn).
MAX_SPEED_KN = 60.0
# Positions relative to ownship are clipped here, metres (100 nm).
MAX_RANGE_M = 185_200.0
OWN_FEATURES = 5
TARGET_FEATURES = 6


@dataclass
class RewardWeights:
    """The reward terms' weights (see the module documentation)."""

    progress: float = 1.0
    """Per kilometre gained toward the goal."""
    clearance: float = 1.0
    """Per step, times ``1 - distance / d_th`` inside d_th."""
    time: float = 0.01
    """Per step."""
    goal: float = 10.0
    """On arrival."""
    finding: float = 5.0
    """Per COLREGs finding of the one evaluation, at the end."""
    collision: float = 100.0
    """For a collision, at the end."""
    clearance_violation: float = 10.0
    """When d_th was not kept, at the end."""


ScenarioSource = Union[Sequence[Scenario], Callable[[int], Scenario], None]


class VorrtEnv(gymnasium.Env):
    """Ownship in a vorrt scenario, steered by the agent.

    ``scenarios``: a list of scenarios (one is drawn per episode), a
    function of a seed giving one, or ``None`` for the open-sea generator
    with ``generator`` keyword arguments (default ``{"kind": "open-sea",
    "targets": 2}``; any of ``vorrt.generate``'s). Every random choice
    flows from the seed given to ``reset``.
    """

    metadata = {"render_modes": []}

    def __init__(
        self,
        scenarios: ScenarioSource = None,
        *,
        generator: Optional[Dict[str, Any]] = None,
        max_targets: int = 4,
        max_course_change_deg: float = 45.0,
        max_episode_steps: Optional[int] = None,
        goal_tolerance_m: float = 100.0,
        reward: Optional[RewardWeights] = None,
    ) -> None:
        if max_targets < 1:
            raise ValueError(f"max_targets is {max_targets}, expected at least 1")
        if not 0.0 < max_course_change_deg <= 180.0:
            raise ValueError(
                f"max_course_change_deg is {max_course_change_deg}, expected 0 to 180"
            )
        if isinstance(scenarios, Scenario):
            scenarios = [scenarios]
        if scenarios is not None and not callable(scenarios) and len(scenarios) == 0:
            raise ValueError("scenarios is empty")
        self.scenarios = scenarios
        self.generator = dict(generator or {"kind": "open-sea", "targets": 2})
        self.max_targets = max_targets
        self.max_course_change_deg = max_course_change_deg
        self.max_episode_steps = max_episode_steps
        self.goal_tolerance_m = goal_tolerance_m
        self.weights = reward or RewardWeights()
        self.action_space = spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        high = np.array(
            [MAX_RANGE_M, MAX_RANGE_M, 1.0, 1.0, MAX_SPEED_KN]
            + [MAX_RANGE_M, MAX_RANGE_M, 1.0, 1.0, MAX_SPEED_KN, 1.0] * max_targets,
            dtype=np.float32,
        )
        low = -high
        low[4] = 0.0
        for slot in range(max_targets):
            base = OWN_FEATURES + slot * TARGET_FEATURES
            low[base + 4] = 0.0
            low[base + 5] = 0.0
        self.observation_space = spaces.Box(low, high, dtype=np.float32)
        self.scenario: Optional[Scenario] = None
        self.run_seed: Optional[int] = None
        self.run: Optional[CommandedRun] = None
        self._service_speed_kn = 0.0
        self._d_th_m = 0.0
        self._steps = 0
        self._distance_m = 0.0

    def _draw_scenario(self) -> Tuple[Scenario, int]:
        seed = int(self.np_random.integers(0, 2**63 - 1))
        if self.scenarios is None:
            options = dict(self.generator)
            kind = options.pop("kind", "open-sea")
            return generate(kind, count=1, seed=seed, **options)[0], seed
        if callable(self.scenarios):
            return self.scenarios(seed), seed
        index = int(self.np_random.integers(0, len(self.scenarios)))
        return self.scenarios[index], seed

    def reset(
        self, *, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None
    ) -> Tuple[np.ndarray, Dict[str, Any]]:
        """Starts an episode: ``options["scenario"]`` (a ``Scenario``)
        chooses its scenario, else one is drawn."""
        super().reset(seed=seed)
        if options and options.get("scenario") is not None:
            self.scenario = options["scenario"]
            self.run_seed = int(self.np_random.integers(0, 2**63 - 1))
        else:
            self.scenario, self.run_seed = self._draw_scenario()
        self.run = CommandedRun(self.scenario, self.run_seed, self.goal_tolerance_m)
        state = self.run.state()
        self._service_speed_kn = state["ownship"]["speed_kn"]
        self._d_th_m = self.run.report()["d_th_m"]
        self._steps = 0
        self._distance_m = _goal_distance_m(state)
        return self._observe(state), self._info(state)

    def step(
        self, action: np.ndarray
    ) -> Tuple[np.ndarray, float, bool, bool, Dict[str, Any]]:
        """One time step of the scenario (5 s by default) under ``action``."""
        if self.run is None:
            raise RuntimeError("call reset() before step()")
        action = np.clip(np.asarray(action, dtype=np.float64), -1.0, 1.0)
        own = self.run.state()["ownship"]
        course_deg = (own["course_deg"] + action[0] * self.max_course_change_deg) % 360.0
        speed_kn = self._service_speed_kn * (action[1] + 1.0) / 2.0
        status = self.run.step(float(course_deg), float(speed_kn))
        self._steps += 1
        state = self.run.state()
        weights = self.weights
        distance_m = _goal_distance_m(state)
        reward = weights.progress * (self._distance_m - distance_m) / 1000.0
        self._distance_m = distance_m
        nearest_m = _nearest_target_m(state)
        if nearest_m is not None and nearest_m < self._d_th_m:
            reward -= weights.clearance * (1.0 - nearest_m / self._d_th_m)
        reward -= weights.time
        terminated = status == "reached_goal"
        if terminated:
            reward += weights.goal
        truncated = status == "out_of_time" or (
            self.max_episode_steps is not None and self._steps >= self.max_episode_steps
        )
        info = self._info(state)
        if terminated or truncated:
            report = self.run.report()
            count = _finding_count(report)
            reward -= weights.finding * count
            if report["collision"]:
                reward -= weights.collision
            if not report["clearance_kept"]:
                reward -= weights.clearance_violation
            info["report"] = report
            info["findings"] = count
        return self._observe(state), float(reward), terminated, truncated, info

    def _observe(self, state: Dict[str, Any]) -> np.ndarray:
        own = state["ownship"]
        values: List[float] = [
            state["goal_east_m"] - own["east_m"],
            state["goal_north_m"] - own["north_m"],
            math.sin(math.radians(own["course_deg"])),
            math.cos(math.radians(own["course_deg"])),
            own["speed_kn"],
        ]
        targets = state["targets"][: self.max_targets]
        for target in targets:
            values += [
                target["east_m"] - own["east_m"],
                target["north_m"] - own["north_m"],
                math.sin(math.radians(target["course_deg"])),
                math.cos(math.radians(target["course_deg"])),
                target["speed_kn"],
                1.0,
            ]
        values += [0.0] * (TARGET_FEATURES * (self.max_targets - len(targets)))
        observation = np.asarray(values, dtype=np.float32)
        return np.clip(observation, self.observation_space.low, self.observation_space.high)

    def _info(self, state: Dict[str, Any]) -> Dict[str, Any]:
        return {
            "time_s": state["time_s"],
            "status": state["status"],
            "scenario": self.scenario.name if self.scenario else None,
            "goal_distance_m": _goal_distance_m(state),
            "nearest_target_m": _nearest_target_m(state),
        }


def _goal_distance_m(state: Dict[str, Any]) -> float:
    own = state["ownship"]
    return math.hypot(state["goal_east_m"] - own["east_m"], state["goal_north_m"] - own["north_m"])


def _nearest_target_m(state: Dict[str, Any]) -> Optional[float]:
    own = state["ownship"]
    distances = [
        math.hypot(t["east_m"] - own["east_m"], t["north_m"] - own["north_m"])
        for t in state["targets"]
    ]
    return min(distances) if distances else None


def _finding_count(report: Dict[str, Any]) -> int:
    return len(report.get("findings", [])) + sum(
        len(target.get("findings", [])) for target in report.get("targets", [])
    )


class PlannerPolicy:
    """vorrt's own planner as a policy: a ``vorrt.ClosedLoop`` of the
    episode's scenario and seed stepped in lockstep with the environment,
    whose ownship's course and speed after each step are the command. The
    commanded ownship follows the planned track closely but not exactly
    (it turns onto each course from where it is), and targets that react to
    ownship see the commanded one."""

    def __init__(self, env: VorrtEnv) -> None:
        self.env = env
        self.loop: Optional[ClosedLoop] = None

    def reset(self) -> None:
        """Call after ``env.reset()``: starts the planner's run."""
        env = self.env
        self.loop = ClosedLoop(env.scenario, env.run_seed)

    def __call__(self, observation: np.ndarray) -> np.ndarray:
        if self.loop is None:
            raise RuntimeError("call reset() after env.reset()")
        if not self.loop.is_finished():
            self.loop.step()
        planned = self.loop.state()["ownship"]
        own = self.env.run.state()["ownship"]
        change = (planned["course_deg"] - own["course_deg"] + 180.0) % 360.0 - 180.0
        env = self.env
        speed = planned["speed_kn"] / env._service_speed_kn if env._service_speed_kn else 0.0
        return np.array(
            [
                np.clip(change / env.max_course_change_deg, -1.0, 1.0),
                np.clip(2.0 * speed - 1.0, -1.0, 1.0),
            ],
            dtype=np.float32,
        )


def episode(env: VorrtEnv, policy: Callable[[np.ndarray], np.ndarray], seed: int) -> Dict[str, Any]:
    """Runs one episode of ``policy`` from ``env.reset(seed=seed)``: its
    return, steps, and the final report's verdict."""
    observation, _ = env.reset(seed=seed)
    if isinstance(policy, PlannerPolicy):
        policy.reset()
    total, steps = 0.0, 0
    while True:
        observation, reward, terminated, truncated, info = env.step(policy(observation))
        total += reward
        steps += 1
        if terminated or truncated:
            report = info["report"]
            return {
                "return": total,
                "steps": steps,
                "reached_goal": report["reached_goal"],
                "collision": report["collision"],
                "clearance_kept": report["clearance_kept"],
                "findings": info["findings"],
            }


gymnasium.register(id="vorrt/Encounter-v0", entry_point="vorrt.gym:VorrtEnv")
