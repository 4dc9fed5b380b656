"""Checks that need the machine itself: a guard must be liftable wherever it can take hold.

The model checker (``apbot.model.validate``) judges a model from its parts; some mistakes only
show when the model runs. A child lock whose one allowed key sets it locked again passes the
part-wise test ("an allowed action changes the lock") yet locks the appliance for good. Here a
breadth-first search runs the compiled model from its initial state and, for every guard,
looks for a reachable state where the guard holds and from which no sequence of actions
reaches a state where it does not.

The search runs over states reduced to what decides the guards — the variables guards read,
the programmes selecting their domains, what conditional effects on them read, the feature
pointer, and the keypad buffer while it types one of those variables — which is exact:
nothing else influences how those evolve. It stops after :data:`MAX_GUARD_STATES` such
states; past that bound a state not yet expanded counts as one that may lift every guard,
so an error is only ever reported when it is proved.

:func:`check_model` is the whole checker: the model's own checks, then these.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Hashable
from operator import itemgetter

from apbot.model.problems import Problem
from apbot.model.schema import ApplianceModel
from apbot.model.validate import check_model as check_parts
from apbot.sim.compiled import DIGIT, CompiledModel, GuardInfo, State, compiled_model

MAX_GUARD_STATES = 20_000  # reduced states searched per model (a bundled model needs <= 158)


def check_model(model: ApplianceModel) -> list[Problem]:
    """Every problem of the model: :func:`apbot.model.validate.check_model`, then — when the
    model has no error — the checks that run it (:func:`guard_problems`)."""
    problems = check_parts(model)
    if any(p.severity == "error" for p in problems):
        return problems
    return problems + guard_problems(model)


def guard_key(compiled: CompiledModel, variables: set[int]) -> Callable[[State], Hashable]:
    """A state reduced to ``variables`` (closed under the programmes selecting their domains
    and what conditional effects on them read: :meth:`CompiledModel.influencers`),
    the feature pointer, and the keypad buffer while it types one of them."""
    kept = compiled.influencers(variables)
    order = sorted(kept)
    typing = tuple(
        step.variable in kept and any(e[0] == DIGIT for e in step.effects.values())
        for step in compiled.steps
    )
    pick = itemgetter(*order) if order else (lambda values: ())
    memory = compiled.memory_of(kept)

    def key(state: State) -> Hashable:
        step = state.step
        kept_values = tuple(state.memory[s] for s in memory)
        return (
            pick(state.values),
            step,
            state.buffer if step >= 0 and typing[step] else "",
            kept_values,
        )

    return key


def guard_problems(model: ApplianceModel, max_states: int = MAX_GUARD_STATES) -> list[Problem]:
    """A ``guard`` error for each guard that some reachable state holds for good."""
    compiled = compiled_model(model)
    if not compiled.guards:
        return []
    key = guard_key(compiled, {v for g in compiled.guards for v, _ in g.conditions})
    start = compiled.initial_state()
    states: dict[Hashable, State] = {key(start): start}
    paths: dict[Hashable, tuple[int, ...]] = {key(start): ()}
    predecessors: dict[Hashable, list[Hashable]] = {key(start): []}
    expanded: set[Hashable] = set()
    queue: deque[Hashable] = deque([key(start)])
    actions = range(len(compiled.action_names))
    while queue and len(expanded) < max_states:
        node = queue.popleft()
        expanded.add(node)
        for action in actions:
            after = compiled.apply(states[node], action)
            if after is None:
                continue
            k = key(after)
            if k not in states:
                states[k] = after
                paths[k] = (*paths[node], action)
                predecessors[k] = []
                queue.append(k)
            predecessors[k].append(node)
    problems = []
    for g, guard in enumerate(compiled.guards):
        # states that can reach a state where the guard is lifted (or one not expanded yet)
        free = [k for k, s in states.items() if not _holds(guard, s) or k not in expanded]
        can_lift = set(free)
        pending = deque(free)
        while pending:
            for previous in predecessors[pending.popleft()]:
                if previous not in can_lift:
                    can_lift.add(previous)
                    pending.append(previous)
        stuck = [k for k in states if k not in can_lift]
        if stuck:
            first = min(stuck, key=lambda k: len(paths[k]))
            problems.append(_stuck(compiled, g, states[first], paths[first], len(states)))
    return problems


def _holds(guard: GuardInfo, state: State) -> bool:
    return all(state.values[v] in ok for v, ok in guard.conditions)


def _stuck(
    compiled: CompiledModel, g: int, state: State, path: tuple[int, ...], searched: int
) -> Problem:
    guard = compiled.guards[g]
    spec = compiled.model.guards[g]
    name = f"guard {spec.name!r}" if spec.name else f"guard {g}"
    values = ", ".join(
        f"{compiled.vars[v].name} is {compiled.value(state, compiled.vars[v].name)}"
        for v, _ in guard.conditions
    )
    via = " → ".join(compiled.action_names[a] for a in path) or "the start"
    allowed = ", ".join(sorted(spec.only)) or "none"
    return Problem(
        ("guards", g),
        f"{name} holds for good: after {via} ({values}) no sequence of actions lifts it "
        f"(allowed: {allowed}; {searched} states searched); let an allowed action release it",
        "guard",
    )
