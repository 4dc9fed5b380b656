"""Ranges a setting's own section states in words the range patterns of ``values.py`` pass by:
"The range is 430 Hz to 450 Hz", "The range is level 1 (gentlest) to level 5", "the level
stops at 1 and at 9", "At 1, VOL− does nothing more; at 16, VOL+ does nothing more".

A setting the reader found no range for was given a guessed 0–10 (or a guessed hour or minute
span); real manuals state the span once, in the section about the setting, with the unit
printed on both ends, a noun before each figure ("level 1"), or as the two places the keys
stop. Asked only where the manual gave the range nowhere else (the guess's place in
:meth:`apbot.read.build.Builder.add_number`), so a range read the usual way is never displaced.
A sentence about where the appliance works or what it measures is no setting's range.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import TYPE_CHECKING

from apbot.read.values import Range
from apbot.read.values_signed import _NOT_A_SETTING

if TYPE_CHECKING:
    from apbot.read.text import Unit

_FIGURE = r"\d+(?:[.,]\d+)?"
# a noun the manual counts the setting in ("level 1", "step 3", "position 2", "speed 4")
_NOUN = r"(?:(?:level|step|setting|position|stage|speed|intensity)\s+)?"
# words in brackets after an end: "(gentlest)", "(silent)"
_ASIDE = r"(?:\s*\([^()\d]{1,30}\))?"
# a unit printed after a figure: a known one or any short symbol of letters ("Hz", "bpm", "V")
_UNIT_WORD = (
    r"(?:%|°\s?[CF]|(?!(?:to|and|in|at|or|the|by|for|when|with|on|of|is|it|per)\b)[A-Za-z]{1,7})"
)


def _end(tag: str) -> str:
    return rf"{_NOUN}(?P<{tag}>{_FIGURE})(?:\s*(?P<{tag}u>{_UNIT_WORD})(?![\w°]))?{_ASIDE}"


# "the range is 430 Hz to 450 Hz", "it can be set from 1 to 16", "adjustable between 2 and 8"
_SPAN_RE = re.compile(
    r"\b(?:range\s+is|ranges\s+from|range\s+of|can\s+be\s+set\s+(?:from|between)"
    r"|adjustable\s+(?:from|between)|goes\s+from|runs\s+from|set\s+(?:it\s+)?(?:from|between))"
    rf"\s+(?:from\s+)?{_end('a')}\s*(?:to|and|–|—|…)\s*{_end('b')}",
    re.IGNORECASE,
)
# "stops at 1 and at 9", "stops at 1 and 9" — the second end closing the statement (a stop,
# a bracket, a new clause), so "stops at 0 and 3 beeps sound" is no span of 0 to 3
_STOPS_RE = re.compile(
    rf"\bstops?\s+at\s+{_end('a')}\s*(?:,\s*)?and\s+(?:at\s+)?{_end('b')}"
    r"(?=\s*(?:[.;,:)!]|$|(?:and|but|then|so|it|the|when|on|in|with|for)\b))",
    re.IGNORECASE,
)
# "At 1, VOL− does nothing more; at 16, VOL+ does nothing more"
_ENDS_RE = re.compile(
    rf"\bat\s+{_end('a')}\s*,[^.;]*?\b(?:nothing|no\s+(?:further|more)\s+effect)\b[^.;]*;"
    rf"\s*at\s+{_end('b')}\s*,",
    re.IGNORECASE,
)


def stated_span(text: str) -> tuple[float, float, str] | None:
    """The (low, high, unit as printed) a sentence states as a setting's span, or None."""
    if _NOT_A_SETTING.search(text):
        return None
    for pattern in (_SPAN_RE, _STOPS_RE, _ENDS_RE):
        for m in pattern.finditer(text):
            a = float(m["a"].replace(",", "."))
            b = float(m["b"].replace(",", "."))
            units = {u.replace(" ", "") for u in (m["au"], m["bu"]) if u}
            if len(units) > 1 or a == b:
                continue  # "from 2 kg to 5 min" is no span
            low, high = min(a, b), max(a, b)
            return low, high, units.pop() if units else ""
    return None


# a sentence that states a span with clock figures ("The range is 0:01 to 9:59")
_CLOCK_CUE_RE = re.compile(r"\brange\s+is\b|\bcan\s+be\s+set\b|\bstops?\s+at\b", re.IGNORECASE)
# how far after the key's own "Press KEY" sentence its span may stand (the procedure's steps)
_AFTER_PRESS = 6


def _span_in(unit: Unit) -> Range | None:
    """The span :func:`stated_span` reads in a sentence, or a clock span after a cue (read by
    :func:`apbot.read.values.find_ranges`, in seconds); the unit only when the reader knows it."""
    from apbot.read.values import UNIT, find_ranges, unit_name

    if unit.cells:
        return None
    if re.search(r"\d:\d\d", unit.text):
        if not _CLOCK_CUE_RE.search(unit.text) or _NOT_A_SETTING.search(unit.text):
            return None
        return next((r for r in find_ranges(unit.text) if r.unit == "s" and r.high > r.low), None)
    found = stated_span(unit.text)
    if found is None:
        return None
    low, high, said = found
    known = unit_name(said) if said and re.fullmatch(UNIT, said, re.IGNORECASE) else ""
    return Range(low, high, known)


def stated_unit_span(unit: Unit) -> Range | None:
    """A span a sentence states with the same unit printed on both ends that the range
    patterns of ``values.py`` do not know ("The range is 30 BPM to 280 BPM"), for a setting
    whose sentences gave no range at all; the unit kept only when the reader knows it. Only
    "range is" / "ranges from" / "can be set from" wordings: where the keys stop ("It stops
    at 20 and at 90") is said of whichever setting the keys are on."""
    text = unit.text
    if unit.cells:  # a numbered step drawn as a row ("4 | The range is …"): its sentence
        if len(unit.cells) != 2 or not re.fullmatch(r"\d{1,2}\.?", unit.cells[0].strip()):
            return None
        text = unit.cells[1]
    if re.search(r"\d:\d\d", text) or _NOT_A_SETTING.search(text):
        return None
    for m in _SPAN_RE.finditer(text):
        low, high = (float(m[end].replace(",", ".")) for end in ("a", "b"))
        if m["au"] and m["au"] == m["bu"] and low < high:  # a decimal comma: "1,5 rpm"
            return Range(low, high, "")
    return None


def stated_unit_step(
    units: Sequence[Unit], near: Sequence[int], at: int
) -> tuple[float, int] | None:
    """The step a press makes in the unit printed on the stated span at ``at`` ("changes the
    tempo by 1 BPM"), from the sentences ``near`` it; a sentence about holding a key gives the
    held jump ("Holding + changes it by 10 BPM"), no step."""
    said = next((m["au"] for m in _SPAN_RE.finditer(units[at].text) if m["au"]), None)
    if said is None:
        return None
    by = re.compile(rf"\b(?:by|in\s+steps\s+of)\s+({_FIGURE})\s*{re.escape(said)}\b", re.I)
    for i in near:
        m = by.search(units[i].text)
        if m and not re.search(r"\bhold", units[i].text, re.IGNORECASE):
            return float(m[1].replace(",", ".")), i
    return None


def _names(text: str, own: set[str]) -> bool:
    return any(t.startswith(w) for t in re.findall(r"[a-z]+", text.lower()) for w in own)


def stated_in_section(units: Sequence[Unit], name: str, label: str) -> tuple[Range, int] | None:
    """The first span stated (:func:`_span_in`) in the section whose heading names the setting
    (a heading word starting with a word of its name or label, three letters at least), else
    in the few sentences after one telling to press the key by its printed label ("Press
    SET.") in the same section; None when there is none."""
    own = {w for w in re.findall(r"[a-z]+", f"{name} {label}".lower()) if len(w) >= 3}
    if not own:
        return None
    found: list[tuple[Range, int]] = []
    for i, unit in enumerate(units):
        heading = re.findall(r"[a-z]+", unit.heading.lower())
        if any(h.startswith(w) for h in heading for w in own) and (r := _span_in(unit)):
            found.append((r, i))
    # a section heading two settings ("THE TIME AND THE BONUS"): the sentence naming this one
    named = [(r, i) for r, i in found if _names(units[i].text, own)]
    if found:
        return (named or found)[0]
    if not label or len(label) < 2 or label.upper() != label:
        return None
    press = re.compile(rf"\b(?i:press|turn|push|hold|touch)\s+(?i:the\s+)?{re.escape(label)}(?!\w)")
    for i, unit in enumerate(units):
        if not press.search(unit.text):
            continue
        for j in range(i, min(i + _AFTER_PRESS + 1, len(units))):
            if units[j].heading != unit.heading:
                break
            if (r := _span_in(units[j])) is not None:
                return r, j
    return None


_HALTS_RE = re.compile(
    r"\bstops?\b|\bdoes\s+nothing\b|\bnothing\s+more\b|\bno\s+further\b|\bgoes\s+no\s+further\b",
    re.IGNORECASE,
)


def stated_halts(text: str) -> bool:
    """Whether the sentence stating the span says the value halts at its ends ("the value
    stops at either end", "does nothing more"): stepping past the end does not wrap."""
    return bool(_HALTS_RE.search(text))
