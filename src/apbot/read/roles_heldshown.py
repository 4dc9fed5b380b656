"""The word the display shows while a held key's on/off setting is on.

A setting switched by holding a key ("Touch and hold DRY for 3 seconds: LOW appears and the
drying runs cooler") is shown by its own word, seldom by the key's name: the key's name is
often shown for something else too (DRY is also a programme). Without that word the belief
reads the key's name on the display as the setting switched on. The sentence that holds the
key says what appears; its first such word (not a key's name) is the setting's sign.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.evidence_checks import SENTENCE_END_RE
from apbot.read.shown import shown_words

# where the hold's sentence ends: the word must be said of this hold, not of a later step
# what the word is then said to mean: something switched off
_SAYS_OFF = re.compile(r"\b(?:off|disabled|deactivated|silenced|muted)\b", re.IGNORECASE)


def held_shown(b: Builder, key: ActionInfo) -> tuple[str, int] | None:
    """(word, unit) that a sentence holding this key says appears; None when none says so."""
    if key.skill != "hold" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return None
    label = b.labels[key.controls[0]].text
    if not label:
        return None
    holding = re.compile(
        rf"\bhold(?:s|ing)?(?:\s+down)?\s+(?:the\s+)?{re.escape(label)}(?!\w)", re.IGNORECASE
    )
    keys = {lab.text for lab in b.labels.values() if lab.text}
    for i, unit in enumerate(b.manual.units):
        if unit.cells:
            continue
        for sentence in SENTENCE_END_RE.split(unit.text):
            m = holding.search(sentence)
            if m is None:
                continue
            rest = sentence[m.end() :]
            words = shown_words(rest, keys)
            if words and words[0].upper() != label.upper():
                after = rest[rest.find(words[0]) + len(words[0]) :]
                if _SAYS_OFF.search(words[0]) or _SAYS_OFF.search(after):
                    return None  # "MUTE lights up, the end signal is off", "SOUND OFF": off
                return words[0], i
    return None


def show_held_word(b: Builder, key: ActionInfo, var: str) -> None:
    """Give the held key's toggle ``var`` the word its hold sentence says appears (unless the
    display rule is already read)."""
    if "show" in b.variables[var]:
        return
    shown = held_shown(b, key)
    if shown is None:
        return
    b.variables[var]["show"] = {"off": "", "on": shown[0]}
    b.note(f"variables.{var}.show", f"the display shows {shown[0]} while on", shown[1])
    if var not in b.indicators:
        b.indicators.append(var)
