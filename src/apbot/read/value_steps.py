"""Step sizes and start values said in prose: "5 °C per press", "in 10-minute steps",
"2 hours at a time", "Pressing TEMP ▲ moves it by 5 °C", "the default is 30 minutes".

Apart from :mod:`apbot.read.values` (ranges and units), which these build on: a range is said
in many ways, a step in many others, and the two are read and tested separately.
"""

from __future__ import annotations

import re

from apbot.read.step_phrases import said_step
from apbot.read.values import NUM, STEP_RE, UNIT, number, unit_name

PER_RE = re.compile(
    rf"\b({NUM})\s*({UNIT})\s+(?:per|for each|each|with each|with every|a)\s+"
    rf"(?:press|click|turn|touch|detent|step|tap|notch)",
    re.IGNORECASE,
)


_WHOLE_RE = re.compile(
    r"\bin (?:whole|full) (degrees?|minutes?|hours?|seconds?)(?:\s+(celsius|fahrenheit))?\b", re.I
)
# "Enter the minutes and seconds.", "type the time in minutes and seconds": any second is keyed
# (a few words apart: "enter the weight, and the oven works out the minutes and seconds" keys
# a weight)
_KEYED_MIN_SEC_RE = re.compile(
    r"\b(?:enter|type|key)(?:s|ed|ing)?\b(?:[\s:]+[\w'-]+){0,5}?[\s:]+minutes\s+and\s+seconds\b",
    re.I,
)
_BARE_STEPS_RE = re.compile(rf"(?<![\w-])({NUM})-({UNIT})\s+(?:steps|increments)\b", re.I)


# "from 35 °C to 70 °C, 5 degrees at a time": the step, said as how much goes at once (not
# a hold's fast steps: "hold for 2 s to move 10 minutes at a time", "2 s: raise 5 °F at a time")
_AT_A_TIME_RE = re.compile(rf"\b({NUM})\s*({UNIT})\s+at\s+a\s+time\b", re.I)
# "Pressing TEMP ▲ or TEMP ▼ moves it by 5 °C": a press said once, what it changes said by how
# much (without "each"/"every")
_PRESSING_BY_RE = re.compile(
    rf"\b(?:pressing|touching|tapping|a\s+(?:press|touch|tap)\s+(?:of|on))\b[^.;]{{0,40}}?"
    rf"\b(?:raises?|lowers?|moves?|changes?|increases?|decreases?|adjusts?|shifts?)\b[^.;]{{0,20}}?"
    rf"\bby\s+({NUM})\s*({UNIT})(?!\w)",
    re.I,
)
# "TEMPO + raises the tempo by 1, TEMPO - lowers it by 1.": the key itself, named in capitals,
# is the subject of a press (a plain count needs no unit: beats, semitones, levels)
_KEY_RAISES_BY_RE = re.compile(
    rf"^[A-Z][A-Z0-9.]*(?:\s*[-+▲▼△▽<>]|\s+(?:UP|DOWN))?\s+"
    rf"(?:raises|lowers|increases|decreases|moves|changes|adjusts|shifts)\b[^.;,]{{0,30}}?"
    rf"\bby\s+({NUM})(?:\s*({UNIT}))?(?![\w/:.,]\d|\w)"
)
# "Tap ▲ or ▼: the desk moves 1 cm up or down": a tap moves the thing itself by its step
_TAP_MOVES_RE = re.compile(
    rf"^\W*(?:tap|press|touch)\b[^.;]{{0,40}}?\bmoves?\s+(?:it\s+)?({NUM})\s*({UNIT})\s+"
    rf"(?:up|down|higher|lower|forwards?|backwards?|in|out)\b",
    re.I,
)
# "each click = 1 %", "one press: 5 °C": a click or press equated with its amount, as a legend
# or a chart of step sizes writes it
_CLICK_EQUALS_RE = re.compile(
    rf"\b(?:each|every|one|per)\s+(?:press|click|turn|touch|detent|step|tap|notch)\s*[=:]\s*"
    rf"({NUM})\s*({UNIT})(?!\w)",
    re.I,
)
_HELD_RE = re.compile(
    r"\b(?:hold|held|holding|keep|fast|faster|quick|quickly|rapid)\b|\d\s*s\b", re.I
)


def find_step(text: str) -> tuple[float, str] | None:
    """A step size: (number, canonical unit)."""
    per = PER_RE.search(text)
    if per is None and not _HELD_RE.search(text):
        per = _AT_A_TIME_RE.search(text)
    if per and number(per.group(1)):
        return number(per.group(1)) or 1.0, unit_name(per.group(2))
    m = STEP_RE.search(text)
    if not m:
        bare = _BARE_STEPS_RE.search(text)  # "| up to 15 h ahead, ten-minute steps |"
        if bare and number(bare.group(1)):
            return number(bare.group(1)) or 1.0, unit_name(bare.group(2))
        whole = _WHOLE_RE.search(text)  # "entered in whole degrees Celsius": one at a time
        if whole:
            scale = (whole.group(2) or "").lower()
            unit = {"fahrenheit": "°F", "celsius": "°C"}.get(scale) or unit_name(whole.group(1))
            return 1.0, unit
        if _KEYED_MIN_SEC_RE.search(text):
            return 1.0, "s"
        pressing = None if _HELD_RE.search(text) else _PRESSING_BY_RE.search(text)
        if pressing and (value := number(pressing.group(1))):
            return value, unit_name(pressing.group(2))
        keyed = None if _HELD_RE.search(text) else _KEY_RAISES_BY_RE.search(text)
        if keyed and (value := number(keyed.group(1))):
            return value, unit_name(keyed.group(2))
        tapped = None if _HELD_RE.search(text) else _TAP_MOVES_RE.search(text)
        if tapped and (value := number(tapped.group(1))):
            return value, unit_name(tapped.group(2))
        equals = _CLICK_EQUALS_RE.search(text)
        if equals and (value := number(equals.group(1))):
            return value, unit_name(equals.group(2))
        return None if _HELD_RE.search(text) else said_step(text)
    groups = m.groups()
    if m.group(0).lower().endswith(("units", "stages")) and not groups[1]:
        return None  # "in half-hour units" is a step, "sold in 2 units", "in two stages" not
    for i in (0, 2, 4, 6):
        raw, unit = groups[i], groups[i + 1]
        if raw is None and i == 4 and unit:
            raw = "1"
        if raw is not None:
            value = number(raw)
            if value:
                return value, unit_name(unit)
    return None


def find_initial(text: str, more: str = "") -> tuple[float, str] | None:
    """A start value said in the text: (number, canonical unit); ``more`` adds ways of
    saying it."""
    m = re.search(
        rf"\b(?:default|factory setting|preset|standard|starts? (?:at|on)|initially|delivered"
        rf"{more})\b[^.;]*?"
        rf"({NUM})\s*({UNIT})?(?![\w:])",
        text,
        re.IGNORECASE,
    )
    if not m:
        return None
    value = number(m.group(1))
    return (value, unit_name(m.group(2))) if value is not None else None
