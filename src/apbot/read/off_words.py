"""On/off settings whose display word shows while they are OFF: "MUTE  buzzer switched off".

Many panels light a word only when a normally-on setting is switched off: MUTE for the buzzer,
ALARM OFF for a door alarm, NO STIR for a stirring arm. The display legend says so, a display
word in its first column and a description saying the setting is off ("the door alarm will not
sound"). Read as a plain toggle the setting would start off and show a lamp while on, so the
agent would believe a silenced buzzer is already silent and misread the display. Such a setting
starts on, shows nothing while on and the word while off.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder

# a legend line: a display word in capitals, two spaces or more, what it means
_LEGEND = re.compile(r"^\s*(?:[-•▪*]\s*)?([A-Z][A-Z0-9+]+(?: [A-Z0-9+]+)?)\s{2,}(\S.*)$")
_SHORT = 8  # words: a legend's meaning, not a paragraph that happens to say "off"
_OFF = re.compile(
    r"\b(?:off|muted?|silenced|silent|disabled|will\s+not|won't|does\s+not|no\s+longer)\b",
    re.IGNORECASE,
)
_ON = re.compile(r"\bon\b", re.IGNORECASE)
_SKIP = frozenset({"power", "running", "child_lock"})


def read_off_words(b: Builder) -> None:
    """Turn an on/off setting the display legend shows only while off into one that starts on."""
    for var, spec in b.variables.items():
        if var in _SKIP or spec.get("type") != "discrete" or "cases" in spec:
            continue
        if sorted(str(v) for v in spec.get("values") or []) != ["off", "on"]:
            continue
        show = spec.get("show")
        if isinstance(show, dict) and show.get("on"):
            continue  # the display already names it while on
        found = _off_word(b.manual.lines, var, str(spec.get("label") or ""))
        if found is None:
            continue
        word, line = found
        _set_off_word(b, var, spec, word)
        b.note(
            f"variables.{var}.show",
            f"the display shows {word} while it is off; it starts on",
            _unit_at(b, line),
        )


def _off_word(lines: list[str], var: str, label: str) -> tuple[str, int] | None:
    """The display word of a legend line saying the setting is off, and its line."""
    nouns = {w for w in var.split("_") if len(w) >= 4}
    for number, line in enumerate(lines, 1):
        match = _LEGEND.match(line)
        if not match:
            continue
        word = match.group(1).strip()
        what = re.split(r"[.;:]\s", match.group(2) + " ")[0]  # its first sentence
        if len(what.split()) > _SHORT:
            continue
        if word == label.upper() or not _OFF.search(what) or _ON.search(what):
            continue
        said = {w.lower() for w in re.findall(r"[A-Za-z]+", what)}
        if nouns & said:
            return word, number
    return None


def _set_off_word(b: Builder, var: str, spec: dict[str, Any], word: str) -> None:
    spec["values"] = ["on", "off"]
    spec["initial"] = "on"
    spec["show"] = {"on": "", "off": word}
    if var not in b.indicators:
        b.indicators.append(var)  # the word is a lamp beside the main display


def _unit_at(b: Builder, line: int) -> int | None:
    """The unit on (or last before) a raw line, for the note's quote."""
    at = None
    for i, unit in enumerate(b.manual.units):
        if unit.line > line:
            break
        at = i
    return at
