"""The belief's plans, remembered while the belief and its state stay the same.

The loop asks the planner the same question several times when a goal is out of reach (the
whole goal, then goal by goal); the search is deterministic, and on a read model the costly
answer is a search that fails after exploring everything. Among plans of the same length the
one that selects the programmes first is taken (see :meth:`BeliefPlans.programmes_first`),
and otherwise the one in the manual's order, whatever the order of the actions
(:mod:`apbot.agent.plan_order`).
"""

from __future__ import annotations

import itertools
from collections.abc import Hashable
from typing import Any

from apbot.agent.executed import AgentConfig
from apbot.agent.plan_order import in_manual_order
from apbot.agent.programmes import programmes, selectors
from apbot.agent.session import Session
from apbot.plan.plan import MacroAction, Plan, Unreachable, plan
from apbot.sim.compiled import CompiledModel, State

__all__ = ["BeliefPlans"]


class BeliefPlans:
    """Plans on the session's belief, each search made once per belief, state and target."""

    def __init__(self, session: Session, config: AgentConfig) -> None:
        self.session = session
        self.config = config
        self._on: CompiledModel | None = None  # the belief the remembered plans are on
        self._known: dict[Hashable, Plan | Unreachable] = {}

    def plan(self, target: dict[str, Any]) -> Plan:
        """The belief's plan to ``target``, remembered while the belief and its state stay the
        same: the search is deterministic, and on a read model the loop asks the same question
        several times (the whole goal, then goal by goal) — the costly answer is a search that
        fails after exploring everything."""
        compiled, state = self.session.belief.compiled, self.session.belief.state
        if self._on is not compiled:
            self._on, self._known = compiled, {}
        key = (state, tuple(sorted((n, repr(v)) for n, v in target.items())))
        known = self._known.get(key)
        if known is None:
            try:
                found = plan(
                    compiled, state, target, self.config.plan_budget, self.config.plan_work
                )
                known = self.programmes_first(in_manual_order(compiled, state, found), target)
            except Unreachable as exc:
                known = exc
            self._known[key] = known
        if isinstance(known, Unreachable):
            raise known.again()
        return known

    def programmes_first(self, found: Plan, target: dict[str, Any]) -> Plan:
        """Among plans of the same length, the one that selects the programmes first.

        Why: a programme change that resets other settings is what a reader of a manual misses
        most easily, and nothing on the display shows it happen; a plan that sets a delay and
        then turns the programme dial succeeds on the belief and fails on the appliance. Setting
        the programmes first costs nothing when the lengths tie, and is as sound either way.
        A programme is one the goal names or one the plan chooses on its way (a menu chosen
        for the texture the goal asks, which starts there): see :func:`programmes`.
        """
        chosen = _chosen_programmes(self.session, found, target)
        parents = set(chosen)
        macros = found.macro_actions
        last = max((i for i, m in enumerate(macros) if parents & set(m.expect)), default=0)
        parts = parents & selectors(self.session.belief.model)
        part = max((i for i, m in enumerate(macros) if parts & set(m.expect)), default=0)
        if not any(set(m.expect) & (set(target) - parents) for m in macros[:last]) and not any(
            set(m.expect) & (parents - parts) for m in macros[:part]
        ):
            return found
        compiled, budget = self.session.belief.compiled, self.config.plan_budget
        work = self.config.plan_work
        # what the plan does before it sets a goal value or a programme (switching the panel
        # on, which may clear the delay on the way) stays first: a programme dial turned on a
        # dark panel shows nothing
        now = self.session.belief.values()
        lead = list(itertools.takewhile(lambda m: not _sets(m, target, parents, now), macros))
        state: State | None = self.session.belief.state
        for action in [a for m in lead for a in m.actions]:
            assert state is not None
            state = compiled.apply(state, compiled.action_index[action.name], action.seconds)
            if state is None:
                return found
        length = len(found) - sum(len(m.actions) for m in lead)
        # the part chosen first (the right bowl), then its programme (its mode): each layer
        # holds the ones before it
        first = {n: v for n, v in chosen.items() if n in parts}
        layers = [first, chosen] if first and len(first) < len(chosen) else [chosen]
        heads: list[MacroAction] = []
        used = 0
        try:
            for layer in layers:
                head = plan(compiled, state, layer, budget, work, length - used)
                for action in head.actions:
                    assert state is not None
                    state = compiled.apply(
                        state, compiled.action_index[action.name], action.seconds
                    )
                    if state is None:
                        return found
                heads += head.macro_actions
                used += len(head)
            if not heads:  # the programmes hold: the rest is the search just made
                return found
            if used > length:
                return found
            # only a rest as short as the found plan's is of use: search no further
            rest = plan(compiled, state, target, budget, work, length - used)
        except Unreachable:
            return found
        if used + len(rest) != length:
            return found
        macro_actions = (*lead, *heads, *rest.macro_actions)
        return Plan(found.goal, macro_actions, found.expanded)

    def start_anyway(self, name: str, value: Any, target: dict[str, Any]) -> Plan | None:
        """The rest of the goal holds, and the belief says starting undoes part of it (a
        reset the reader may have misread): start the belief's way, and let the display say
        whether the side effect is real (once per belief)."""
        rest = {n: v for n, v in target.items() if n != name}
        if any(self.session.belief.value(n) != v for n, v in rest.items()):
            return None  # the rest first
        try:
            found = self.plan({name: value})
        except Unreachable:
            return None
        if not {n for m in found.macro_actions for n in m.expect} & set(rest):
            return None  # it undoes nothing of the goal: not why there is no plan
        repairs = len(self.session.episode.repairs)  # once per belief
        if not self.session.budget.once("inspect", f"anyway:{name}:{repairs}"):
            return None
        return found

    def progress(self, target: dict[str, Any]) -> bool:
        """Whether the belief has a plan that changes something towards ``target``."""
        try:
            return bool(self.plan(target).macro_actions)
        except Unreachable:
            return False

    def undoes(self, others: dict[str, Any], name: str) -> bool:
        """Whether the belief's plan to ``others`` changes run state ``name`` on the way
        (False when ``name`` is empty: nothing to keep)."""
        if not name:
            return False
        try:
            found = self.plan(others)
        except Unreachable:
            return False
        return any(name in m.expect for m in found.macro_actions)

    def plannable(self, target: dict[str, Any]) -> bool:
        try:
            self.plan(target)
        except Unreachable:
            return False
        return True


def _sets(
    macro: MacroAction, target: dict[str, Any], parents: set[str], now: dict[str, Any]
) -> bool:
    """Whether ``macro`` chooses a programme or brings a setting to its goal value (one it
    does not hold ``now``)."""
    return any(
        n in parents or (target.get(n, _NONE) == v and now.get(n, _NONE) != v)
        for n, v in macro.expect.items()
    )


_NONE = object()


def _chosen_programmes(session: Session, found: Plan, target: dict[str, Any]) -> dict[str, Any]:
    """The programmes the goal names, and those the plan changes on its way, each with the
    value the plan leaves it at."""
    compiled = session.belief.compiled
    named = programmes(session.belief.model)
    chosen = {n: target[n] for n in named & set(target)}
    state: State | None = session.belief.state
    for action in found.actions:
        assert state is not None
        state = compiled.apply(state, compiled.action_index[action.name], action.seconds)
        if state is None:
            return chosen
    start = session.belief.values()
    for name in sorted(named - set(target)):
        if name not in compiled.var_index or state is None:
            continue
        value = compiled.value(state, name)
        if value != start.get(name) and value is not None:
            chosen[name] = value
    return chosen
