"""Words the panel shows for a state: "RUN appears", "the flame icon lights", "shown LOC".

The agent reads the display through the belief's own display rules, so a running or locked
state is only as useful as the word the belief expects for it. Manuals name that word in a few
set ways — a capitalised word that *appears*, *lights* or *is shown*, an icon or lamp named by
what it depicts, a word the display *shows* — and a sentence that ties it to the state (the
START key, "while cooking", "locked").

>>> shown_words("Touch START/STOP. HEAT appears and the time counts down.")
['HEAT']
>>> shown_words("The flame icon lights and the digits show the set temperature.")
['FLAME']
>>> shown_words("a padlock (child lock, shown LOC) appears")
['LOC']
"""

from __future__ import annotations

import re

_WORD = r"([A-Z][A-Z0-9+-]{0,11}(?: [A-Z][A-Z0-9+-]{1,9})?|[A-Z][a-z]{1,3}|[A-Z]-?[a-z])"
_PATTERNS = [
    re.compile(rf"(?:shown(?: as)?|reads?|displays?|shows?)\s+(?:the word\s+)?{_WORD}(?![\w/])"),
    re.compile(rf"(?<![\w/]){_WORD}\s+(?:appears|lights(?: up)?|is shown|is displayed|comes on"
               r"|shows in|flashes|is lit|lamp lights|indicator lights)"),
    re.compile(rf"(?<![\w/]){_WORD}\s+(?:while|during|when)\b"),
    re.compile(rf"(?<![\w/]){_WORD}\s*(?:=|:|—|–)\s*(?:\w+\s+){{0,3}}"
               r"(?:running|cooking|heating|baking|washing|active|on|locked|in progress)\b"),
]  # fmt: skip
# punctuation that separates a legend's name from its meaning ("the lock symbol – locked",
# "Heat indicator = heating"), never a lamp's glyph
NOT_GLYPHS = r"\-–—−=+<>~^&%#@$·•→←"
_ICON = re.compile(
    r"\b(?:the|a|an)?\s*([a-z]{3,12})\s+(?:icon|symbol)\b"
    r"(?:\s*\(\s*\**([^\w\s()*]{1,3}|\*{1,3}|(?-i:[A-Z]{2}[A-Z0-9-]{0,10}))\**\s*\)"
    rf"|\s+([^\w\s()*.,;:!?'\"|/{NOT_GLYPHS}]{{1,3}})(?=\s|$))?",  # "the brushing symbol ≋ lights"
    re.IGNORECASE,
)  # "the flame icon", "a padlock symbol", "the star symbol (*)": the glyph in brackets;
# a lone capital "(A)" is a figure callout, not a glyph
_NOT_WORDS = {
    "THE", "A", "AN", "AND", "OR", "IT", "IF", "TO", "NO", "ON", "OFF", "IN", "AT", "THIS",
    "WHEN", "WHILE", "PRESS", "TOUCH", "HOLD", "PUSH", "TAP", "NOTE", "TIP", "DISPLAY", "SCREEN",
    "THEN", "ALL", "EVERY", "EACH", "AFTER", "BEFORE", "ONCE", "YOU", "YOUR", "WE", "I", "ITS",
    "DURING", "SET", "SELECT", "TURN", "SWITCH",
}  # fmt: skip
_GENERIC_ICONS = {"the", "this", "that", "each", "every", "small", "little", "red", "green"}


def shown_words(text: str, keys: set[str] | None = None) -> list[str]:
    """Candidate display words in one sentence, in the order found; ``keys`` (printed key
    names) are skipped: "Press START" names a key, not what the display shows."""
    keys = {k.upper() for k in keys or set()}
    out: list[str] = []
    for pattern in _PATTERNS:
        for m in pattern.finditer(text):
            word = m.group(1).strip()
            if word.upper() in _NOT_WORDS or word.upper() in keys or word.split()[0] in _NOT_WORDS:
                continue
            if word.isdigit():
                continue
            if word not in out:
                out.append(word)
    for m in _ICON.finditer(text):
        word = m.group(1).lower()
        if m.group(3) and m.group(3) not in out:
            out.append(m.group(3))  # the glyph printed right after the icon's name
        elif (
            m.group(2)
            and m.group(2) not in out
            and (m.group(2).isupper() or not m.group(2).isalnum())
        ):
            out.append(m.group(2))  # the glyph or word printed for the icon is what shows
        elif word not in _GENERIC_ICONS and word.upper() not in out:
            out.append(word.upper())
    return out


RUNNING_CUE = re.compile(
    r"\b(?:runs?|running|cooking|heating|baking|washing|drying|in progress|is working|works"
    r"|while it works|operat\w+|started|starts|under way|brew\w*|blend\w*)\b",
    re.IGNORECASE,
)
LOCK_CUE = re.compile(r"\block(?:ed|s)?\b|\bpadlock\b", re.IGNORECASE)
