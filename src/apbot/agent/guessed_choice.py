"""A programme the goal asks for that the belief only guesses the appliance starts in.

A panel with one key per programme (WASH, DRY, STERILISE+DRY) lights the programme's name when
that key is pressed; until then the display may show nothing of it (HELLO, then RUN). Manuals
say which programme each key chooses far more often than which one the appliance starts in:
the reader then takes the first programme listed — a guess. When the goal asks for exactly that
guess, the plan presses nothing for it, no screen ever shows it, and a claim of success rests
on the guess alone. Pressing the programme's own key costs one press and is what a person
would do; the belief forgets the guess, so the plan chooses the programme (first, with the
programmes) and the check sees it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from apbot.model.display import can_show
from apbot.model.domain import ValueProblem, normalise
from apbot.model.effects import default_effect
from apbot.model.schema import ApplianceModel, DiscreteVariable, GoTo

if TYPE_CHECKING:
    from apbot.agent.session import Session


def direct_key(model: ApplianceModel, name: str, value: Any) -> str | None:
    """A key whose step goes straight to ``value`` of ``name`` (a programme's own key)."""
    for steps in model.features.values():
        for step in steps:
            if step.variable != name:
                continue
            for action in step.actions:
                effect = default_effect(step, action, model)
                if isinstance(effect, GoTo) and str(effect.to) == str(value):
                    return action
    return None


def guessed(model: ApplianceModel, name: str) -> bool:
    """Whether the belief's start value of ``name`` is the reader's guess: a choice among
    several named values with no start stated, that no other setting depends on."""
    spec = model.variables.get(name)
    if not isinstance(spec, DiscreteVariable) or len(spec.values or ()) < 3:
        return False
    if spec.initial is not None or spec.cases or spec.depends_on:
        return False
    return not any(v.depends_on == name for v in model.variables.values())


def forget_guessed_choices(session: Session, goal: dict[str, Any]) -> list[str]:
    """At the start of an episode: each goal setting whose asked value is the belief's guessed
    start, never shown, with a key of its own that chooses it and a screen that shows it, is
    believed elsewhere (and blind) so that the plan presses that key. The names forgotten."""
    model = session.belief.model
    forgotten = []
    for name, raw in goal.items():
        if name not in model.variables or name in session.ever_seen or not guessed(model, name):
            continue
        try:
            asked = normalise(model.variables[name], raw)
        except ValueProblem:
            continue
        held = session.belief.value(name)
        if asked != held or direct_key(model, name, held) is None or not can_show(model, name):
            continue
        other = next((v for v in session.domain_values(name) if v != held), None)
        if other is None or not session.belief.set_value(name, other):
            continue
        session.blind.add(name)  # a stand-in, not seen: the key's screen is no surprise
        session.episode.log("repair", f"{name}={held!r} is only a guess of the start: to be chosen")
        forgotten.append(name)
    return forgotten
