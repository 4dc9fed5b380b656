"""The ApBot closed loop: plan on the belief, execute one macro action, check, repair, re-plan.

After every macro action the agent compares what the appliance showed after each press with
what its belief predicted. On a mismatch it explores — repeats the step's key until a shown
value repeats (and the opposite key after an end) — infers the variable's true definition from
that walk by code, writes it into the belief and plans again from the observed state. A goal
value the belief does not even contain is treated the same way: the agent brings the setting
up, explores it, and learns whether the value exists. Faults in procedures are probed for
(``apbot.agent.procedures``).

Counting follows the paper: a reasoning step is one macro action (exploration excluded); every
physical action, exploration included, is an execution step.
"""

from __future__ import annotations

from collections.abc import Hashable
from typing import Any

from apbot.agent.budget import Budget
from apbot.agent.discovery import VariableFinder
from apbot.agent.displays import DisplayLearner
from apbot.agent.environment import Environment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.explorer import Explorer
from apbot.agent.greedy import GreedyExecutor
from apbot.agent.guards import GuardLearner
from apbot.agent.looking import route_to_screen
from apbot.agent.merged import ProcedureSplitter
from apbot.agent.perception import Seen
from apbot.agent.procedures import ProcedureRepairer
from apbot.agent.session import (
    MISSING,
    UNREADABLE,
    AgentConfig,
    Executed,
    Session,
    Stop,
    loose,
    magnitude,
    summary,
)
from apbot.model.display import can_show, display_value
from apbot.model.domain import ValueProblem, all_values, build_domain, normalise
from apbot.model.goal import GoalError
from apbot.model.schema import DiscreteVariable, GoTo
from apbot.model.validate import check_goal
from apbot.plan.plan import MacroAction, Plan, Unreachable, plan
from apbot.sim.compiled import CompiledModel, State

__all__ = ["AgentConfig", "run_agent"]


class ClosedLoop:
    """One episode of the agent: plans, executes, checks and dispatches repairs to its
    collaborators (the explorer, the procedure repairer, the greedy executor), which share one
    :class:`Session`."""

    def __init__(self, config: AgentConfig, context: TaskContext, env: Environment) -> None:
        self.session = Session(config, context, env, Budget())
        self.displays = DisplayLearner(self.session)
        self.explorer = Explorer(self.session, self.displays)
        self.guards = GuardLearner(self.session)
        self.procedures = ProcedureRepairer(self.session, self.guards)
        self.finder = VariableFinder(self.session, self.guards)
        self.splitter = ProcedureSplitter(self.session)
        self.greedy = GreedyExecutor(self.session)
        self.config = config
        self.context = context
        self.missing: dict[str, Any] = {}  # goal settings the belief lacks and has not found
        self.finding = 1  # the finder's attempt: once at the start, once with the rest set
        self._plans_on: CompiledModel | None = None  # the belief the remembered plans are on
        self._plans: dict[Hashable, Plan | Unreachable] = {}
        self.pending: list[MacroAction] = []  # the rest of the plan, while it holds
        self.values_before: dict[str, Any] = {}  # the belief before the current macro action

    def run(self) -> Episode:
        episode = self.session.episode
        try:
            self.session.start()
            if not self.config.closed_loop:
                self.open_loop()
            stalled = 0
            while True:
                mark = (episode.reasoning_steps, episode.execution_steps, len(episode.repairs))
                self.reasoning_step()
                progress = mark != (
                    episode.reasoning_steps,
                    episode.execution_steps,
                    len(episode.repairs),
                )
                stalled = 0 if progress else stalled + 1
                if stalled >= 2:
                    raise Stop("no progress: the belief offers no way to bring the goal closer")
        except Stop as stop:
            episode.claimed_success = stop.success
            episode.failure = "" if stop.success else stop.reason
            episode.log("stop", stop.reason)
        except Unreachable as exc:  # a repair left the belief with no plan: a declared failure
            episode.failure = f"no plan on the belief model: {exc.reason}"
            episode.log("stop", episode.failure)
        episode.belief = self.session.belief.model
        return episode

    def open_loop(self) -> None:
        """Plan once on the belief and press everything: no checks, no repairs."""
        inside, outside = self.goal()
        if outside:
            raise Stop(_outside_text(outside))
        for macro in self.make_plan(inside).macro_actions:
            self.start_macro(macro)
            self.execute(macro)
        holds = all(self.session.belief.value(n) == v for n, v in inside.items())
        raise Stop(
            "plan executed" if holds else "plan executed, but the belief no longer holds the goal",
            success=holds,
        )

    def reasoning_step(self) -> None:
        inside, outside = self.goal()
        if self.missing:  # set the rest first (the missing setting may need its programme),
            inside = {n: v for n, v in inside.items() if not _starts(n)}  # but do not start
        for name in outside:
            if name in self.session.explored:
                if self._again_after_the_rest(name, inside):
                    continue
                raise Stop(
                    _outside_text({name: outside[name]}) + " (explored: "
                    f"{summary(self.session.domain_values(name))})"
                )
        if not self.pending:
            target = dict(inside)
            for name in outside:
                proxy = self.proxy(name, inside)
                if proxy is not MISSING:
                    target[name] = proxy
                elif name not in self.session.explored:
                    # the setting is to be looked for in its programme: starting first would
                    # lock it out
                    target = {n: v for n, v in target.items() if not _starts(n)}
            found = self.make_plan(target)
            if not found.macro_actions:
                if self.missing:
                    self.finding += 1  # the rest is set: look for the missing settings again
                    return
                if outside:
                    pressed = self.session.episode.execution_steps
                    self.explore_outside(outside)
                    if self.session.episode.execution_steps == pressed:  # no value to go to first
                        any(self.inspect(name) for name in outside)
                    return
                if any(self.session.belief.value(n) != v for n, v in inside.items()):
                    raise Stop("the rest of the goal cannot be reached on the belief model")
                if self.settle_contradictions(inside):
                    return  # the belief now holds what was shown: plan again
                unseen = self.session.unconfirmed(set(inside))
                if unseen and self._look(unseen):
                    return  # plan again from what the display showed
                if unseen:  # believed, but the display last said otherwise: it would be a guess
                    raise Stop(
                        "the belief holds the goal, but the display last showed "
                        + ", ".join(f"{n}={self._last_reading(n)}" for n in unseen)
                    )
                unseeable = [
                    n
                    for n in sorted(inside)
                    if n not in self.session.ever_seen
                    and not can_show(self.session.belief.model, n)
                ]
                if unseeable:  # an oven lamp: the plan may have done it, nothing can tell
                    raise Stop(
                        "the belief holds the goal, but the display cannot show "
                        + ", ".join(unseeable)
                        + ": done as planned, not confirmed"
                    )
                raise Stop("the goal holds", success=True)
            self.pending = list(found.macro_actions)
            self.session.episode.log("plan", " → ".join(m.feature for m in found.macro_actions))
        if any(_starts(n) or _locks(n) for n in self.pending[0].expect):
            # once it runs (or the lock is on), most keys are locked out: see what is
            # unconfirmed first
            unseen = self.session.unconfirmed({n for n in inside if not (_starts(n) or _locks(n))})
            if unseen and self._look(unseen):
                self.pending.clear()
                return
        macro = self.pending.pop(0)
        self.start_macro(macro)
        executed = self.execute(macro)
        if not self.check(macro, executed):
            self.pending.clear()  # the belief changed: plan again from what was observed

    def _again_after_the_rest(self, name: str, inside: dict[str, Any]) -> bool:
        """A goal value missing from what a walk showed, while the rest of the goal (a
        programme) is still to be set: the value may exist there. Walk it again once the rest
        holds (once per setting)."""
        pending = [n for n, v in inside.items() if self.session.belief.value(n) != v]
        if not [n for n in pending if not _starts(n)]:
            return False
        if not self.session.budget.once("inspect", f"again:{name}"):
            return False
        self.session.explored.discard(name)
        return True

    def _last_reading(self, name: str) -> str:
        if name in self.session.unread:
            return "(unreadable)"
        return repr(self.session.evidence.get(name, "?"))

    def explore(self, name: str, last: Executed, history: list[Any] | None = None) -> None:
        """Walk ``name`` with ``last``'s key; a walk stuck on one value looks for the key
        that walks it, filed under another procedure."""
        self.explorer.explore(name, last, history)
        if self.explorer.stuck is not None:
            self.procedures.find_sibling(*self.explorer.stuck)

    def start_macro(self, macro: MacroAction) -> None:
        self.session.count_reasoning_step()
        self.session.episode.log("macro", macro.feature, expected=dict(macro.expect))
        self.values_before = self.session.belief.values()

    def execute(self, macro: MacroAction) -> list[Executed]:
        if not self.config.button_policy:
            return self.greedy.execute_greedily(macro)
        executed = []
        for action in macro.actions:
            executed.append(self.session.press(action))
            if self.config.closed_loop and executed[-1].surprising:
                break  # not as predicted: pressing on would only make things worse
        return executed

    # --- the goal and the plan -----------------------------------------------------------

    def goal(self) -> tuple[dict[str, Any], dict[str, Any]]:
        """The goal split into values the belief has and values it does not."""
        inside: dict[str, Any] = {}
        outside: dict[str, Any] = {}
        variables = self.session.belief.model.variables
        self.missing = {}
        for name, raw in self.context.goal.items():
            if name not in variables:
                if not self.finder.find(name, raw, attempt=self.finding):
                    if self.finding >= 2:
                        raise Stop(
                            f"the goal names {name!r}, which the model does not have, and no "
                            "key the model gives no role shows it"
                        )
                    self.missing[name] = raw  # look again once the rest is set
                    continue
                variables = self.session.belief.model.variables
            try:
                inside[name] = normalise(variables[name], raw)
            except ValueProblem as exc:
                if loose(variables[name], raw) is None:  # not even a value of that kind
                    raise Stop(f"goal {name}={raw!r}: {exc}") from None
                outside[name] = raw
        for problem in check_goal(self.session.belief.model, inside):  # not in the goal programme's
            name = str(problem.path[-1])
            outside[name] = self.context.goal[name]
            del inside[name]
        return inside, outside

    def proxy(self, name: str, inside: dict[str, Any]) -> Any:
        """A value the belief has, near the goal value it lacks: planning to it brings the
        setting onto the display, where it can be explored (MISSING: the setting does not
        exist in the goal's programme at all, as far as the belief knows)."""
        spec = self.session.belief.model.variables[name]
        values = self.session.domain_values(name)
        if spec.depends_on in inside:  # the setting as it will be in the goal's programme
            case = (spec.cases or {}).get(str(inside[spec.depends_on]))
            if case is None:
                return MISSING  # the belief lacks it there: reach the programme, then look
            values = list(build_domain(spec, case).values)
        values = values or all_values(spec)
        current = self.session.belief.value(name)
        others = [v for v in values if v != current] or values
        if isinstance(spec, DiscreteVariable):
            index = values.index(current) if current in values else -1
            return values[(index + 1) % len(values)]
        goal = magnitude(spec, loose(spec, self.context.goal[name]))
        if goal is None:
            return others[0]
        return min(others, key=lambda v: abs((magnitude(spec, v) or 0) - goal))

    def make_plan(self, target: dict[str, Any]) -> Plan:
        """The belief's plan to ``target``; when it has none, make progress on the part it can
        reach, or probe for what it lacks."""
        try:
            return self._plan(target)
        except GoalError as exc:
            raise Stop(f"the goal does not fit the belief model: {exc}") from None
        except Unreachable as exc:
            if not self.config.closed_loop or exc.budget_hit:
                raise Stop(f"no plan on the belief model: {exc.reason}") from None
            reachable: dict[str, Any] = {}
            kept = ""  # a run state the appliance is in as asked: nothing may undo it
            # the goal variable that breaks planning (a run state last: it locks the rest)
            for name, value in sorted(target.items(), key=lambda item: _starts(item[0])):
                if self._plannable({**reachable, name: value}):
                    reachable[name] = value
                    continue
                if _starts(name):
                    others = {n: v for n, v in target.items() if n != name}
                    # running as asked, a way to the rest that stops the cycle is no progress:
                    # starting again would undo it (a reset the start is believed to make,
                    # often read off a running display that only hides the setting)
                    kept = name if self.session.belief.value(name) == value else ""
                    if others and not self._undoes(others, kept) and self._progress(others):
                        return self._plan(others)  # a run state comes last: set the rest first
                    anyway = self._start_anyway(name, value, target)
                    if anyway is not None:
                        return anyway
                # look for the way to it first: progress on the rest (starting a cycle, say)
                # could close the door on it
                if self.procedures.recover_unreachable({name: value}):
                    return self.make_plan(target)
                if self.guards.relax(target):
                    return self.make_plan(target)
                if reachable:
                    try:  # the repairs tried above may have changed what is reachable
                        partial: Plan | None = self._plan(reachable)
                    except Unreachable:
                        partial = None
                    if (
                        partial is not None
                        and partial.macro_actions
                        and not (kept and any(kept in m.expect for m in partial.macro_actions))
                    ):
                        return partial  # progress: the rest may be reachable from there
                if not kept and self.inspect(name):
                    return self.make_plan(target)
                break
            if kept:
                raise Stop(
                    f"no plan on the belief model that keeps {kept}={target[kept]}: {exc.reason}"
                ) from None
            raise Stop(f"no plan on the belief model: {exc.reason}") from None

    def _look(self, names: list[str]) -> bool:
        """Bring up a goal setting the display has not confirmed since the belief last changed
        it (once each): enter its step and press its key once, and read what it shows."""
        for name in names:
            if not self.session.budget.once("inspect", f"look:{name}"):
                continue
            session = self.session
            route = route_to_screen(
                session.belief.compiled,
                session.belief.state,
                name,
                session.belief.model.variables,  # a look changes nothing else
                sorted(session.offered & set(session.belief.model.actions)),
            )
            if route is not None:
                for action in route:
                    session.press(session.planned(action), exploring=True)
                return True
            if self._guarding_the_goal():
                continue  # getting out would undo the goal (stop a running cycle): no look
            for feature, steps in self.session.belief.model.features.items():
                index = next((i for i, s in enumerate(steps) if s.variable == name), None)
                if index is None:
                    continue
                self.guards.lift_all()  # a dark panel shows nothing
                self.procedures.enter_step(feature, index)
                self.session.press(self.session.planned(steps[index].actions[0]), exploring=True)
                return True
        return False

    def _guarding_the_goal(self) -> bool:
        """A guard holds whose condition the goal itself asks for (running, locked)."""
        compiled, state = self.session.belief.compiled, self.session.belief.state
        goal = set(self.context.goal)
        return any(
            all(state.values[v] in ok for v, ok in guard.conditions)
            and any(compiled.vars[v].name in goal for v, _ in guard.conditions)
            for guard in compiled.guards
        )

    def inspect(self, name: str) -> bool:
        """A goal setting the belief cannot reach: go through the procedure that adjusts it
        and walk its values, in case its keys do something else than believed. Once."""
        if not self.session.budget.once("inspect", name):
            return False
        for feature, steps in self.session.belief.model.features.items():
            for index, step in enumerate(steps):
                walking = [
                    a
                    for a in step.actions
                    if step.variable == name and self.session.stepping((feature, index), a)
                ]
                if not walking:
                    continue
                self.procedures.enter_step(feature, index)
                self.explore(
                    name,
                    Executed(
                        self.session.planned(walking[0]),
                        (feature, index),
                        name,
                        self.session.last,
                        True,
                    ),
                )
                return True
        return False

    def _plan(self, target: dict[str, Any]) -> Plan:
        """The belief's plan to ``target``, remembered while the belief and its state stay the
        same: the search is deterministic, and on a read model the loop asks the same question
        several times (the whole goal, then goal by goal) — the costly answer is a search that
        fails after exploring everything."""
        compiled, state = self.session.belief.compiled, self.session.belief.state
        if self._plans_on is not compiled:
            self._plans_on, self._plans = compiled, {}
        key = (state, tuple(sorted((n, repr(v)) for n, v in target.items())))
        known = self._plans.get(key)
        if known is None:
            try:
                known = self._programmes_first(
                    plan(compiled, state, target, self.config.plan_budget, self.config.plan_work),
                    target,
                )
            except Unreachable as exc:
                known = exc
            self._plans[key] = known
        if isinstance(known, Unreachable):
            raise known.again()
        return known

    def _programmes_first(self, found: Plan, target: dict[str, Any]) -> Plan:
        """Among plans of the same length, the one that selects the programmes first.

        Why: a programme change that resets other settings is what a reader of a manual misses
        most easily, and nothing on the display shows it happen; a plan that sets a delay and
        then turns the programme dial succeeds on the belief and fails on the appliance. Setting
        the programmes first costs nothing when the lengths tie, and is as sound either way.
        """
        model = self.session.belief.model
        parents = {v.depends_on for v in model.variables.values() if v.depends_on} & set(target)
        macros = found.macro_actions
        last = max((i for i, m in enumerate(macros) if parents & set(m.expect)), default=0)
        if not any(set(m.expect) & (set(target) - parents) for m in macros[:last]):
            return found
        compiled, budget = self.session.belief.compiled, self.config.plan_budget
        work = self.config.plan_work
        try:
            state: State | None = self.session.belief.state
            head = plan(compiled, state, {n: target[n] for n in parents}, budget, work, len(found))
            if not head.actions:  # the programmes hold: the rest is the search just made
                return found
            for action in head.actions:
                assert state is not None
                state = compiled.apply(state, compiled.action_index[action.name], action.seconds)
                if state is None:
                    return found
            if len(head) > len(found):
                return found
            # only a rest as short as the found plan's is of use: search no further
            rest = plan(compiled, state, target, budget, work, len(found) - len(head))
        except Unreachable:
            return found
        if len(head) + len(rest) != len(found):
            return found
        return Plan(found.goal, head.macro_actions + rest.macro_actions, found.expanded)

    def _start_anyway(self, name: str, value: Any, target: dict[str, Any]) -> Plan | None:
        """The rest of the goal holds, and the belief says starting undoes part of it (a
        reset the reader may have misread): start the belief's way, and let the display say
        whether the side effect is real (once per belief)."""
        rest = {n: v for n, v in target.items() if n != name}
        if any(self.session.belief.value(n) != v for n, v in rest.items()):
            return None  # the rest first
        try:
            found = self._plan({name: value})
        except Unreachable:
            return None
        if not {n for m in found.macro_actions for n in m.expect} & set(rest):
            return None  # it undoes nothing of the goal: not why there is no plan
        repairs = len(self.session.episode.repairs)  # once per belief
        if not self.session.budget.once("inspect", f"anyway:{name}:{repairs}"):
            return None
        return found

    def _progress(self, target: dict[str, Any]) -> bool:
        """Whether the belief has a plan that changes something towards ``target``."""
        try:
            return bool(self._plan(target).macro_actions)
        except Unreachable:
            return False

    def _undoes(self, others: dict[str, Any], name: str) -> bool:
        """Whether the belief's plan to ``others`` changes run state ``name`` on the way
        (False when ``name`` is empty: nothing to keep)."""
        if not name:
            return False
        try:
            found = self._plan(others)
        except Unreachable:
            return False
        return any(name in m.expect for m in found.macro_actions)

    def _plannable(self, target: dict[str, Any]) -> bool:
        try:
            self._plan(target)
        except Unreachable:
            return False
        return True

    # --- checking ----------------------------------------------------------------------------

    def check(self, macro: MacroAction, executed: list[Executed]) -> bool:
        """Compare what the display showed with what the belief predicted, press by press;
        repair on a mismatch. True when all was as predicted (the rest of the plan holds)."""
        if not self.config.closed_loop:
            return True
        first = next((i for i, e in enumerate(executed) if e.surprises or e.refused), None)
        if first is None:
            self.session.episode.log("check", "ok", expected=dict(macro.expect))
            self.session.budget.works("value", {e.variable for e in executed if e.variable})
            self.session.budget.works("procedure", {macro.feature})
            outside = self.goal()[1]
            return not (outside and self._look_at(outside))
        done = executed[first]
        self.session.episode.log(
            "check",
            "mismatch",
            expected={n: p for n, (p, _) in done.surprises.items()},
            values={
                n: "(unreadable)" if o is UNREADABLE else o for n, (_, o) in done.surprises.items()
            },
        )
        if not done.refused and self.displays.no_lamp(done):
            pass  # plan again, reading the setting on its own screen only
        elif not done.refused and self.splitter.split(done):
            pass  # plan again with the procedure the key really starts
        elif (
            not done.refused
            and (feature := self.splitter.misentered(done)) is not None
            and self.procedures.find_entry(feature)
        ):
            pass  # the procedure lacked its entry key: found
        elif (
            not done.refused
            and self.procedures.plausibly_moved(done)
            and (self.procedures.move_key(done))
        ):
            pass  # plan again with the key where it belongs
        elif not done.refused and self._shown_otherwise(done):
            assert done.variable is not None and done.pointer is not None
            # the key is the setting's own, and the screen that came up belongs to a setting
            # no step of which has this key: more likely the belief prints the setting wrong
            if self.session.stepping(done.pointer, done.action.name):
                self.explore(done.variable, done)
            else:
                self._learn_display(done.variable, executed[: first + 1])
        elif done.refused or self._wrong_setting(done):
            self.procedures.repair_procedure(executed[first:])
            name = self.session.step_variable(self.session.belief.pointer())
            key = self.explorer.stepping_key(name) if name else None
            if (
                name is not None
                and key is not None
                and self.session.shown(name)
                not in (
                    MISSING,
                    self.session.belief.value(name),
                )
            ):
                self.explore(name, key)  # the probe showed a value the belief cannot hold
        else:
            name = done.variable if done.variable in done.surprises else next(iter(done.surprises))
            predicted, observed = done.surprises[name]
            if observed is UNREADABLE and self._learn_display(name, executed[: first + 1]):
                pass  # read again and plan again with the repaired display rules
            else:
                self.repair_value(name, predicted, observed, executed, first)
        outside = self.goal()[1]  # a repair may have taught the belief the goal value
        self._look_at(outside)
        return False

    def _shown_otherwise(self, done: Executed) -> bool:
        """The press of the belief's setting's own key brought up the screen of another setting
        whose steps do not have that key (or that shows the very value predicted), and the
        display changed: the belief's display rules for its setting may be wrong (once)."""
        seen = done.seen
        name = done.variable
        if seen is None or name is None or done.pointer is None or done.unchanged:
            return False
        others = {v for kind, v in seen.screens if kind == "focus"}
        if not others or seen.showing(name):
            return False
        effect = self.session.effect(done.pointer, done.action.name)
        if not self.session.stepping(done.pointer, done.action.name) and effect != "digit":
            return False
        model = self.session.belief.model
        printed = display_value(model.variables[name], done.predicted)
        if not (len(printed) >= 2 and printed in seen.text) and any(
            done.action.name in step.actions
            for steps in model.features.values()
            for step in steps
            if step.variable in others
        ):
            return False  # the other setting's own key, and not the value predicted either
        return self.session.budget.once("template", f"suspect:{name}")

    def _wrong_setting(self, done: Executed) -> bool:
        """The press brought up another setting than the belief's step adjusts (or left the
        display as it was: a key ignored without a sign)."""
        if done.variable is None:
            return False
        seen = done.seen or Seen()
        if not seen.showing(done.variable) and not seen.unknown:
            return True
        if done.surprises.get(done.variable, (None, 0))[1] is not None:
            return False
        if done.unchanged:
            return True
        shown = seen.shown()
        return bool(shown - set(self.session.belief.model.display.indicators) - {done.variable})

    def _learn_display(self, name: str, executed: list[Executed]) -> bool:
        """The display showed text the belief cannot read where it expected ``name``: learn
        how the display prints it from the texts of the presses that adjusted it."""
        unread = [
            e
            for e in executed
            if e.variable == name
            and e.seen is not None
            and e.seen.text.strip()
            and (e.seen.unknown or not e.seen.showing(name))
        ]
        if not unread:
            return False
        texts = [e.feedback.text for e in unread]
        if not self.displays.learn(name, texts, believed=unread[-1].predicted):
            return False
        value = self.displays.read(name, unread[-1].feedback.text)
        if value is not None:
            self.session.belief.set_value(name, value)
        self.session.reread()
        return True

    def _look_at(self, outside: dict[str, Any]) -> bool:
        focused = {
            name: raw
            for name, raw in outside.items()
            if self.session.shown(name) is not MISSING and name not in self.session.explored
        }
        if focused:
            self.explore_outside(focused)
        return bool(focused)

    def repair_value(
        self, name: str, predicted: Any, observed: Any, executed: list[Executed], upto: int
    ) -> None:
        """The display showed ``observed`` for ``name`` where the belief predicted otherwise."""
        self.session.again(
            "value",
            name,
            f"{name} keeps showing values the model does not predict (last: "
            f"{observed!r}, expected {predicted!r})",
        )
        if self.procedures.independent(name, executed[upto], observed):
            return
        adjusting = [e for e in executed[: upto + 1] if e.variable == name and e.believed_accepted]
        if not adjusting:  # changed as a side effect: the step that did it says so now
            self.procedures.learn_side_effect(name, executed[upto], observed)
            return
        last = adjusting[-1]
        assert last.pointer is not None
        unchanged = observed == self.values_before.get(name)
        first = next((e for e in executed[: upto + 1] if e.surprises), None)
        if (
            first is not None
            and first.variable == name
            and self.explorer.learn_on_entry(name, first)
        ):
            return
        if unchanged and self.procedures.absorbed(adjusting[0]):
            return
        if first is not None and first.unchanged and self.guards.learn(first):
            return  # a key ignored without a sign: a guard the belief lacked (now learnt)
        effect = self.session.effect(last.pointer, last.action.name)
        if self.session.stepping(last.pointer, last.action.name):
            self.explore(name, last, self.explorer.history(name, last, executed))
        elif isinstance(effect, GoTo) and observed is not None and not unchanged:
            self.explorer.learn_goto(name, last, observed)
        elif effect == "digit" and observed is not None:
            if self.explorer.learn_entry_format(name, last, observed, unchanged):
                return
            shown = [e.observed(name) for e in executed[upto:]]
            self.explorer.widen(name, [observed, *(v for v in shown if v not in (MISSING, None))])
            self.settle_contradictions({name: None})

    def settle_contradictions(self, names: dict[str, Any]) -> bool:
        """A setting last shown with a value the belief cannot hold must not count as done:
        a keypad setting learns the value, another is walked again once (True: plan again);
        otherwise the run gives up."""
        settled = False
        for name in [n for n in self.session.contradicted if n in names]:
            value = self.session.contradicted.pop(name)
            spec = self.session.belief.model.variables[name]
            if getattr(spec, "entry", None) is not None:
                self.explorer.widen(name, [value])
                if self.session.belief.set_value(name, value):
                    settled = True
                    continue
            elif self.session.budget.once("inspect", f"contradicted:{name}"):
                # walk it again where it is now (another programme may have other values)
                key = self.explorer.stepping_key(name)
                if key is not None:
                    self.explore(name, key)
                    settled = True
                    continue
                if self.inspect(name):
                    settled = True
                    continue
            raise Stop(f"the display showed {name}={value!r}, which the belief cannot hold")
        return settled

    def explore_outside(self, outside: dict[str, Any]) -> None:
        """Look at a variable whose goal value the belief lacks: explore it, or for a keypad
        setting, allow the value and let the next check say whether it exists."""
        for name, raw in outside.items():
            spec = self.session.belief.model.variables[name]
            if getattr(spec, "entry", None) is not None:
                self.session.explored.add(name)
                value = loose(spec, raw)
                if value is not None:
                    self.explorer.widen(name, [value])
                continue
            key = self.explorer.stepping_key(name)
            if key is not None:
                self.explore(name, key)
            elif self.session.step_variable(self.session.belief.pointer()) == name:
                self.session.explored.add(
                    name
                )  # its setting is up, and no key walks it: seen it all


RUN_STATES = ("running", "heating", "dispensing", "status", "start")


def _starts(name: str) -> bool:
    """A goal setting that starts the appliance (left for last while settings are missing)."""
    return any(word in name for word in RUN_STATES)


def _locks(name: str) -> bool:
    """A goal setting that locks the panel (a child lock): the belief may lack its guard."""
    return "lock" in name.split("_")


def _outside_text(outside: dict[str, Any]) -> str:
    return "; ".join(
        f"{name}={raw!r} is not a value the model knows" for name, raw in outside.items()
    )


def run_agent(config: AgentConfig, context: TaskContext, env: Environment) -> Episode:
    """One episode of ApBot (or an ablation of it) on ``env``."""
    return ClosedLoop(config, context, env).run()
