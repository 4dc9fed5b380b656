"""A way to bring one setting onto the display without disturbing anything else.

Before it claims success the agent must see every goal setting the belief changed since the
display last showed it. Entering the setting's own step is not always a look: a dial shared by
two settings keeps adjusting the one chosen last, and a go-to key sets what it shows. A short
search on the belief finds the fewest presses after which the display shows the setting and
every other variable is as it was (a lock switched on on the way is no look); the setting itself
may move one step on the last press — the next plan puts it back.
"""

from __future__ import annotations

from collections.abc import Collection

from apbot.sim.compiled import CompiledModel, State

MAX_PRESSES = 3  # a look longer than this is not a look
MAX_STATES = 4_000  # states searched for one look


def route_to_screen(
    compiled: CompiledModel,
    state: State,
    name: str,
    keep: Collection[str],
    actions: Collection[str],
) -> list[str] | None:
    """The fewest presses of ``actions`` (at most :data:`MAX_PRESSES`) after which the belief
    shows ``name`` on a lit display and every variable of ``keep`` but ``name`` is unchanged;
    None when there is none within the search's bounds.

    >>> from apbot.examples import load_example
    >>> model = load_example("microwave_keypad")
    >>> compiled = CompiledModel(model)
    >>> route_to_screen(compiled, compiled.initial_state(), "power_level", [], model.actions)
    ['press_power_level']
    """
    if name not in compiled.var_index:
        return None
    target = compiled.var_index[name]
    kept = [compiled.var_index[n] for n in keep if n != name and n in compiled.var_index]
    model = compiled.model
    keys = [
        (compiled.action_index[a], a, model.actions[a].seconds)
        for a in actions
        if a in compiled.action_index and model.actions[a].skill != "wait"
    ]
    frontier: list[tuple[State, list[str]]] = [(state, [])]
    seen = {state}
    for _ in range(MAX_PRESSES):
        following: list[tuple[State, list[str]]] = []
        for current, path in frontier:
            for index, action, seconds in keys:
                after = compiled.apply(current, index, seconds)
                if after is None or after in seen:
                    continue
                if any(after.values[v] != state.values[v] for v in kept):
                    continue
                if compiled.hiding_guard(after) is None and compiled.focus(after) == target:
                    return [*path, action]
                if after.values[target] != state.values[target]:
                    continue  # only the last press may move the setting itself
                seen.add(after)
                following.append((after, [*path, action]))
                if len(seen) >= MAX_STATES:
                    return None
        frontier = following
    return None
