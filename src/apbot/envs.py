"""Every bundled appliance as a registered Gymnasium environment, ``apbot/<appliance-id>-v0``.

>>> import gymnasium as gym
>>> import apbot.envs  # registers the ids
>>> env = gym.make("apbot/dehumidifier_1-v0")
>>> display, info = env.reset(seed=0, options={"task": "t01"})
>>> info["instruction"]
'Set the target humidity to 45%.'
"""

from __future__ import annotations

import string
from functools import cache
from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from apbot.agent.environment import panel_feedback
from apbot.bench.suite import SuiteAppliance, bundled_suite_dir, load_appliance
from apbot.model.goal import parse_goal
from apbot.sim.simulator import Simulator

MAX_DISPLAY = 64


class ApplianceEnv(gym.Env[str, int]):
    """A simulated appliance and one of its tasks.

    ## Description
    The agent operates an appliance through its physical actions and sees only the display
    text, as a robot reading the panel would. Each episode is one task of the appliance (an
    instruction with a goal); the manual is in ``info["manual"]``.

    ## Action Space
    ``Discrete(n)``: index into ``info["actions"]``, the appliance's actions in model order
    (press, hold — for its required duration — or a dial turn). Anything that is not an
    integer in ``0 … n-1`` raises (``TypeError``, ``ValueError``).

    ## Observation Space
    ``Text``: the panel's text after the action — the main display, then the lit lamps (may be
    empty: a dark panel). ``info["accepted"]`` is False only for a refusal the appliance makes
    perceptible (a beep); a key that does nothing here is usually ignored without a sign.

    ## Rewards
    1 on the step the goal is reached, 0 otherwise.

    ## Termination and truncation
    Terminated when every goal variable holds its goal value. The step budget is a
    ``TimeLimit`` wrapper added by ``gym.make`` (``max_episode_steps`` of the registration).

    ## Options
    ``reset(options={"task": "t03"})`` (or an index) picks the task; otherwise it is drawn with
    the environment's seeded random generator.
    """

    metadata: dict[str, Any] = {"render_modes": ["ansi"], "render_fps": 4}  # noqa: RUF012

    def __init__(self, appliance_id: str, render_mode: str | None = None) -> None:
        self.appliance = _appliance(appliance_id)
        self.simulator = Simulator(self.appliance.model)
        self.action_names = self.simulator.actions
        self.action_space = spaces.Discrete(len(self.action_names))  # type: ignore[assignment]
        self.observation_space = spaces.Text(
            max_length=MAX_DISPLAY, min_length=0, charset=_charset(self.appliance)
        )
        self.render_mode = render_mode
        self.task = self.appliance.tasks[0]
        self.goal = parse_goal(self.appliance.model, self.task.goal)
        self._display = ""

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[str, dict[str, Any]]:
        super().reset(seed=seed)
        unknown = sorted(set(options or {}) - {"task"})
        if unknown:
            raise ValueError(f"unknown reset option(s) {unknown}; the one option is 'task'")
        chosen = (options or {}).get("task")
        tasks = self.appliance.tasks
        if chosen is None:
            self.task = tasks[int(self.np_random.integers(len(tasks)))]
        elif isinstance(chosen, int | np.integer) and not isinstance(chosen, bool):
            if not 0 <= chosen < len(tasks):
                raise ValueError(
                    f"task index {chosen} is out of range: {self.appliance.id} has "
                    f"{len(tasks)} tasks, 0 to {len(tasks) - 1}"
                )
            self.task = tasks[int(chosen)]
        else:
            self.task = next((t for t in tasks if t.id == chosen), None) or _no_task(chosen, tasks)
        self.goal = parse_goal(self.appliance.model, self.task.goal)
        self._display = self._clip(panel_feedback(self.simulator.reset()).text)
        return self._display, self._info(accepted=True, reason="")

    def step(self, action: int) -> tuple[str, float, bool, bool, dict[str, Any]]:
        name = self.action_names[self._action_index(action)]
        # what a robot at the panel has, by the same rule as the benchmark's environment: the
        # panel's text, and a refusal only where the appliance signals one (never its reason)
        feedback = panel_feedback(self.simulator.step(name), "display")
        self._display = self._clip(feedback.text)
        reached = self.simulator.satisfies(self.goal)
        info = self._info(accepted=feedback.accepted, reason=feedback.reason)
        return self._display, float(reached), reached, False, info

    def _action_index(self, action: Any) -> int:
        """The action as an index into ``info["actions"]``; anything else is refused, not
        wrapped round (``-1``) or truncated (``1.5``) into some other action."""
        count = len(self.action_names)
        integral = isinstance(action, int | np.integer) or (
            isinstance(action, np.ndarray)
            and action.shape == ()
            and np.issubdtype(action.dtype, np.integer)
        )
        if isinstance(action, bool | np.bool_) or not integral:
            raise TypeError(
                f"an action is an integer index into info['actions'] (0 to {count - 1}), "
                f"not {type(action).__name__} {action!r}"
            )
        index = int(action)
        if not 0 <= index < count:
            raise ValueError(
                f"action {index} is out of range: {self.appliance.id} has {count} actions, "
                f"0 to {count - 1} (see info['actions'])"
            )
        return index

    def render(self) -> str | None:
        return self._display if self.render_mode == "ansi" else None

    def _info(self, accepted: bool, reason: str) -> dict[str, Any]:
        return {
            "task": self.task.id,
            "instruction": self.task.instruction,
            "optimal_steps": self.task.optimal_steps,
            "actions": self.action_names,
            "accepted": accepted,
            "reason": reason,
            "manual": self.appliance.manual,
        }

    @staticmethod
    def _clip(display: str) -> str:
        return display[:MAX_DISPLAY]


def _no_task(chosen: Any, tasks: list[Any]) -> Any:
    raise ValueError(f"no task {chosen!r}; choose one of {[t.id for t in tasks]}")


@cache
def _appliance(appliance_id: str) -> SuiteAppliance:
    directory = bundled_suite_dir() / appliance_id
    if not (directory / "model.yaml").exists():
        raise ValueError(f"no bundled appliance {appliance_id!r}")
    return load_appliance(directory, check=True)


def _charset(appliance: SuiteAppliance) -> str:
    """Every character the display can show: printable ASCII plus the model's own symbols."""
    extra = {
        c
        for c in (appliance.directory / "model.yaml").read_text(encoding="utf-8")
        if not c.isascii() and c.isprintable()
    }
    return "".join(
        sorted(set(string.digits + string.ascii_letters + string.punctuation + " ") | extra)
    )


def step_budget(optimal: list[int]) -> int:
    """Physical actions allowed per episode: generous for exploration, bounded."""
    return max(50, 4 * max(optimal, default=0))


def register_envs() -> list[str]:
    """Register ``apbot/<id>-v0`` for every bundled appliance; returns the ids."""
    from apbot.bench.suite import TaskFile
    from apbot.model.yaml_text import read_yaml

    ids = []
    for directory in sorted(bundled_suite_dir().iterdir()):
        tasks_file = directory / "tasks.yaml"
        if not tasks_file.exists() or not (directory / "model.yaml").exists():
            continue
        tasks = TaskFile.model_validate(read_yaml(tasks_file.read_text(encoding="utf-8")))
        env_id = f"apbot/{directory.name}-v0"
        if env_id not in gym.registry:
            gym.register(
                id=env_id,
                entry_point="apbot.envs:ApplianceEnv",
                kwargs={"appliance_id": directory.name},
                max_episode_steps=step_budget([t.optimal_steps or 0 for t in tasks.tasks]),
            )
        ids.append(env_id)
    return ids


ENV_IDS = register_envs()
