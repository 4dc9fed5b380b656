"""Re-entering a procedure to find the setting that follows it: a weight typed after AUTO
DEFROST chose the food, the variable finder's last resort when no key without a role shows it
(:mod:`apbot.agent.discovery`). The procedure is the one the goal entry is named after
(``auto_defrost_weight``, as the goal parser names an open entry said beside a choice).
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

from apbot.agent.added_settings import add_keypad_step
from apbot.agent.finder_keys import _digit_keys, _main, _planned, _press_digit, _unknown
from apbot.agent.model_edits import RepairError
from apbot.agent.setting_texts import _typing, typed_setting
from apbot.model.schema import DiscreteVariable

if TYPE_CHECKING:
    from apbot.agent.discovery import VariableFinder


def typed_after_named(finder: VariableFinder, name: str, goal_value: Any) -> bool:
    """A procedure named like the setting may go on with digits ("press AUTO DEFROST for
    the food, then type the weight"): press its key until the display shows again the
    choice the belief holds (the programme the rest of the goal set), then type the goal's
    value; a display that then shows it is the setting, that procedure's next step."""
    session = finder.session
    digits = _digit_keys(session.context.actions or tuple(session.offered))
    typing = _typing(goal_value)
    if typing is None or len(digits) < 10:
        return False
    _, typed, value, _ = typing
    lamps = session.perceiver.reader.lamp_texts()
    for key, site in finder._named_steps(name)[:2]:
        feature, index = site
        chosen = session.belief.model.features[feature][index].variable
        if chosen is None:
            continue
        before = session.belief.values()
        if not _reenter(finder, key, chosen, before[chosen]):
            continue
        texts: list[str] = []
        # one digit shows one text, from which no setting can be read: type another digit
        # first (a one-digit entry takes the last; a longer one shows a value not asked for)
        keyed = typed if len(typed) > 1 else ("2" if typed == "1" else "1") + typed
        for digit in keyed:
            done = _press_digit(session, digits[digit])
            if not done.feedback.accepted:
                break
            texts.append(_main(done.feedback.text, lamps))
        if len(texts) < len(keyed):
            continue
        found = typed_setting(name, texts, typing, goal_value)
        if found is None:
            continue
        learnt, variable = found
        try:
            new = add_keypad_step(
                session.belief.model, name, variable, [digits[d] for d in sorted(digits)], site
            )
        except RepairError as exc:
            session.episode.log("repair", f"could not add {name}: {exc}")
            continue
        session.adopt(
            new,
            f"{name}: found under {key}, then the digits; {learnt.note}",
            (feature, index + 1),
        )
        session.discovered.add(name)
        for other, was in before.items():  # the digits typed nothing else
            if other != name and session.belief.value(other) != was:
                session.belief.set_value(other, was)
        session.belief.set_value(name, value)
        session.evidence[name] = value
        session.reread()
        return True
    return False


def _reenter(finder: VariableFinder, key: str, chosen: str, held: Any) -> bool:
    """Press ``key`` until the display shows ``chosen`` at the value the belief holds again
    (once round its list at most); False when refused or never shown."""
    session = finder.session
    spec = session.belief.model.variables.get(chosen)
    if not isinstance(spec, DiscreteVariable):
        return False
    values = list(spec.values or [])
    word = re.compile(rf"(?<!\w){re.escape(str(held))}(?!\w)", re.IGNORECASE)
    for _ in range(len(values) + 2):
        finder.guards.lift_all()
        done = session.press(session.planned(key) or _planned(key), exploring=True)
        if not done.feedback.accepted:
            return False
        seen = done.seen
        if seen is not None and seen.screen == chosen and not _unknown(done):
            if session.belief.value(chosen) == held:
                return True
        elif word.search(_main(done.feedback.text, set())):
            return True  # a screen the belief cannot read yet, naming the choice
    return False
