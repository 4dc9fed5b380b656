"""How the display shows a setting while it is set: "ON 18:00   the switch-on time is being set".

Display legends list, for each setting, what the screen reads while that setting is being
changed: a word in capitals, an example value, and a description saying it is being set
("TEMP 50°C   the set bath temperature is being changed", "HRS 4 h   mowing hours per day
being set"). Without it, a screen "ON 18:00" is read as the mode ON and a time no setting
claims; with the word, the example's unit and the value in between as the setting's display
text, the agent reads the setting off the screen.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.off_words import lines_outside_asides, unit_at

_LEGEND = re.compile(
    r"^\s*(?:[-•▪*]\s*)?(?P<word>[A-Z][A-Z]{1,7})\s+"
    r"(?P<value>\d{1,2}:\d{2}|\d{1,4}(?:[.,]\d+)?)(?P<unit>\s?(?:°C|°F|%|min|h|s))?"
    r"\s{2,}(?P<what>\S.*\bbeing\s+(?:set|changed|adjusted)\b.*)$"
)
_GENERIC = frozenset({"the", "set", "is", "being", "changed", "adjusted", "with", "per", "a"})


def _candidates(b: Builder, clock: bool) -> list[str]:
    """The settings a legend's example may belong to: times for h:mm, numbers otherwise."""
    kind = "time" if clock else "numeric"
    return [
        name
        for name, spec in b.variables.items()
        if spec.get("type") == kind and "show" not in spec
    ]


def _score(b: Builder, name: str, word: str, what: list[str]) -> int:
    """How well a legend row names the setting: its printed label, the shown word as the start
    of the setting's name (TEMP for temperature), the description's words in its name."""
    spec: dict[str, Any] = b.variables[name]
    label = str(spec.get("label") or "")
    own = set(name.split("_")) | set(words(label))
    score = 0
    if label.upper() == word:
        score += 3
    if any(w.startswith(word.lower()) for w in own):
        score += 2
    score += len((own - _GENERIC) & set(what))
    return score


def read_shown_settings(b: Builder) -> None:
    """Give a setting the display text its legend row shows while it is being set."""
    taken: set[str] = set()
    for number, line in enumerate(lines_outside_asides(b), start=1):
        m = _LEGEND.match(line)
        if m is None:
            continue
        word, what = m.group("word"), words(m.group("what"))
        names = [n for n in _candidates(b, ":" in m.group("value")) if n not in taken]
        scored = sorted(((_score(b, n, word, what), n) for n in names), reverse=True)
        if not scored or scored[0][0] < 1 or (len(scored) > 1 and scored[1][0] == scored[0][0]):
            continue
        name = scored[0][1]
        unit = m.group("unit") or ""
        b.variables[name]["show"] = f"{word} {{value}}{unit}"
        taken.add(name)
        b.note(
            f"variables.{name}.show",
            f"the display shows {word} and the value while it is set",
            unit_at(b, number),
        )
