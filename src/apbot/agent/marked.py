"""A choice shown as only highlighted, not yet taken: ``SEL heavy`` after ``REFRESH``.

Many panels let a knob run through the choices and take one only when the knob is pushed (or
OK pressed); while turning, the display marks the candidate — a word in front of it, the name in
small letters — and the home screen keeps printing the choice in force in its own way (capitals,
alone). A belief that took the turns for the choice itself reads ``SEL sanitize`` as
``sanitize`` (a partial reading: ``SEL`` is a word it cannot place) and would claim a course the
appliance never took. So a word value read only partially, in another letter case than the
same setting was last read in a full reading, is not taken as confirmed: the agent looks at it
again before it starts the appliance or claims (:meth:`apbot.agent.session.Session.unconfirmed`);
a look that enters the setting's screen by the knob's push shows the choice taken, or that it
was not. A value read in one case only (numbers, a reading never made in full) teaches nothing,
and only a setting turned by a knob that can also be pushed is held back so
(:func:`pushed_to_take`): held back for any key, the rule cost true claims on the held-out set.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.schema import ApplianceModel, DiscreteVariable

__all__ = ["letter_case", "marked_now", "pushed_to_take"]


def letter_case(model: ApplianceModel, name: str, value: Any, text: str) -> str | None:
    """How ``text`` prints ``value`` of the word setting ``name``: ``upper``, ``lower`` or
    ``mixed`` (None: not printed as letters, or not found as whole words)."""
    spec = model.variables.get(name)
    if not isinstance(spec, DiscreteVariable):
        return None
    words = [str(value)]
    if isinstance(spec.show, dict):
        shown = spec.show.get(str(value))
        if isinstance(shown, str) and shown and "{" not in shown:
            words.insert(0, shown)
    for word in words:
        if not re.search(r"[^\W\d_]", word):
            continue
        found = re.search(rf"(?<!\w){re.escape(word)}(?!\w)", text, re.IGNORECASE)
        if found is None:
            continue
        letters = "".join(c for c in found.group(0) if c.isalpha())
        if letters.isupper():
            return "upper"
        if letters.islower():
            return "lower"
        return "mixed"
    return None


def pushed_to_take(model: ApplianceModel, name: str) -> bool:
    """Whether the belief turns ``name`` with a knob that can also be pushed (a press of the
    same control): the shape of a knob that highlights a choice and takes it when pushed. A
    setting stepped by keys alone may print its candidate otherwise for other reasons."""
    actions = model.actions
    turned = {
        control
        for steps in model.features.values()
        for step in steps
        if step.variable == name
        for action in step.actions
        if action in actions and actions[action].skill in ("turn_cw", "turn_ccw")
        for control in actions[action].control_ids
    }
    return any(
        spec.skill == "press" and set(spec.control_ids) & turned for spec in actions.values()
    )


def marked_now(
    model: ApplianceModel,
    values: dict[str, Any],
    text: str,
    partial: bool,
    forms: dict[str, str],
    marked: set[str],
) -> None:
    """Update, from one reading of ``text``, each word setting's letter case in its last full
    reading (``forms``) and the settings whose last reading was only a marked one
    (``marked``): partial, and in another case than that full reading."""
    for name, value in values.items():
        case = letter_case(model, name, value, text)
        if case is None:
            marked.discard(name)
            continue
        if not partial:
            forms[name] = case
            marked.discard(name)
        elif name in forms and forms[name] != case:
            marked.add(name)
        else:
            marked.discard(name)
