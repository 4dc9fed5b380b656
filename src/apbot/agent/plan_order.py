"""The order of a plan's macro actions, chosen by the manual rather than by the action list.

The planner's search breaks ties between plans of one length by the order it meets the
actions, which is the order the environment happens to list them in: the same belief, its
actions listed another way, sets the temperature before starting on one robot and after on
another. Making the search itself order-free costs its pruning of tied paths (tie15: held out
57 → 44), so the plan found is reordered afterwards instead: among the orders of its own macro
actions that the belief accepts — every action allowed, every macro showing what it showed in
the found order, the goal reached — the one that makes the choices that change several settings
at once (a programme and the defaults it puts back) before those that change one (what a choice
resets is what a reader misses most easily), and otherwise follows the manual's order of the
settings (the belief's variables, read in the manual's order). A key that starts or stops the
appliance stays where the search put it: moving the start last cost more than it won (a keep-warm
that a start resets, a timer refused while running that the explorer then misread: newcats 577
→ 569), so only the settings on either side of it are reordered. The order of the settings
then no longer depends on how the actions are listed.
"""

from __future__ import annotations

from collections.abc import Sequence

from apbot.agent.keys import RUN_WORDS
from apbot.plan.goals import CompiledGoal
from apbot.plan.plan import MacroAction, Plan
from apbot.sim.compiled import CompiledModel, State

__all__ = ["in_manual_order"]


def in_manual_order(compiled: CompiledModel, start: State, found: Plan) -> Plan:
    """``found`` with its macro actions in the manual's order where the belief allows it.

    Greedy: each place takes the earliest (by :func:`_rank`) remaining macro after which the
    rest, in the found order, still replays; the found order always does, so the result is a
    plan of the same actions that the belief accepts."""
    macros = found.macro_actions
    if len(macros) < 2:
        return found
    goal = CompiledGoal.build(compiled, found.goal)
    ranks = {id(m): _rank(compiled, m, i) for i, m in enumerate(macros)}
    remaining = list(macros)
    state = start
    ordered: list[MacroAction] = []
    while remaining:
        # a macro that starts or stops the appliance stays where the search put it: the
        # settings before it are reordered among themselves, those after it likewise
        anchor = next((i for i, m in enumerate(remaining) if _runs(m)), len(remaining))
        segment = remaining[: max(anchor, 1)]
        for macro in sorted(segment, key=lambda m: ranks[id(m)]):
            rest = [m for m in remaining if m is not macro]
            after = _replay(compiled, state, [macro])
            if after is None:
                continue
            end = _replay(compiled, after, rest)
            if end is not None and goal.holds(compiled, end):
                ordered.append(macro)
                remaining = rest
                state = after
                break
        else:  # cannot happen (the found order replays); keep the plan as found
            return found
    if all(a is b for a, b in zip(ordered, macros, strict=True)):
        return found
    return Plan(found.goal, tuple(ordered), found.expanded, found.seconds, found.generated)


def _runs(macro: MacroAction) -> bool:
    """Whether the macro starts or stops the appliance (it changes a run state)."""
    return any(any(w in n for w in RUN_WORDS) for n in macro.expect)


def _rank(compiled: CompiledModel, macro: MacroAction, index: int) -> tuple[int, int, int]:
    """A choice that changes other settings too (a programme putting back its defaults)
    before those that change one; then the manual's order of the first setting the macro
    shows; the found order only between macros alike in both."""
    names = list(compiled.model.variables)
    shown = [names.index(n) for n in macro.expect if n in compiled.model.variables]
    return (int(len(shown) < 2), min(shown, default=len(names)), index)


def _replay(compiled: CompiledModel, state: State, macros: Sequence[MacroAction]) -> State | None:
    """The state after ``macros``, or None when the belief refuses an action or a macro does
    not show what it showed in the found order (the agent checks each against the display)."""
    current: State | None = state
    for macro in macros:
        for action in macro.actions:
            assert current is not None
            current = compiled.apply(current, compiled.action_index[action.name], action.seconds)
            if current is None:
                return None
        assert current is not None
        if any(compiled.value(current, n) != v for n, v in macro.expect.items()):
            return None
    return current
