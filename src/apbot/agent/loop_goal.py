"""The loop's goal and plan: the goal split by what the belief has, a value near a missing one
to plan to, the plan to a target (or progress and probes when there is none), and the walk of a
setting the belief cannot reach. Apart from :mod:`apbot.agent.loop`, which runs the episode's
steps, because these decide where the next steps go; a part of
:class:`apbot.agent.loop.ClosedLoop`."""

from __future__ import annotations

from typing import Any

from apbot.agent.claims import Claims, starts_appliance
from apbot.agent.discovery import VariableFinder
from apbot.agent.locks import lit_not_dark
from apbot.agent.planning import BeliefPlans
from apbot.agent.quantities import loose, magnitude
from apbot.agent.session import MISSING, Executed, Stop
from apbot.model.domain import ValueProblem, all_values, build_domain, normalise
from apbot.model.goal import GoalError
from apbot.model.schema import DiscreteVariable
from apbot.model.validate import check_goal
from apbot.plan.plan import Plan, Unreachable


class GoalPlanning(Claims):
    """The goal and the plan to it (a part of :class:`apbot.agent.loop.ClosedLoop`)."""

    finder: VariableFinder
    plans: BeliefPlans
    missing: dict[str, Any]  # goal settings the belief lacks and has not found
    finding: int  # the finder's attempt: once at the start, once with the rest set

    def goal(self) -> tuple[dict[str, Any], dict[str, Any]]:
        """The goal split into values the belief has and values it does not."""
        inside: dict[str, Any] = {}
        outside: dict[str, Any] = {}
        variables = self.session.belief.model.variables
        self.missing = {}
        for name, raw in self.context.goal.items():
            if name in self.set_aside:
                continue  # given up on: the rest is set without it
            if name in self.finder.misread:
                continue  # what the reader took a key to set, which a walk of it showed wrong
            if name not in variables:
                if name in self.unfound:
                    continue
                if not self.finder.find(name, raw, attempt=self.finding):
                    if self.finding >= 2:
                        # the words may name a setting the panel does not have (or not as
                        # read): the rest of the goal may still be all that was asked, so
                        # set it, and never claim the whole goal
                        self.unfound[name] = raw
                        self.session.episode.log(
                            "explore",
                            f"the goal names {name!r}, which the model does not have, and no "
                            "key the model gives no role shows it: setting the rest",
                        )
                        continue
                    self.missing[name] = raw  # look again once the rest is set
                    continue
                variables = self.session.belief.model.variables
            raw = self.session.renamed.get(name, {}).get(str(raw), raw)
            try:
                inside[name] = normalise(variables[name], raw)
            except ValueProblem as exc:
                if loose(variables[name], raw) is None:  # not even a value of that kind
                    raise Stop(f"goal {name}={raw!r}: {exc}") from None
                outside[name] = raw
        for name in set(inside) & self.finder.misread:  # found wrong after it was taken
            del inside[name]
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
            return self.plans.plan(target)
        except GoalError as exc:
            raise Stop(f"the goal does not fit the belief model: {exc}") from None
        except Unreachable as exc:
            if self.config.closed_loop and lit_not_dark(self.session):
                return self.make_plan(target)  # the panel is lit: it is not switched off
            if not self.config.closed_loop or exc.budget_hit:
                raise Stop(f"no plan on the belief model: {exc.reason}") from None
            reachable: dict[str, Any] = {}
            kept = ""  # a run state the appliance is in as asked: nothing may undo it
            # the goal variable that breaks planning (a run state last: it locks the rest)
            for name, value in sorted(target.items(), key=lambda item: starts_appliance(item[0])):
                if self.plans.plannable({**reachable, name: value}):
                    reachable[name] = value
                    continue
                if starts_appliance(name):
                    others = {n: v for n, v in target.items() if n != name}
                    # running as asked, a way to the rest that stops the cycle is no progress:
                    # starting again would undo it (a reset the start is believed to make,
                    # often read off a running display that only hides the setting)
                    kept = name if self.session.belief.value(name) == value else ""
                    if (
                        others
                        and not self.plans.undoes(others, kept)
                        and self.plans.progress(others)
                    ):
                        return self.plans.plan(others)  # a run state comes last: set the rest first
                    anyway = self.plans.start_anyway(name, value, target)
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
                        partial: Plan | None = self.plans.plan(reachable)
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

    def inspect(self, name: str) -> bool:
        """A goal setting the belief cannot reach: go through the procedure that adjusts it
        and walk its values, in case its keys do something else than believed. Once per case
        of a setting whose values depend on another (each hair type, programme, ... its own
        range): a walk in one case says nothing of another's values."""
        cases = self.session.belief.model.variables[name].cases or {}
        budget = self.session.budget
        if budget.spent_on("inspect", self._walk_key(name)) or not any(
            budget.once("inspect", f"{name} walk {n}") for n in range(len(cases) + 1)
        ):  # one walk per case at most, even when the believed case stays wrong
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
                # the case the walk showed it was in (the belief's may have been wrong)
                self.session.budget.once("inspect", self._walk_key(name))
                return True
        return False

    def _walk_key(self, name: str) -> str:
        """What one walk of ``name`` covers: the setting, in the case it is in now."""
        case = self.session.case(name)
        return name if case is None else f"{name} when {case}"
