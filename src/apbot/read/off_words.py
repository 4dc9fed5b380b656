"""On/off settings whose display word shows while they are OFF: "MUTE  buzzer switched off".

Many panels light a word only when a normally-on setting is switched off: MUTE for the buzzer,
ALARM OFF for a door alarm, NO STIR for a stirring arm. The display legend says so, a display
word in its first column and a description saying the setting is off ("the door alarm will not
sound"). Read as a plain toggle the setting would start off and show a lamp while on, so the
agent would believe a silenced buzzer is already silent and misread the display. Such a setting
starts on, shows nothing while on and the word while off.

A held key that switches such a setting ("Hold MODE for 3 seconds to mute the buzzer") is often
read with no setting of its own — a copy of the key's press list, or a chart column — and then
becomes that on/off setting, named by the legend's noun.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.shapes import ASIDE_HEADING

# a legend line: a display word in capitals, two spaces or more, what it means
# (a word with dashes for its blank value, "AUTO OFF --  the auto switch-off is disabled", is
# that word while off)
# (the panel's icon may stand before the word, as drawn beside it: "⚡̸ GRID OFF   grid off")
_LEGEND = re.compile(
    r"^\s*(?:[-•▪*]\s*)?(?:[^\w\s()\[\]]{1,3}\s+)?"
    r"([A-Z][A-Z0-9+]+(?: [A-Z0-9+]+)?(?: -{1,3}(?=\s))?)\s{2,}(\S.*)$"
)
_SHORT = 8  # words: a legend's meaning, not a paragraph that happens to say "off"
_SUBJECT = 3  # words naming what is off ("the door alarm", "end signal")
_OFF = re.compile(
    r"\b(?:off|muted?|silenced|silent|disabled|will\s+not|won't|does\s+not|no\s+longer)\b",
    re.IGNORECASE,
)
_ON = re.compile(r"\bon\b", re.IGNORECASE)
# a sentence holding a key that switches a thing off or on, not one that only mentions it
# ("Hold NIGHT 3 s to choose the night speed; each beep confirms" switches no beep)
_SWITCHING = re.compile(
    r"\b(?:mute|unmute|silence|switch(?:es)?|turns?|off|disables?|enables?|toggles?)\b",
    re.IGNORECASE,
)
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
        found = _off_word(lines_outside_asides(b), var, str(spec.get("label") or ""))
        if found is None:
            continue
        word, line = found
        _set_off_word(b, var, spec, word)
        b.note(
            f"variables.{var}.show",
            f"the display shows {word} while it is off; it starts on",
            unit_at(b, line),
        )


def read_held_off_words(b: Builder) -> None:
    """A hold read with no on/off setting of its own becomes the setting a legend's off word
    names, when a sentence holding that key names the same thing."""
    for steps in list(b.features.values()):
        if len(steps) != 1 or len(steps[0].get("actions") or []) != 1:
            continue
        action, var = steps[0]["actions"][0], steps[0].get("variable")
        info = next((i for i in b.infos if i.name == action), None)
        spec = b.variables.get(str(var))
        if info is None or info.skill != "hold" or not info.controls or spec is None:
            continue
        if not _borrowed(b, str(var), spec) or info.controls[0] not in b.labels:
            continue
        label = b.labels[info.controls[0]].text
        found = _held_off_word(b, label)
        if found is None:
            continue
        word, noun, line = found
        del b.variables[str(var)]
        if var in b.indicators:
            b.indicators.remove(str(var))
        name = b.unique(noun.replace(" ", "_"), b.variables)
        b.variables[name] = {"type": "discrete", "values": ["on", "off"], "label": word}
        _set_off_word(b, name, b.variables[name], word)
        steps[0] = {"actions": [action], "variable": name, "effect": "toggle"}
        b.note(
            f"variables.{name}",
            f"holding {label} switches the {noun}; the display shows {word} while it is off",
            unit_at(b, line),
        )


def _borrowed(b: Builder, var: str, spec: dict[str, Any]) -> bool:
    """Whether a setting has no on/off reading of its own: another setting's list again, or
    values from a chart column."""
    if "cases" in spec:
        return True
    values = list(spec.get("values") or [])
    return len(values) >= 3 and any(
        other != var and list(o.get("values") or []) == values for other, o in b.variables.items()
    )


def _held_off_word(b: Builder, label: str) -> tuple[str, str, int] | None:
    """A legend off word ("MUTE  the buzzer is muted") whose noun a sentence holding the key
    names ("Hold MODE for 3 seconds to mute the buzzer"): the word, the noun, the legend line."""
    held = re.compile(
        rf"\bhold\b[^.]*?(?<![A-Za-z]){re.escape(label)}(?![A-Za-z])"
        rf"|(?<![A-Za-z]){re.escape(label)}(?![A-Za-z])[^.]*?\bhold",
        re.IGNORECASE,
    )
    own_row = [  # the key's own legend row that speaks of holding
        u.text for u in b.manual.units if u.cells and u.cells[0].strip() == label
    ]
    texts = [u.text for u in b.manual.units if held.search(u.text)]
    sentences = [  # the sentence holding the key, and it switches something off
        t.lower()
        for text in texts + own_row
        for t in re.split(r"(?<=[.;!?])\s+", text)
        if (held.search(t) or (text in own_row and re.search(r"\bhold", t, re.I)))
        and _SWITCHING.search(t)
    ]
    for number, line in enumerate(lines_outside_asides(b), 1):
        match = _LEGEND.match(line)
        if not match:
            continue
        word = match.group(1).strip()
        what = re.split(r"[.;:]\s", match.group(2) + " ")[0]
        if len(what.split()) > _SHORT or not _OFF.search(what) or _ON.search(what):
            continue
        noun = _noun(what)
        if noun and any(re.search(rf"\b{re.escape(noun)}\b", t) for t in sentences):
            return word, noun, number
    return None


_FILLER = frozenset({"the", "is", "are", "was", "switched", "turned", "will", "does", "not", "no"})


def _noun(what: str) -> str:
    """The thing a legend's off description names: its words before the off phrase, without
    articles and verbs ("the buzzer is muted" → "buzzer", "stirring arm switched off" →
    "stirring arm")."""
    off = _OFF.search(what)
    head = what[: off.start()] if off else what
    kept = [w for w in re.findall(r"[a-z]+", head.lower()) if w not in _FILLER]
    return " ".join(kept[-2:])


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
        if nouns & set(_subject(what)):
            return word, number
    return None


def _subject(what: str) -> list[str]:
    """The words a legend's meaning says are off, when they open it as one short clause
    ("the buzzer is muted", "end signal switched off"); none when the meaning first names
    something else ("energy saving, lamp off after 2 min": the word is the saving's)."""
    off = _OFF.search(what)
    head = what[: off.start()] if off else ""
    if re.search(r"[,;:()]", head):
        return []
    kept = [w for w in re.findall(r"[a-z]+", head.lower()) if w not in _FILLER]
    return kept if len(kept) <= _SUBJECT else []


def lines_outside_asides(b: Builder) -> list[str]:
    """The manual's lines, blanked under a troubleshooting, error-code or safety heading: a
    fault's code there ("E2  pump will not start", "L  low water") is no word the display
    shows while a setting is off, nor a setting's code spelled out."""
    heading: dict[int, str] = {}
    for unit in b.manual.units:
        heading.setdefault(unit.line, unit.heading)
    out: list[str] = []
    last = ""
    for number, line in enumerate(b.manual.lines, 1):
        last = heading.get(number, last)
        out.append("" if last and ASIDE_HEADING.search(last) else line)
    return out


def _set_off_word(b: Builder, var: str, spec: dict[str, Any], word: str) -> None:
    spec["values"] = ["on", "off"]
    spec["initial"] = "on"
    spec["show"] = {"on": "", "off": word}
    if var not in b.indicators:
        b.indicators.append(var)  # the word is a lamp beside the main display


def unit_at(b: Builder, line: int) -> int | None:
    """The unit on (or last before) a raw line, for the note's quote."""
    at = None
    for i, unit in enumerate(b.manual.units):
        if unit.line > line:
            break
        at = i
    return at
