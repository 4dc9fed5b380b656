"""What every part of the closed loop shares: pressing, reading feedback, the belief.

``Core`` owns one episode's state — the belief, the environment, the episode being logged —
and the two things everything else is built on: :meth:`Core.press` (act on the appliance and
on the belief together, and note every surprise) and :meth:`Core.adopt` (switch the belief to
a repaired model). Exploration, procedure repairs and the greedy ablation are mixins on top
(``apbot.agent.exploring``, ``.procedures``, ``.greedy``); ``apbot.agent.loop`` ties them up.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Any

from apbot.agent.belief import Belief
from apbot.agent.environment import Environment, Feedback
from apbot.agent.episode import TaskContext
from apbot.agent.estimate import Estimate, StateEstimator
from apbot.model.domain import ValueProblem, parse_value
from apbot.model.schema import Add, ApplianceModel, TimeVariable
from apbot.model.values import format_hms, parse_hms
from apbot.plan.plan import PlannedAction
from apbot.sim.compiled import default_effect

MISSING = object()
EXPLORE_LIMIT = 400  # presses per direction (a 1-minute clock over 6 hours; most domains < 100)
PLAN_BUDGET = 100_000  # search nodes per plan: every bundled task needs under 4k on its truth
MAX_SAME_REPAIR = 3  # the same thing going wrong this often in a row: give up


@dataclass(frozen=True)
class AgentConfig:
    """Which parts of ApBot are switched on (the ablations switch them off)."""

    closed_loop: bool = True
    button_policy: bool = True
    explore_limit: int = EXPLORE_LIMIT
    plan_budget: int = PLAN_BUDGET


class Stop(Exception):
    """The run ends: ``success`` claimed, or a declared failure with its reason."""

    def __init__(self, reason: str, success: bool = False) -> None:
        super().__init__(reason)
        self.reason = reason
        self.success = success


@dataclass
class Executed:
    """One action as performed: where the belief was, what it predicted, what was shown.

    ``surprises`` maps each variable the feedback contradicted to (predicted, observed); an
    observed None means the display was dark where the belief expected the value.
    """

    action: PlannedAction
    pointer: tuple[str, int] | None  # the belief's feature step after the action
    variable: str | None  # the variable that step adjusts
    feedback: Feedback
    believed_accepted: bool
    before: tuple[str, int] | None = None  # the belief's feature step before the action
    predicted: Any = None  # the belief's value of ``variable`` after the action
    estimate: Estimate | None = None
    surprises: dict[str, tuple[Any, Any]] = field(default_factory=dict)

    def observed(self, name: str) -> Any:
        """The value of ``name`` the display showed after this action (MISSING if none)."""
        if self.estimate is None:
            return MISSING
        return self.estimate.values.get(name, self.estimate.outside.get(name, MISSING))

    @property
    def refused(self) -> bool:
        """The appliance refused what the belief expected to work."""
        return self.believed_accepted and not self.feedback.accepted


class Core:
    """One episode's state and the primitives every part of the loop uses."""

    def __init__(self, config: AgentConfig, context: TaskContext, env: Environment) -> None:
        self.config = config
        self.context = context
        self.env = env
        self.episode = context.episode()
        self.belief = Belief(context.belief)
        self.estimator = StateEstimator(self.belief.model)
        self.offered = frozenset(env.actions)
        self.last = Feedback()
        self.counts: Counter[str] = Counter()  # how often each kind of trouble came back
        self.explored: set[str] = set()
        self.unverified: set[str] = set()  # changed by a press but not seen since
        self.contradicted: dict[str, Any] = {}  # last shown as a value the belief cannot hold

    # --- acting ------------------------------------------------------------------------------

    def press(self, action: PlannedAction, exploring: bool = False) -> Executed:
        """Perform ``action`` on the appliance and on the belief; the belief then follows what
        the display shows, and whatever contradicted its prediction is kept as a surprise."""
        before_state = self.belief.state
        before = self.belief.pointer()
        if action.name not in self.offered:  # the belief has a control the appliance lacks
            feedback = Feedback(
                self.last.text, dict(self.last.values), False, "the appliance has no such action"
            )
            self.episode.log(
                "action",
                action=action.name,
                display=feedback.text,
                accepted=False,
                exploring=exploring,
            )
            return Executed(action, before, None, feedback, True, before)
        believed = self.belief.advance(action.name, action.seconds)
        pointer = self.belief.pointer() if believed else before
        variable = self.step_variable(pointer) if believed else None
        predicted = self.belief.value(variable) if variable else None
        expected = self.belief.expected().values
        feedback = self.env.step(action.name, action.seconds)
        self.episode.execution_steps += 1
        self.last = feedback
        self.episode.log(
            "action",
            action=action.name,
            display=feedback.text,
            values=dict(feedback.values),
            accepted=feedback.accepted,
            exploring=exploring,
        )
        if not feedback.accepted:
            self.belief.state = before_state  # a refused action changes nothing
            return Executed(action, pointer, variable, feedback, believed, before, predicted)
        estimate = self.estimate(feedback)
        surprises = {
            name: (self.belief.value(name), value)
            for name, value in (*estimate.values.items(), *estimate.outside.items())
            if self.belief.value(name) != value
        }
        if (
            variable
            and variable in expected
            and variable not in surprises
            and variable not in estimate.values
            and variable not in estimate.outside
        ):
            surprises[variable] = (predicted, None)  # expected on the display, and it is dark
        self.sync(estimate)
        if variable and not exploring:
            self.unverified.add(variable)
        self.unverified -= set(estimate.values)
        self.contradicted.update(estimate.outside)
        for name in estimate.values:
            self.contradicted.pop(name, None)
        return Executed(
            action, pointer, variable, feedback, believed, before, predicted, estimate, surprises
        )

    def planned(self, action: str) -> PlannedAction:
        spec = self.belief.model.actions[action]
        return PlannedAction(action, spec.skill, tuple(spec.control_ids), spec.seconds)

    # --- reading -------------------------------------------------------------------------------

    def estimate(self, feedback: Feedback) -> Estimate:
        return self.estimator.estimate(feedback, context=self.belief.values())

    def sync(self, estimate: Estimate) -> None:
        """Believe what the display shows."""
        for name, value in estimate.values.items():
            self.belief.set_value(name, value)

    def shown(self, name: str, feedback: Feedback | None = None) -> Any:
        """The value of ``name`` on the display now (or in ``feedback``); MISSING if none."""
        estimate = self.estimate(feedback or self.last)
        return estimate.values.get(name, estimate.outside.get(name, MISSING))

    # --- the belief model ------------------------------------------------------------------

    def step_variable(self, pointer: tuple[str, int] | None) -> str | None:
        if pointer is None:
            return None
        feature, index = pointer
        return self.belief.model.features[feature][index].variable

    def effect(self, pointer: tuple[str, int], action: str) -> Any:
        feature, index = pointer
        step = self.belief.model.features[feature][index]
        return default_effect(step, action, self.belief.model)

    def stepping(self, pointer: tuple[str, int], action: str) -> bool:
        """Whether ``action`` walks the step's variable through its values (not a go-to)."""
        effect = self.effect(pointer, action)
        return effect in ("next", "prev", "toggle") or isinstance(effect, Add)

    def domain_values(self, name: str) -> list[Any]:
        compiled = self.belief.compiled
        var = compiled.vars[compiled.var_index[name]]
        domain = var.domain(self.belief.state.values)
        return list(domain.values) if domain is not None else []

    def magnitudes(self, name: str) -> list[float]:
        spec = self.belief.model.variables[name]
        return [m for m in (magnitude(spec, v) for v in self.domain_values(name)) if m is not None]

    def case(self, name: str) -> str | None:
        parent = self.belief.model.variables[name].depends_on
        return None if parent is None else str(self.belief.value(parent))

    def adopt(self, model: ApplianceModel, note: str, pointer: tuple[str, int] | None) -> None:
        """Switch the belief to a repaired model, keeping the believed state."""
        self.belief.replace(model, pointer)
        self.estimator.rebind(model)
        self.episode.repairs.append(note)
        self.episode.log("repair", note)

    def count_reasoning_step(self) -> None:
        """One more decision; the run ends instead when the limit is reached."""
        if self.episode.reasoning_steps >= self.context.max_reasoning_steps:
            raise Stop(f"reached the limit of {self.context.max_reasoning_steps} reasoning steps")
        self.episode.reasoning_steps += 1

    def trouble(self, key: str, message: str) -> None:
        """Count one more occurrence of a problem; give up when it keeps coming back."""
        self.counts[key] += 1
        if self.counts[key] > MAX_SAME_REPAIR:
            raise Stop(message)


# --- values ------------------------------------------------------------------------------------


def magnitude(spec: Any, value: Any) -> float | None:
    """A numeric or time value as a number (seconds for times); None for anything else."""
    if value is None:
        return None
    try:
        if isinstance(spec, TimeVariable):
            return float(parse_hms(str(value)))
        return float(value)
    except (TypeError, ValueError):
        return None


def loose(spec: Any, raw: Any) -> Any:
    """``raw`` in canonical form for ``spec``'s type, whether or not its domain has it."""
    try:
        return parse_value(spec, raw)
    except ValueProblem:
        return None


def canonical(spec: Any, number: float | None) -> Any:
    """A number back in the model's notation (``HH:MM:SS`` for times)."""
    if number is None:
        return None
    if isinstance(spec, TimeVariable):
        return format_hms(int(number))
    return tidy(number)


def tidy(number: float) -> int | float:
    return int(number) if float(number).is_integer() else number


def summary(values: list[Any] | None) -> str:
    if not values:
        return "nothing"
    shown = [str(v) for v in values]
    return ", ".join(shown) if len(shown) <= 12 else ", ".join(shown[:10]) + f", … ({len(shown)})"
