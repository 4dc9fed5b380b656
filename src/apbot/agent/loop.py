"""The ApBot closed loop: plan on the belief, execute one macro action, check, repair, re-plan.

After every macro action the agent compares what the appliance shows with what its belief
predicts. On a mismatch it explores — repeats the step's action until a shown value repeats
(and the opposite action after a clamp) — infers the variable's true definition from that
trace by code (``apbot.agent.infer``), writes it into the belief (``apbot.agent.repair``) and
plans again from the observed state. A goal value the belief does not even contain is treated
the same way: the agent goes to the variable, explores it, and learns whether the value exists.

Counting follows the paper: a reasoning step is one macro action (exploration excluded); every
physical action, exploration included, is an execution step.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Any

from apbot.agent.belief import Belief
from apbot.agent.environment import Environment, Feedback
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.estimate import Estimate, StateEstimator
from apbot.agent.infer import (
    Dark,
    common_step,
    fill_dark,
    order_from_traces,
    ranges_from_values,
    splice,
    typical_change,
)
from apbot.agent.repair import RepairError, insert_step, redefine_domain, set_effects
from apbot.model.domain import ValueProblem, build_domain, normalise, parse_value
from apbot.model.goal import GoalError
from apbot.model.schema import Add, DiscreteVariable, GoTo, TimeVariable, time_step_seconds
from apbot.model.validate import check_goal
from apbot.model.values import format_hms, parse_hms
from apbot.plan.plan import MacroAction, PlannedAction, Unreachable, plan
from apbot.sim.compiled import default_effect

MISSING = object()
EXPLORE_LIMIT = 400  # presses per direction: enough for a 1-minute clock over a day... almost
PLAN_BUDGET = 20_000  # search nodes per plan: every bundled task needs under 4k on its truth
MAX_SAME_REPAIR = 3  # the same variable mismatching this often without progress: give up


@dataclass(frozen=True)
class AgentConfig:
    """Which parts of ApBot are switched on (the ablations switch them off)."""

    closed_loop: bool = True
    button_policy: bool = True
    explore_limit: int = EXPLORE_LIMIT
    plan_budget: int = PLAN_BUDGET


@dataclass
class Executed:
    """One action of a macro action as performed: the belief's step and what happened."""

    action: PlannedAction
    pointer: tuple[str, int] | None
    variable: str | None
    feedback: Feedback
    believed_accepted: bool
    before: tuple[str, int] | None = None  # the belief's feature step before the action
    predicted: Any = None  # the belief's value of ``variable`` after the action
    shown: bool = False  # whether the belief expects the display to show ``variable`` then


class Stop(Exception):
    """The run ends: ``success`` claimed or a declared failure with its reason."""

    def __init__(self, reason: str, success: bool = False) -> None:
        super().__init__(reason)
        self.reason = reason
        self.success = success


@dataclass
class Mismatch:
    variable: str
    expected: Any
    observed: Any
    outside: bool = False  # the observed value is not in the belief's domain at all


@dataclass
class _Run:
    """One episode of the agent: the belief, the environment and the bookkeeping."""

    config: AgentConfig
    context: TaskContext
    env: Environment
    episode: Episode = field(default_factory=Episode)
    explored: set[str] = field(default_factory=set)
    pending: list[MacroAction] = field(default_factory=list)  # rest of the plan, while it holds
    values_before: dict[str, Any] = field(default_factory=dict)  # belief before the macro action
    mismatches: Counter[str] = field(default_factory=Counter)

    def __post_init__(self) -> None:
        self.episode = self.context.episode()
        self.belief = Belief(self.context.belief)
        self.estimator = StateEstimator(self.belief.model)
        self.last = Feedback()

    # --- the loop ----------------------------------------------------------------------------

    def run(self) -> Episode:
        episode = self.episode
        try:
            self.last = self.env.reset()
            self._sync(self._estimate(self.last))
            if not self.config.closed_loop:
                self._open_loop()
            while True:
                self._reasoning_step()
        except Stop as stop:
            episode.claimed_success = stop.success
            episode.failure = "" if stop.success else stop.reason
            episode.log("stop", stop.reason)
        return episode

    def _open_loop(self) -> None:
        """Plan once on the belief and press everything: no checks, no repairs."""
        inside, outside = self._goal()
        if outside:
            raise Stop(self._outside_text(outside))
        for macro in self._plan(inside).macro_actions:
            self._start_macro(macro)
            self._execute(macro)
        raise Stop("plan executed", success=True)

    def _reasoning_step(self) -> None:
        inside, outside = self._goal()
        for name in outside:
            if name in self.explored:
                raise Stop(self._outside_text({name: outside[name]}) + " (explored: "
                           f"{_summary(self._domain_values(name))})")
        if not self.pending:
            target = dict(inside)
            target.update({name: self._proxy(name, raw, inside) for name, raw in outside.items()})
            found = self._plan(target)
            if not found.macro_actions:
                if outside:
                    self._explore_outside(outside)
                    return
                if any(self.belief.value(n) != v for n, v in inside.items()):
                    raise Stop("the rest of the goal cannot be reached on the belief model")
                raise Stop("the goal holds", success=True)
            self.pending = list(found.macro_actions)
        macro = self.pending.pop(0)
        self._start_macro(macro)
        executed = self._execute(macro)
        if not self._check(macro, executed, outside):
            self.pending.clear()  # the belief changed: plan again from what was observed

    def _start_macro(self, macro: MacroAction) -> None:
        if self.episode.reasoning_steps >= self.context.max_reasoning_steps:
            raise Stop(f"reached the limit of {self.context.max_reasoning_steps} reasoning steps")
        self.episode.reasoning_steps += 1
        self.episode.log("macro", macro.feature, expected=dict(macro.expect))
        self.values_before = self.belief.values()

    # --- goal ------------------------------------------------------------------------------

    def _goal(self) -> tuple[dict[str, Any], dict[str, Any]]:
        """The goal split into values the belief has and values it does not."""
        inside: dict[str, Any] = {}
        outside: dict[str, Any] = {}
        variables = self.belief.model.variables
        for name, raw in self.context.goal.items():
            if name not in variables:
                raise Stop(f"the goal names {name!r}, which the model does not have")
            try:
                inside[name] = normalise(variables[name], raw)
            except ValueProblem:
                outside[name] = raw
        for problem in check_goal(self.belief.model, inside):  # not in the goal programme's range
            name = problem.path[-1]
            outside[name] = self.context.goal[name]
            del inside[name]
        return inside, outside

    def _outside_text(self, outside: dict[str, Any]) -> str:
        return "; ".join(f"{name}={raw!r} is not a value the model knows" for name, raw in
                         outside.items())

    def _domain_values(self, name: str) -> list[Any]:
        compiled = self.belief.compiled
        var = compiled.vars[compiled.var_index[name]]
        domain = var.domain(self.belief.state.values)
        return list(domain.values) if domain is not None else []

    def _proxy(self, name: str, raw: Any, inside: dict[str, Any]) -> Any:
        """A value the belief has, to reach the variable's setting and look at it there."""
        spec = self.belief.model.variables[name]
        values = self._domain_values(name)
        if spec.depends_on in inside:  # the setting as it will be in the goal's programme
            case = (spec.cases or {}).get(str(inside[spec.depends_on]))
            values = list(build_domain(spec, case).values) if case is not None else []
        current = self.belief.value(name)
        others = [v for v in values if v != current] or values
        if isinstance(spec, DiscreteVariable) or not others:
            index = values.index(current) if current in values else -1
            return values[(index + 1) % len(values)] if values else current
        goal = _magnitude(spec, _loose(spec, raw))
        if goal is None:
            return others[0]
        return min(others, key=lambda v: abs(_magnitude(spec, v) - goal))

    def _plan(self, target: dict[str, Any]) -> Any:
        try:
            return plan(self.belief.compiled, self.belief.state, target,
                        self.config.plan_budget)
        except GoalError as exc:
            raise Stop(f"the goal does not fit the belief model: {exc}") from None
        except Unreachable as exc:
            if not self.config.closed_loop or exc.budget_hit:
                raise Stop(f"no plan on the belief model: {exc.reason}") from None
            blocked = [name for name, value in target.items()
                       if not self._plannable({name: value})]
            rest = {name: value for name, value in target.items() if name not in blocked}
            if blocked and rest and self._plannable(rest):
                partial = plan(self.belief.compiled, self.belief.state, rest,
                               self.config.plan_budget)
                if partial.macro_actions:
                    return partial  # progress on the rest first
            if self._recover_unreachable({name: target[name] for name in blocked}):
                return self._plan(target)
            raise Stop(f"no plan on the belief model: {exc.reason}") from None

    def _plannable(self, goal: dict[str, Any]) -> bool:
        try:
            plan(self.belief.compiled, self.belief.state, goal, self.config.plan_budget)
        except Unreachable:
            return False
        return True

    def _recover_unreachable(self, target: dict[str, Any]) -> bool:
        """The belief cannot reach a goal variable: probe the actions no feature uses for
        the one that brings that setting up, and make it the first step of its feature."""
        for name in target:
            key = f"unreachable:{name}"
            if self.mismatches[key]:
                continue
            self.mismatches[key] += 1
            features = [f for f, steps in self.belief.model.features.items()
                        if any(s.variable == name for s in steps)]
            for candidate in self._orphans():
                self._lift_guards(candidate)
                probe = self._press(self._planned(candidate), exploring=True)
                estimate = self._estimate(probe.feedback)
                if not probe.feedback.accepted or not (
                        name in estimate.values or name in estimate.outside):
                    continue
                for feature in features:
                    try:
                        new = insert_step(self.belief.model, feature, 0, [candidate])
                    except RepairError:
                        continue
                    self._adopt(new, f"{feature} starts with {candidate}", (feature, 0))
                    self._sync(estimate)
                    return True
            if any(self._find_separator(feature, name) for feature in features):
                return True
        return False

    def _find_separator(self, feature: str, name: str) -> bool:
        """A step of ``feature`` that can never be entered because it shares its keys with
        the step before it: walk the procedure up to that step, then try the procedure's other
        keys for the one that brings ``name`` up (a SET/CLOCK press between hours and minutes)."""
        steps = self.belief.model.features[feature]
        index = next((i for i, s in enumerate(steps) if s.variable == name), None)
        if index is None or index == 0 or not set(steps[index].actions) & \
                set(steps[index - 1].actions):
            return False
        inside = {a for i in (index - 1, index) for a in steps[i].actions}
        others = [a for s in steps for a in s.actions if a not in inside]
        walk = [s.actions[0] for s in steps[:index]]
        for candidate in dict.fromkeys(others):
            self._lift_guards(walk[0])
            for action in walk:
                self._press(self._planned(action), exploring=True)
            probe = self._press(self._planned(candidate), exploring=True)
            estimate = self._estimate(probe.feedback)
            if probe.feedback.accepted and (name in estimate.values or name in estimate.outside):
                try:
                    new = insert_step(self.belief.model, feature, index, [candidate])
                except RepairError:
                    continue
                self._adopt(new, f"{feature} needs {candidate} before {name}", (feature, index))
                self._sync(estimate)
                return True
            self._resync_pointer()
        return False

    def _lift_guards(self, action: str) -> None:
        """Bring the appliance out of any guard that would refuse ``action`` (switch it on,
        unlock it), so a probe with ``action`` can tell something."""
        compiled = self.belief.compiled
        index = compiled.action_index[action]
        for guard in compiled.guards:
            holds = all(self.belief.state.values[v] in ok for v, ok in guard.conditions)
            if index in guard.allowed or not holds:
                continue
            for v, ok in guard.conditions:
                domain = compiled.vars[v].domain(self.belief.state.values)
                others = [value for i, value in enumerate(domain.values if domain else ())
                          if i not in ok]
                if not others:
                    continue
                try:
                    found = plan(compiled, self.belief.state, {compiled.vars[v].name: others[0]},
                                 self.config.plan_budget)
                except Unreachable:
                    continue
                for planned in found.actions:
                    self._press(planned, exploring=True)
                self._sync(self._estimate(self.last))
                break

    def _orphans(self) -> list[str]:
        """Actions the environment offers that no feature of the belief uses."""
        used = {a for steps in self.belief.model.features.values() for s in steps
                for a in s.actions}
        offered = set(self.env.actions)
        return [a for a in self.belief.model.actions if a not in used and a in offered][:8]

    def _planned(self, action: str) -> PlannedAction:
        spec = self.belief.model.actions[action]
        return PlannedAction(action, spec.skill, tuple(spec.control_ids), spec.seconds)

    # --- acting ------------------------------------------------------------------------------

    def _press(self, action: PlannedAction, exploring: bool = False) -> Executed:
        before = self.belief.state
        pointer_before = self.belief.pointer()
        believed = self.belief.advance(action.name, action.seconds)
        pointer = self.belief.pointer() if believed else pointer_before
        variable = self._step_variable(pointer) if believed else None
        predicted = self.belief.value(variable) if variable else None
        shown = bool(variable) and variable in self.belief.expected().values
        feedback = self.env.step(action.name, action.seconds)
        if not feedback.accepted:
            self.belief.state = before  # a refused action changes nothing
        self.episode.execution_steps += 1
        self.last = feedback
        self.episode.log("action", action=action.name, display=feedback.text,
                         values=dict(feedback.values), accepted=feedback.accepted,
                         exploring=exploring)
        return Executed(action, pointer, variable, feedback, believed, pointer_before, predicted,
                        shown)

    def _step_variable(self, pointer: tuple[str, int] | None) -> str | None:
        if pointer is None:
            return None
        feature, index = pointer
        return self.belief.model.features[feature][index].variable

    def _execute(self, macro: MacroAction) -> list[Executed]:
        if self.config.button_policy:
            executed = []
            for action in macro.actions:
                executed.append(self._press(action))
                if self.config.closed_loop and executed[-1].believed_accepted and \
                        not executed[-1].feedback.accepted:
                    break  # the appliance refused what the model allows: stop and find out why
            return executed
        return self._execute_greedily(macro)

    def _execute_greedily(self, macro: MacroAction) -> list[Executed]:
        """Without the button policy: enter each step as planned, then choose every further
        press from the feedback, one at a time, each choice a reasoning step."""
        executed: list[Executed] = []
        actions = list(macro.actions)
        i = 0
        while i < len(actions):
            done = self._press(actions[i])
            executed.append(done)
            i += 1
            run_end = i
            while (run_end < len(actions) and self._same_step(executed[-1], actions[run_end])):
                run_end += 1
            if run_end == i or done.variable is None or not self._steppable(done):
                continue
            target = self._value_after(actions[i:run_end])
            executed.extend(self._greedy(done, target))
            i = run_end
        return executed

    def _same_step(self, done: Executed, action: PlannedAction) -> bool:
        if done.pointer is None:
            return False
        feature, index = done.pointer
        return action.name in self.belief.model.features[feature][index].actions and \
            self._effect(done.pointer, action.name) not in ("digit", "none")

    def _steppable(self, done: Executed) -> bool:
        assert done.pointer is not None
        effect = self._effect(done.pointer, done.action.name)
        return effect in ("next", "prev", "toggle") or isinstance(effect, Add)

    def _effect(self, pointer: tuple[str, int], action: str) -> Any:
        feature, index = pointer
        step = self.belief.model.features[feature][index]
        return default_effect(step, action, self.belief.model)

    def _value_after(self, actions: list[PlannedAction]) -> Any:
        """What the belief says the step's variable will be after these planned presses."""
        saved = self.belief.state
        name = self._step_variable(self.belief.pointer())
        for action in actions:
            self.belief.advance(action.name, action.seconds)
        value = self.belief.value(name) if name else None
        self.belief.state = saved
        return value

    def _greedy(self, entered: Executed, target: Any) -> list[Executed]:
        """Press whichever of the step's actions the belief says brings the value closest,
        look, and repeat until the display shows the target."""
        assert entered.pointer is not None and entered.variable is not None
        name = entered.variable
        feature, index = entered.pointer
        choices = [a for a in self.belief.model.features[feature][index].actions
                   if self._effect(entered.pointer, a) not in ("digit", "none")]
        executed: list[Executed] = []
        seen: Counter[Any] = Counter()
        while True:
            estimate = self._estimate(self.last)
            observed = estimate.values.get(name, estimate.outside.get(name, MISSING))
            if observed is MISSING or observed == target:
                return executed
            self.belief.set_value(name, observed)
            seen[observed] += 1
            if seen[observed] > 2:  # going round in circles
                return executed
            best = min(choices, key=lambda a: self._distance_after(name, a, target))
            if self.episode.reasoning_steps >= self.context.max_reasoning_steps:
                raise Stop("reached the limit of "
                           f"{self.context.max_reasoning_steps} reasoning steps")
            self.episode.reasoning_steps += 1
            spec = self.belief.model.actions[best]
            executed.append(self._press(PlannedAction(best, spec.skill,
                                                      tuple(spec.control_ids), spec.seconds)))

    def _distance_after(self, name: str, action: str, target: Any) -> float:
        saved = self.belief.state
        self.belief.advance(action)
        values = self._domain_values(name)
        after = self.belief.value(name)
        self.belief.state = saved
        if after not in values or target not in values:
            return float("inf")
        return abs(values.index(after) - values.index(target))

    # --- checking ----------------------------------------------------------------------------

    def _estimate(self, feedback: Feedback) -> Estimate:
        return self.estimator.estimate(feedback, context=self.belief.values())

    def _sync(self, estimate: Estimate) -> None:
        for name, value in estimate.values.items():
            self.belief.set_value(name, value)

    def _check(self, macro: MacroAction, executed: list[Executed],
               outside: dict[str, Any]) -> bool:
        """Compare the display with the belief after a macro action; repair on a mismatch.
        True when everything was as predicted (the rest of the plan still holds)."""
        if not self.config.closed_loop:
            return True
        estimate = self._estimate(self.last)
        found: list[Mismatch] = []
        for name, value in estimate.values.items():
            if self.belief.value(name) != value:
                found.append(Mismatch(name, self.belief.value(name), value))
        for name, value in estimate.outside.items():
            found.append(Mismatch(name, self.belief.value(name), value, outside=True))
        shown = set(estimate.values) | set(estimate.outside)
        expected_focus = self.belief.expected().focus
        refused = [i for i, e in enumerate(executed)
                   if e.believed_accepted and not e.feedback.accepted]
        divergence = self._divergence(executed)
        self.episode.log("check", "ok" if not (found or refused or divergence) else "mismatch",
                         expected={m.variable: m.expected for m in found} or dict(macro.expect),
                         values={m.variable: m.observed for m in found})
        elsewhere = shown - set(self.belief.model.display.indicators)
        wrong_focus = bool(expected_focus and expected_focus not in shown and elsewhere and
                           executed and executed[-1].variable == expected_focus)
        if divergence is not None and (not refused or divergence[0] < refused[0]):
            index, mismatch = divergence  # repair the first thing that went wrong, re-plan
            found.append(mismatch)
            self._repair_value(mismatch, executed, index)
        elif refused or wrong_focus:
            self._repair_procedure(executed, [executed[i] for i in refused])
            return False
        else:
            for mismatch in found:
                self._repair_value(mismatch, executed)
        if found:
            estimate = self._estimate(self.last)  # exploring moved the appliance on
        self._sync(estimate)
        if found or divergence:
            outside = self._goal()[1]  # a repair may have taught the belief the goal value
        focused = [name for name in outside if name in shown and name not in self.explored]
        if focused:
            self._explore_outside({name: outside[name] for name in focused})
        return not (found or focused or outside)

    def _divergence(self, executed: list[Executed]) -> tuple[int, Mismatch] | None:
        """The first action after which the display showed its step's variable with a value
        other than the belief predicted (the root of a mismatch seen later, e.g. a wrong
        programme that made the weight typed after it invalid)."""
        for index, done in enumerate(executed):
            name = done.variable
            if name is None or not done.believed_accepted or not done.feedback.accepted:
                continue
            estimate = self._estimate(done.feedback)
            observed = estimate.values.get(name, estimate.outside.get(name, MISSING))
            if observed is MISSING and done.shown:  # expected on the display, and it is dark
                return index, Mismatch(name, done.predicted, None)
            if observed is not MISSING and observed != done.predicted:
                return index, Mismatch(name, done.predicted, observed,
                                       outside=name in estimate.outside)
        return None

    def _history(self, name: str, last: Executed, executed: list[Executed]) -> list[Any]:
        """Values ``name`` showed under the presses of ``last``'s action that end the macro
        action: the start of the exploration trace, already paid for."""
        values: list[Any] = []
        for done in reversed(executed):
            if done.action.name != last.action.name or done.pointer != last.pointer:
                break
            estimate = self._estimate(done.feedback)
            value = estimate.values.get(name, estimate.outside.get(name, MISSING))
            if value is MISSING:
                break
            values.append(value)
        return list(reversed(values))

    def _repair_value(self, mismatch: Mismatch, executed: list[Executed],
                      upto: int | None = None) -> None:
        name = mismatch.variable
        self.mismatches[name] += 1
        if self.mismatches[name] > MAX_SAME_REPAIR:
            raise Stop(f"{name} keeps showing values the model does not predict "
                       f"(last: {mismatch.observed!r}, expected {mismatch.expected!r})")
        considered = executed if upto is None else executed[:upto + 1]
        adjusting = [e for e in considered if e.variable == name and e.believed_accepted]
        if not adjusting:
            return  # changed as a side effect: believing the display is all we can do
        last = adjusting[-1]
        assert last.pointer is not None
        unchanged = mismatch.observed == self.values_before.get(name)
        if unchanged and self._absorbed(adjusting[0]):
            return
        effect = self._effect(last.pointer, last.action.name)
        stepping = effect in ("next", "prev", "toggle") or isinstance(effect, Add)
        if mismatch.observed is None and not stepping:
            return  # dark where a value was expected, and nothing to walk through
        if isinstance(effect, GoTo):
            self._learn_goto(name, last, mismatch.observed)
        elif effect == "digit":
            self._widen(name, [mismatch.observed])
        elif effect in ("next", "prev", "toggle") or isinstance(effect, Add):
            self._explore(name, last, self._history(name, last, executed))
            return
        self.belief.set_value(name, mismatch.observed)

    def _absorbed(self, entering: Executed) -> bool:
        """An action meant to start a new procedure changed nothing: perhaps the procedure
        the appliance was in takes that action as one more step (a START that confirms a
        clock). Add it there, once, and let the next check judge."""
        before, after = entering.before, entering.pointer
        if before is None or after is None or before[0] == after[0]:
            return False
        shown = set(self._estimate(entering.feedback).values) - set(
            self.belief.model.display.indicators)
        staying = {s.variable for s in self.belief.model.features[before[0]]} - {None}
        if entering.variable in staying | shown or not staying & shown:
            return False  # the display moved on: the action did start something else
        key = f"absorbed:{before[0]}:{entering.action.name}"
        if self.mismatches[key]:
            return False
        self.mismatches[key] += 1
        feature, index = before
        try:
            new = insert_step(self.belief.model, feature, index + 1, [entering.action.name])
        except RepairError as exc:
            self.episode.log("repair", f"could not add a step to {feature}: {exc}")
            return False
        self._adopt(new, f"{feature} takes {entering.action.name} as a further step",
                    (feature, index + 1))
        self._sync(self._estimate(self.last))
        return True

    def _explore_outside(self, outside: dict[str, Any]) -> None:
        """Look at a variable whose goal value the belief lacks: explore it, or for a keypad
        setting, allow the value and let the next check say whether it exists."""
        for name, raw in outside.items():
            spec = self.belief.model.variables[name]
            if getattr(spec, "entry", None) is not None:
                self.explored.add(name)
                value = _loose(spec, raw)
                if value is not None:
                    self._widen(name, [value])
                continue
            stepping = self._stepping_action(name)
            if stepping is not None:  # (else the proxy plan has not reached its setting yet)
                self.explored.add(name)
                self._explore(name, stepping)

    def _stepping_action(self, name: str) -> Executed | None:
        """The step the belief is in, if it steps ``name`` with next/prev/add."""
        pointer = self.belief.pointer()
        if pointer is None or self._step_variable(pointer) != name:
            return None
        feature, index = pointer
        for action in self.belief.model.features[feature][index].actions:
            effect = self._effect(pointer, action)
            if effect in ("next", "prev", "toggle") or isinstance(effect, Add):
                spec = self.belief.model.actions[action]
                planned = PlannedAction(action, spec.skill, tuple(spec.control_ids), spec.seconds)
                return Executed(planned, pointer, name, self.last, True)
        return None

    # --- exploring and learning ------------------------------------------------------------

    def _trace(self, name: str, action: PlannedAction,
               history: list[Any] | None = None) -> tuple[list[Any], int]:
        """Press ``action`` until the value of ``name`` shown repeats.

        A press after which the display shows nothing for ``name`` (an OFF position) is
        recorded as :class:`Dark`; two in a row end the walk. Returns the values seen and how
        many presses at the end went unseen (the appliance moved on in the dark).
        """
        estimate = self._estimate(self.last)
        start = estimate.values.get(name, estimate.outside.get(name, MISSING))
        values = [] if start is MISSING else [start]  # not shown now: start from the first press
        if history and values and history[-1] == values[0]:
            values = list(history)  # the macro action's own presses of this action come first
            if len(values) >= 2 and values[-1] in values[:-1]:
                return values, 0  # they already went round
        dark = 0
        for _ in range(self.config.explore_limit):
            done = self._press(action, exploring=True)
            if not done.feedback.accepted:
                break
            estimate = self._estimate(done.feedback)
            value = estimate.values.get(name, estimate.outside.get(name, MISSING))
            if value is MISSING:
                dark += 1
                values.append(Dark())
                if dark >= 2:
                    break
                continue
            dark = 0
            values.append(value)
            if value in values[:-1]:
                break
        return values, dark

    def _explore(self, name: str, last: Executed, history: list[Any] | None = None) -> None:
        assert last.pointer is not None
        pointer = last.pointer
        action = last.action
        forward, unseen = self._trace(name, action, history or [])
        backward: list[Any] | None = None
        opposite = self._opposite(pointer, action.name)
        final = action
        if len(forward) >= 2 and forward[-1] == forward[-2] and opposite is not None:
            backward, unseen = self._trace(name, opposite)
            final = opposite
        self.episode.log("explore", f"{name} under {action.name}: "
                         f"{_summary(forward)}" + (f"; under {opposite.name}: "
                                                   f"{_summary(backward)}" if backward else ""))
        if len([v for v in forward if not isinstance(v, Dark)]) < 2:
            return
        current = next(v for v in reversed(backward or forward) if not isinstance(v, Dark))
        self._learn(name, pointer, action.name, opposite, forward, backward, current)
        for _ in range(unseen):  # presses taken in the dark: the repaired model says where to
            self.belief.advance(final.name, final.seconds)

    def _opposite(self, pointer: tuple[str, int], action: str) -> PlannedAction | None:
        feature, index = pointer
        effect = self._effect(pointer, action)
        for other in self.belief.model.features[feature][index].actions:
            if other == action:
                continue
            theirs = self._effect(pointer, other)
            stepping = theirs in ("next", "prev") or isinstance(theirs, Add)
            if stepping and theirs != effect:
                return self._planned(other)
        return None

    def _learn(self, name: str, pointer: tuple[str, int], action: str,
               opposite: PlannedAction | None, forward: list[Any],
               backward: list[Any] | None, current: Any) -> None:
        """Write what the traces show into the belief model."""
        model = self.belief.model
        spec = model.variables[name]
        case = self._case(name)
        effect = self._effect(pointer, action)
        order = order_from_traces(forward, backward)
        if not order.values:
            return
        notes: list[str] = []
        try:
            if isinstance(spec, DiscreteVariable):
                values = [v if isinstance(v, Dark) else str(v) for v in order.values]
                if effect == "prev":
                    values.reverse()
                values = fill_dark(values, self._domain_values(name), order.wrap)
                if not order.complete:
                    values = splice(self._domain_values(name), values)
                new = redefine_domain(model, name, case, values=values, wrap=order.wrap,
                                      current=current)
                notes.append(f"{name}: values {_summary(values)}{_ends(order.wrap)}")
            else:
                magnitudes = [_magnitude(spec, v) for v in order.values
                              if not isinstance(v, Dark)]
                numbers = [m for m in magnitudes if m is not None]
                if not numbers:
                    return
                change = _direction(spec, forward, backward)
                new = model
                if isinstance(effect, Add):
                    new, numbers = self._learn_add(new, pointer, action, spec, change,
                                                   numbers, notes)
                elif effect in ("next", "prev") and change is not None:
                    rising = change > 0
                    if rising != (effect == "next"):
                        flipped = {action: "prev" if effect == "next" else "next"}
                        if opposite is not None:
                            flipped[opposite.name] = effect
                        new = set_effects(new, pointer[0], pointer[1], flipped)
                        notes.append(f"{action} moves {name} the other way")
                    if not order.complete:
                        numbers = _keep_unseen(self._magnitudes(name), numbers,
                                               clamped_high=rising if order.wrap is False
                                               else None)
                ranges = ranges_from_values(numbers)
                new = redefine_domain(new, name, case, ranges=ranges,
                                      wrap=order.wrap if effect != "toggle" else None,
                                      current=_canonical_raw(spec, current))
                notes.append(f"{name}: ranges {ranges}{_ends(order.wrap)}")
        except RepairError as exc:
            self.episode.log("repair", f"could not repair {name}: {exc}")
            return
        self._adopt(new, "; ".join(notes), pointer)
        self.belief.set_value(name, current)

    def _learn_add(self, model: Any, pointer: tuple[str, int], action: str, spec: Any,
                   change: float | None, numbers: list[float],
                   notes: list[str]) -> tuple[Any, list[float]]:
        """An ``add`` key: learn its amount and sign; widen (never shrink) the domain."""
        effect = self._effect(pointer, action)
        believed = float(time_step_seconds(effect.add) if isinstance(effect.add, str)
                         else effect.add)
        if change is not None and change != believed:
            amount: Any = int(change) if isinstance(spec, TimeVariable) else _tidy(change)
            model = set_effects(model, pointer[0], pointer[1], {action: {"add": amount}})
            notes.append(f"{action} adds {amount:g}" if isinstance(amount, float) else
                         f"{action} adds {amount}")
        known = self._magnitudes(self._step_variable(pointer) or "")
        merged = sorted(set(known) | set(numbers))
        return model, merged

    def _learn_goto(self, name: str, last: Executed, observed: Any) -> None:
        assert last.pointer is not None
        try:
            new = set_effects(self.belief.model, last.pointer[0], last.pointer[1],
                              {last.action.name: {"to": observed}})
        except RepairError as exc:
            self.episode.log("repair", f"could not repair {last.action.name}: {exc}")
            return
        self._adopt(new, f"{last.action.name} sets {name} to {observed}", last.pointer)

    def _widen(self, name: str, observed: list[Any]) -> None:
        """Let a keypad setting take values the belief's ranges missed."""
        spec = self.belief.model.variables[name]
        if isinstance(spec, DiscreteVariable):
            return
        known = self._magnitudes(name)
        extra = [m for m in (_magnitude(spec, _loose(spec, v)) for v in observed)
                 if m is not None]
        if not known or not extra or set(extra) <= set(known):
            return
        points = sorted(set(known) | set(extra))
        step = common_step(points)
        low, high = points[0], points[-1]
        try:
            new = redefine_domain(self.belief.model, name, self._case(name),
                                  ranges=[(low, high, step)])
        except RepairError as exc:
            self.episode.log("repair", f"could not widen {name}: {exc}")
            return
        self._adopt(new, f"{name}: allow {low:g}..{high:g} in steps of {step:g}",
                    self.belief.pointer())

    def _repair_procedure(self, executed: list[Executed], refused: list[Executed]) -> None:
        """An action the model expected to work did not (refused, or the wrong setting came
        up): look for a step the procedure is missing among the actions no feature uses."""
        failing = (refused or [e for e in executed if e.variable is not None])
        if not failing or failing[0].pointer is None:
            raise Stop("the appliance does not respond as the model predicts, and the "
                       "model gives no step to learn from")
        first = failing[0]
        assert first.pointer is not None
        name = first.variable
        key = f"procedure:{first.pointer[0]}"
        self.mismatches[key] += 1
        if self.mismatches[key] > MAX_SAME_REPAIR:
            raise Stop(f"{first.action.name} keeps failing in {first.pointer[0]}")
        feature, index = first.pointer
        idle = [a for a in self.belief.model.features[feature][index].actions
                if a != first.action.name and self._effect(first.pointer, a) == "none"]
        for candidate in self._orphans() + idle:
            probe = self._press(self._planned(candidate), exploring=True)
            if not probe.feedback.accepted:
                continue
            after = self._press(first.action, exploring=True)
            estimate = self._estimate(after.feedback)
            if after.feedback.accepted and name is not None and (
                    name in estimate.values or name in estimate.outside):
                feature, index = first.pointer
                try:
                    new = insert_step(self.belief.model, feature, index, [candidate])
                except RepairError as exc:
                    self.episode.log("repair", f"could not add a step: {exc}")
                    continue
                self._adopt(new, f"{feature} starts with {candidate} before "
                            f"{first.action.name}", (feature, index + 1))
                self._sync(estimate)
                return
        self._resync_pointer()

    def _resync_pointer(self) -> None:
        """After actions the belief cannot follow, assume no feature is active."""
        self.belief.set_pointer(None)
        self._sync(self._estimate(self.last))

    def _adopt(self, model: Any, note: str, pointer: tuple[str, int] | None) -> None:
        self.belief.replace(model, pointer)
        self.estimator.rebind(model)
        self.episode.repairs.append(note)
        self.episode.log("repair", note)

    # --- helpers ------------------------------------------------------------------------------

    def _case(self, name: str) -> str | None:
        parent = self.belief.model.variables[name].depends_on
        return None if parent is None else str(self.belief.value(parent))

    def _magnitudes(self, name: str) -> list[float]:
        if not name:
            return []
        spec = self.belief.model.variables[name]
        values = self._domain_values(name)
        return [m for m in (_magnitude(spec, v) for v in values) if m is not None]


def _magnitude(spec: Any, value: Any) -> float | None:
    if value is None:
        return None
    try:
        if isinstance(spec, TimeVariable):
            return float(parse_hms(str(value)))
        return float(value)
    except (TypeError, ValueError):
        return None


def _ends(wrap: bool | None) -> str:
    return {True: ", wraps", False: ", stops at the ends", None: ""}[wrap]


def _keep_unseen(known: list[float], seen: list[float],
                 clamped_high: bool | None) -> list[float]:
    """Numbers after a partial walk: what was seen replaces the belief between the lowest and
    highest value seen; beyond them the belief stands, except past an end the walk hit."""
    low, high = min(seen), max(seen)
    kept = [m for m in known if (m < low and clamped_high is not False)
            or (m > high and clamped_high is not True)]
    return sorted(set(seen) | set(kept))


def _direction(spec: Any, forward: list[Any], backward: list[Any] | None) -> float | None:
    """The usual change one press of the explored action makes (from the opposite action's
    trace, reversed, when the first press already hit an end)."""
    def numbers(trace: list[Any]) -> list[float]:
        return [m for m in (_magnitude(spec, v) for v in trace) if m is not None]

    change = typical_change(numbers(forward))
    if change is None and backward:
        opposite = typical_change(numbers(backward))
        change = None if opposite is None else -opposite
    return change


def _loose(spec: Any, raw: Any) -> Any:
    """``raw`` in canonical form for ``spec``'s type, whether or not its domain has it."""
    try:
        return parse_value(spec, raw)
    except ValueProblem:
        return None


def _canonical_raw(spec: Any, value: Any) -> Any:
    magnitude = _magnitude(spec, value)
    if magnitude is None:
        return None
    if isinstance(spec, TimeVariable):
        return format_hms(int(magnitude))
    return _tidy(magnitude)


def _tidy(number: float) -> int | float:
    return int(number) if float(number).is_integer() else number


def _summary(values: list[Any] | None) -> str:
    if not values:
        return "nothing"
    shown = [str(v) for v in values]
    return ", ".join(shown) if len(shown) <= 12 else ", ".join(shown[:10]) + f", … ({len(shown)})"


def run_agent(config: AgentConfig, context: TaskContext, env: Environment) -> Episode:
    """One episode of ApBot (or an ablation of it) on ``env``."""
    return _Run(config, context, env).run()


__all__ = ["AgentConfig", "run_agent"]
