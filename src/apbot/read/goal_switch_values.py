"""A word that is both a value of one setting and the whole name of a switch.

A drum module's metronome is switched by CLICK, and its sound can be CLICK, BEEP, COWBELL …:
"click" names three things. Said with another value of that sound, as its name ("the cowbell as
the click sound", "the beep as the click": after "as the", or before the setting's word) it
names the sound setting — neither its CLICK value nor the
switch; said with a state or a start ("start the click", "the click going", "click on") it is
the switch. Elsewhere the value stands.
"""

from __future__ import annotations

from typing import Any

from apbot.read.goal_text import Text
from apbot.read.goal_view import Model, own_stems
from apbot.read.goal_vocab import stem

_STATES = frozenset(stem(w) for w in ("on", "off", "going", "running", "playing", "sounding"))
_STARTS = frozenset(stem(w) for w in ("start", "stop", "starting", "stopping"))


def _state_beside(text: Text, k: int) -> bool:
    after = text.stems[k + 1] if k + 1 < len(text.stems) else ""
    before = [text.stems[i] for i in range(max(0, k - 2), k)]
    if before and before[-1] == stem("the"):
        before = before[:-1]
    return after in _STATES or bool(before and before[-1] in _STARTS)


def _names_the_setting(view: Model, text: Text, match: Any) -> bool:
    """The word is said as the setting's name: after "as the" / "as a" ("the beep as the
    click"), or before a word of the setting's own ("the click sound")."""
    k = match.start
    if text.word(k - 2) == "as" and text.word(k - 1) in ("the", "a", "its", "my"):
        return True
    after = text.concepts[k + 1] if k + 1 < len(text.concepts) else ""
    return view.infos[match.var].vocab.get(after, 0.0) >= 0.7


def switch_named_values(view: Model, text: Text, matches: list[Any]) -> tuple[list[Any], set[int]]:
    """The value matches kept, and the words that name a setting (claimed, no switch's)."""
    names = {
        next(iter(own)): name
        for name, info in view.infos.items()
        if info.role == "switch" and len(own := own_stems(info)) == 1
    }
    kept: list[Any] = []
    naming: set[int] = set()
    for match in matches:
        one = match.end - match.start == 1
        switch = names.get(text.stems[match.start]) if one else None
        if switch is None or switch == match.var:
            kept.append(match)
            continue
        others = any(
            m.var == match.var and m.value != match.value and m.start != match.start
            for m in matches
        )
        if others and _names_the_setting(view, text, match):
            naming.add(match.start)  # "the cowbell as the click sound": the sound setting
        elif not _state_beside(text, match.start):
            kept.append(match)
    return kept, naming


def started_switches(view: Model, text: Text) -> set[int]:
    """Positions of "start" / "stop" whose object is a switch's whole name ("start the click"):
    that switch's state, no start of the appliance."""
    names = {
        next(iter(own))
        for info in view.infos.values()
        if info.role == "switch" and len(own := own_stems(info)) == 1
    }
    found = set()
    for k in range(len(text.tokens)):
        if text.stems[k] not in _STARTS:
            continue
        j = k + 2 if text.word(k + 1) in ("the", "its", "my") else k + 1
        if j < len(text.stems) and text.stems[j] in names:
            found.add(k)
    return found
