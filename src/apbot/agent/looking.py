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
from typing import TYPE_CHECKING

from apbot.agent.case_starts import learn_start
from apbot.agent.perception import MISSING
from apbot.model.domain import ValueProblem, normalise
from apbot.model.effects import default_effect
from apbot.model.schema import ApplianceModel, GoTo
from apbot.sim.compiled import CompiledModel, State

if TYPE_CHECKING:
    from apbot.agent.session import Session

MAX_PRESSES = 3  # a look longer than this is not a look
MAX_STATES = 4_000  # states searched for one look


def route_to_screen(
    compiled: CompiledModel,
    state: State,
    name: str,
    keep: Collection[str],
    actions: Collection[str],
    still: bool = False,
) -> list[str] | None:
    """The fewest presses of ``actions`` (at most :data:`MAX_PRESSES`) after which the belief
    shows ``name`` on a lit display and every variable of ``keep`` but ``name`` is unchanged
    (``still``, or a state a guard watches: ``name`` too); None when there is none within the
    search's bounds.

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
    # a state a guard watches (running, a lock, power) never moves for a look: stopping a
    # cycle to see that it runs undoes it, and a STOP may clear the settings as well
    still = still or any(name in guard.when for guard in model.guards)
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
                moved = after.values[target] != state.values[target]
                if compiled.hiding_guard(after) is None and compiled.focus(after) == target:
                    if not (still and moved):
                        return [*path, action]
                    continue
                if moved:
                    continue  # only the last press may move the setting itself
                seen.add(after)
                following.append((after, [*path, action]))
                if len(seen) >= MAX_STATES:
                    return None
        frontier = following
    return None


def glance(session: Session, names: Collection[str]) -> bool:
    """Look at one setting of ``names`` the display never showed, or showed only before a
    press the belief did not foresee (:meth:`Session.unverified`), where a route shows it
    changing nothing else (once per setting); True when it pressed. A setting shown before is
    looked at only where the look leaves it as it is: moving it would cost a walk round its
    values (and a programme's resets) to settle a doubt; a value never shown is a guess worth
    that step. Not a setting typed on a keypad: its entry key starts a new entry, which may
    clear what was typed; one whose believed value the goal asks for is typed again instead
    (:func:`_retype`). A never-shown setting behind a dark panel may switch the panel
    on first. Nor through a key that selects a value or sets others
    (:func:`selecting`): choosing the programme already chosen resets its settings on many
    appliances. Where no route shows it, the belief is all there is."""
    model = session.belief.model
    for name in session.unverified(set(names)):
        if typed(model, name):
            if _retype(session, name):
                return True
            continue
        if not _may_glance(session, name):
            continue
        compiled, state = session.belief.compiled, session.belief.state
        keep = set(model.variables)
        hiding = compiled.hiding_guard(state)
        if hiding is not None and name not in session.ever_seen:
            # a dark panel shows nothing: a guess is worth switching it on (the goal's setting
            # cannot be set on a dark panel either)
            keep -= {compiled.vars[v].name for v, _ in hiding.conditions}
        route = route_to_screen(
            compiled,
            state,
            name,
            keep,
            sorted(session.offered & set(model.actions) - selecting(model)),
            still=name in session.ever_seen,
        )
        if route is None:
            continue
        before = session.belief.value(name)
        done = None
        for action in route:
            done = session.press(session.planned(action), exploring=True)
        learn_start(session, name, before, done)
        if session.shown(name) is MISSING:
            # the look may have moved it, and the display did not say to what
            session.unread.add(name)
        return True
    return False


def _may_glance(session: Session, name: str) -> bool:
    """Once per setting, and once more when a programme chosen after the display showed it put
    it in doubt (:attr:`Session.reprogrammed`): the first look may have been spent before that
    choice, which may have brought the setting back to the programme's default — even to the
    very value the belief holds."""
    if session.budget.once("inspect", f"glance:{name}"):
        return True
    return name in session.reprogrammed and session.budget.once("inspect", f"reglance:{name}")


def _retype(session: Session, name: str) -> bool:
    """A keypad setting the display never showed holds a default start value (the model
    states none: the first of its range), or it was shown only before a press that may have
    reset it, and the goal asks for what the belief holds: typing the value is the only way
    to know (a few presses, once). The belief forgets the value (takes another of the
    domain), so the next plan types the asked one and the check sees it. True when it did."""
    held = session.belief.value(name)
    raw = session.context.goal.get(name)
    try:
        asked = normalise(session.belief.model.variables[name], raw) if raw is not None else None
    except ValueProblem:
        return False
    if asked is None or asked != held:
        return False  # not asked, or the plan types it anyway
    spec = session.belief.model.variables[name]
    if name in session.ever_seen and name not in session.rechosen:
        return False  # a doubt of another kind (a programme chosen): a look is not worth it
    if name not in session.ever_seen and (
        getattr(spec, "initial", None) is not None or getattr(spec, "cases", None)
    ):
        return False  # the model states where it starts: no mere default to doubt
    compiled, state = session.belief.compiled, session.belief.state
    if any(
        not g.hide and all(state.values[v] in ok for v, ok in g.conditions) for g in compiled.guards
    ):
        return False  # it runs, or the panel is locked: typing would undo that first
    if not session.budget.once("inspect", f"retype:{name}"):
        return False
    other = next((v for v in session.domain_values(name) if v != held), None)
    if other is None or not session.belief.set_value(name, other):
        return False
    session.blind.add(name)  # a stand-in, not seen: a screen showing the value is no surprise
    session.episode.log("repair", f"{name}={held!r} was never shown: to be typed")
    return True


def typed(model: ApplianceModel, name: str) -> bool:
    """Whether a step of the model sets ``name`` with keypad digits."""
    return any(
        default_effect(step, action, model) == "digit"
        for steps in model.features.values()
        for step in steps
        if step.variable == name
        for action in step.actions
    )


def selecting(model: ApplianceModel) -> set[str]:
    """Keys that go to a value (a programme key) or set or reset other settings as they do."""
    found = set()
    for steps in model.features.values():
        for step in steps:
            for action in step.actions:
                effect = default_effect(step, action, model)
                if isinstance(effect, GoTo) or step.set or step.reset:
                    found.add(action)
    return found
