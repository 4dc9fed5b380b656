"""What the user asked for that the goal, as read, does not hold: the honest part of a claim.

The goal parser places what it can and leaves the rest; a goal reached is then only the part
of the request that was understood. A robot that says "done" for "Mozzarella with 4 litres of
milk and a one hour ripening" when it set only the ripening has said something false. Two
kinds of words are counted as unread, from the user's sentence and the belief alone:

- a number the user said (a quantity, a duration, a clock time, a level) that no value of the
  goal holds in any of its forms (seconds, minutes or hours of a duration, the hour and minute
  of a clock, a temperature in the other scale) — the setting it was for was not found;
- a value the user named for a kind of setting the belief has no such value for ("the winter
  mode" where the modes read are others): the parser's own note says so;
- a setting the user named that the goal leaves out ("the recirculation pump on" where only
  the boil was placed): :mod:`apbot.agent.unnamed`;
- an end of a range asked in words ("the hottest setting") where no goal setting stands at
  an end of its range: :mod:`apbot.agent.extremes`.

Numbers that ask nothing are left alone: counts of things ("two slices"), a number written as an
article or a fraction word ("a kilo and a half": the whole is what was placed), a code glued to
a letter ("P4") or following a programme's kind word ("programme 5 for sweet bread"), a number in
brackets ("50 % power (level 5)"), the whole in "day 5 of 17", and a number the user corrected
("190… no, make it 180").
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from typing import Any

from apbot.agent.extremes import unmet_extremes
from apbot.agent.unnamed import unnamed_settings
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction
from apbot.read.goal_error import GoalParseError
from apbot.read.goal_remarks import without_remarks
from apbot.read.goal_view import model_view
from apbot.read.number_tokens import Token, read_number, tokenize
from apbot.read.numbers import Mention, find_mentions
from apbot.read.shapes import GROUP_NOUNS

_NUMBER = re.compile(r"\d+(?:\.\d+)?")
_CLOCK = re.compile(r"^(\d+):(\d\d)(?::(\d\d))?$")
_NO_VALUE = re.compile(r"^'(?P<words>[^']+)': \S+ has no '")  # the parser's note for a name
_NOT_A_NUMBER = frozenset({"a", "an", "half", "quarter", "one"})  # "a kilo", "the rear one"
_CORRECTIONS = frozenset({"no", "sorry", "actually"})  # "190... no, make it 180"
_CORRECTION_REACH = 5
_TOLERANCE = 0.6  # a rounded figure ("17.8" read as 18)
_SCALE_TOLERANCE = 2.0  # a temperature given in the other scale, rounded by the manual


def unread_parts(
    belief: ApplianceModel, instruction: str, goal: Mapping[str, Any], manual: str = ""
) -> list[str]:
    """The words of ``instruction`` that ask for something ``goal`` does not hold."""
    view = model_view(belief, manual)
    try:
        text = without_remarks(view, instruction)
    except (GoalParseError, ValueError):
        text = instruction
    named = {  # a coded value the manual gives as a quantity: knob mark 2 is "60 %"
        f"{name} {label}": value
        for name, pairs in view.named_quantities.items()
        for value, label in pairs
        if name in goal and str(value) == str(goal[name])
    }
    return [
        *unplaced_numbers(text, {**goal, **named}),
        *unknown_names(belief, instruction, manual),
        *unnamed_settings(belief, text, goal, manual),
        *unmet_extremes(belief, text, goal),
    ]


def unplaced_numbers(instruction: str, goal: Mapping[str, Any]) -> list[str]:
    """The numbers the user said that no value (or setting name) of ``goal`` holds."""
    tokens = tokenize(instruction)
    held = _goal_numbers(goal)
    unplaced: list[str] = []
    for mention in find_mentions(tokens):
        if _asks_nothing(mention, tokens):
            continue
        if _held(mention, tokens, held):
            continue
        unplaced.append(" ".join(t.text for t in tokens[mention.start : mention.end]))
    return unplaced


def unknown_names(belief: ApplianceModel, instruction: str, manual: str = "") -> list[str]:
    """Values the user named that the belief's setting of that kind lacks (the parser's
    notes: such a value is dropped from the goal, not kept as said)."""
    notes: list[str] = []
    try:
        parse_instruction(belief, instruction, manual, outside=notes)
    except (GoalParseError, ValueError):
        return []
    return [m["words"] for m in map(_NO_VALUE.match, notes) if m]


def _asks_nothing(mention: Mention, tokens: list[Token]) -> bool:
    first = tokens[mention.start].text.casefold()
    if first in _NOT_A_NUMBER:
        return True
    after = tokens[mention.end].text.casefold() if mention.end < len(tokens) else ""
    if mention.kind == "number" and mention.words and (after.isalpha() or after == "-"):
        return True  # "two slices", "a four-step buttonhole": a count of things
    if mention.start > 0:
        before = tokens[mention.start - 1].text.casefold()
        if len(before) == 1 and before.isalpha() and before not in ("a", "i"):
            return True  # "P4": a code, named as a value if at all
        if mention.kind == "number" and before in GROUP_NOUNS:
            return True  # "programme 5 for sweet bread": a code, the name beside it
    if after == ")" and "(" in {t.text for t in tokens[max(0, mention.start - 2) : mention.start]}:
        return True  # "50 % power (level 5)": an aside, the request said outside it
    if (
        mention.start > 1
        and tokens[mention.start - 1].text.casefold() == "of"
        and read_number(tokens, mention.start - 2) is not None
    ):
        return True  # "day 5 of 17": the whole the said part is counted in
    later = {t.text.casefold() for t in tokens[mention.end : mention.end + _CORRECTION_REACH]}
    return bool(later & _CORRECTIONS)


def _held(mention: Mention, tokens: list[Token], held: set[float]) -> bool:
    forms = {mention.value}
    if mention.kind == "duration":
        forms |= {mention.value / 60, mention.value / 3600}
    if mention.kind == "clock":
        # its hour and minute, where the goal holds them apart (an alarm's hour and minute);
        # a whole hour's minute 0 is no form of it: every duration under an hour holds a 0
        hours, minutes = divmod(int(mention.value) // 60, 60)
        forms |= {float(hours)} | ({float(minutes)} if minutes else set())
    said = read_number(tokens, mention.start)
    if said is not None:
        forms.add(said.value)
    if _near(forms, held, _TOLERANCE):
        return True
    if mention.dimension not in ("temperature", "fahrenheit"):
        return False
    scales = {v * 9 / 5 + 32 for v in forms} | {(v - 32) * 5 / 9 for v in forms}
    return _near(scales, held, _SCALE_TOLERANCE)


def _near(forms: Iterable[float], held: set[float], tolerance: float) -> bool:
    return any(abs(abs(f) - h) <= tolerance for f in forms for h in held)


def _goal_numbers(goal: Mapping[str, Any]) -> set[float]:
    """Every number a goal holds, in every form a user may have said it in."""
    held: set[float] = set()
    for name, value in goal.items():
        held |= {float(n) for n in _NUMBER.findall(name)}  # "temperature_1": zone 1
        if isinstance(value, bool):
            continue
        if isinstance(value, int | float):
            held.add(abs(float(value)))
            continue
        clock = _CLOCK.match(str(value).strip())
        if clock:
            hours, minutes, seconds = int(clock[1]), int(clock[2]), int(clock[3] or 0)
            total = float(hours * 3600 + minutes * 60 + seconds)
            held |= {total, total / 60, total / 3600, float(hours), float(minutes)}
        held |= {float(n) for n in _NUMBER.findall(str(value))}
    return held
