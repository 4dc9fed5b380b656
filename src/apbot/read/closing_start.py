"""A procedure that ends by pressing START where START does not start the appliance.

Manuals close the entry of a side setting with the start key: "Tap TIMER, type the minutes,
tap START" for a kitchen timer that "does not switch the microwave on", or "1. Touch CLOCK.
2. Enter the time. 3. Touch START." for the clock. That closing press is part of the
procedure: without it the model's separate START (the run) is spent confirming the timer, and
the appliance never runs. Only a START that confirms is added here; a START that closes a
cooking or defrosting procedure starts the run, which the model's own start feature already
does (planned last).
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_common import label_of, mentions_of
from apbot.read.roles_functions import section_units
from apbot.read.text import Unit

_VERB = r"(?:press|touch|push|tap|hit)(?:es)?\s+(?:the\s+)?"
_ANY_PRESS = re.compile(rf"\b{_VERB}", re.IGNORECASE)
# the procedure types the value: "type the minutes", "Enter the time with the number pads"
_ENTRY = re.compile(
    r"\b(?:type|enter|key\s+in|input|digits|number\s+(?:pads?|keys?|buttons?))", re.IGNORECASE
)
# what the section says of the setting: it runs nothing ("a countdown timer that does not
# cook", "minute minder (no heating)", "counts down without turning on the microwave energy")
_RUNS_NOTHING = re.compile(
    r"\b(?:does\s+not|doesn't|do\s+not|without|no)\s+(?:\w+\s+)?"
    r"(?:cook\w*|heat\w*|(?:turn|switch)\w*\b[^.;:]{0,40}?\bon\b)",
    re.IGNORECASE,
)


def close_with_start(b: Builder) -> None:
    """Append the closing START press to each feature 'KEY, then the number keys' whose own
    procedure ends by pressing START, when that START only confirms (a clock, or a setting its
    section or legend says runs nothing)."""
    starts = [i for i in b.infos if i.skill == "press" and "start" in words(i.token)]
    if len(starts) != 1:
        return  # (no start key, or several whose one this is cannot be told)
    start = starts[0]
    start_labels = [label_of(b, c) for c in start.controls]
    for fname, steps in b.features.items():
        if len(steps) != 2 or set(steps[0]) != {"actions"} or len(steps[0]["actions"]) != 1:
            continue
        var = steps[1].get("variable")
        if var is None or not all(_is_digit(b, a) for a in steps[1]["actions"]):
            continue
        key = next((i for i in b.infos if i.name == steps[0]["actions"][0]), None)
        if key is None or key.skill != "press" or key is start or len(key.controls) != 1:
            continue
        at = _closing_procedure(b, key.controls[0], start_labels)
        if at is None:
            continue
        clock = "clock" in words(var.replace("_", " "))
        if not clock and not _runs_nothing(b, key.controls[0], at):
            continue  # (its START starts the run: the start feature does that)
        steps.append({"actions": [start.name], "note": "START closes the entry"})
        b.note(f"features.{fname}", "its procedure ends by pressing START, which confirms", at)


def _is_digit(b: Builder, action: str) -> bool:
    return any(i.name == action and i.digit is not None for i in b.infos)


def _closing_procedure(b: Builder, token: str, start_labels: list[str]) -> int | None:
    """The unit opening the key's procedure when that procedure is: press the key, type the
    value, press START last ("Tap TIMER, type the minutes, tap START." or numbered steps)."""
    units = b.manual.units
    label = re.escape(label_of(b, token))
    starts = "|".join(re.escape(s) for s in start_labels if s)
    if not starts:
        return None
    opens = re.compile(rf"^\W*{_VERB}{label}(?![\w/])(.*)$", re.IGNORECASE)
    # (START may carry its purpose: "Touch START to begin the countdown.")
    closes = re.compile(
        rf"\b{_VERB}(?:{starts})(?![\w/])(?:\s+to\s+[a-z][^.;:]*)?\W*$", re.IGNORECASE
    )
    for i in mentions_of(b, token):
        m = opens.match(units[i].text)
        if m is None or units[i].cells:
            continue
        rest = m.group(1)
        if _ANY_PRESS.search(rest):  # one sentence: the key, the value, START at its end
            if len(_ANY_PRESS.findall(rest)) == 1 and closes.search(rest) and _ENTRY.search(rest):
                return i
            continue
        if units[i].step is not None and _numbered_closes(units, i, closes):
            return i
    return None


def _numbered_closes(units: list[Unit], first: int, closes: re.Pattern[str]) -> bool:
    """Numbered steps after the key's: values typed, and the list's last step presses START."""
    number = units[first].step
    assert number is not None
    middle: list[str] = []
    for k in range(first + 1, min(first + 12, len(units))):
        unit = units[k]
        if unit.heading != units[first].heading or unit.cells:
            break
        if unit.step is None:
            continue  # (a worked example under a step: "For 9:25, touch 9, 2, 5.")
        if unit.step != number + 1:
            break
        number = unit.step
        pressed = re.match(rf"^\W*{_VERB}", unit.text, re.IGNORECASE)
        if pressed and closes.search(unit.text):
            if not middle:
                return False
            following = [u for u in units[k + 1 : k + 12] if u.heading == unit.heading]
            ends_list = not any(u.step == number + 1 for u in following)
            return ends_list and any(_ENTRY.search(t) for t in middle)
        if pressed and not _ENTRY.search(unit.text):
            return False  # another key pressed before START ("Touch the digits" types)
        middle.append(unit.text)
    return False


def _runs_nothing(b: Builder, token: str, at: int) -> bool:
    """Whether the procedure's section, or the key's own legend row, says the setting runs
    nothing ("does not cook", "no heating", "does not switch the microwave on")."""
    units = b.manual.units
    section = [u.text for u in section_units(b, at)] if units[at].heading else [units[at].text]
    label = label_of(b, token).upper()
    legend = [
        units[i].text
        for i in mentions_of(b, token)
        if re.sub(r"^[^A-Za-z]*", "", units[i].text).upper().startswith(label)
    ]
    return any(_RUNS_NOTHING.search(t) for t in section + legend)
