"""Keys printed as an icon only, named by the legend line the icon leads.

A panel of touch keys may carry pictures and no words ("❋", "☾", "◷"), and its manual give a
legend line per picture: "❋ — fan speed. Each touch: 1 → 2 → 3 → TURBO → 1." The reader drops
pictographs, so the line would lose its key. When the line's first clause starts with the words
of exactly one of the panel's keys (the action's ``fan``), the icon is that key: written as the
key's name in capitals wherever it stands, the legend line and every step that uses the icon
name the key as a printed name would.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from apbot.read.marks_legend import legend_meanings
from apbot.read.text_icons import _icon, _put

# the icon leading a line (after any callout mark "(B)" or bullet), a dash, colon or gap (not
# "=", which a legend of chart marks uses), and the first clause of what it does; after a
# callout mark one space will do when a capitalised name ends there ("(D) ☾ Backlight.")
_SIGN_LINE = re.compile(
    r"^[ \t]*(?:\(?[A-Za-z0-9]\)[ \t]*|[\u2460-\u2473][ \t]*|[•*-][ \t]+)?"  # ("⑤" too)
    r"(\S)\ufe0f?[ \t]*(?:[—–:-]+|[ \t]{2,}|(?<=\)[ \t]\S)[ \t](?=[A-Z][a-z]+\.))[ \t]*"
    r"([^.;:\n]+)",
    re.M,
)


_LEADS = frozenset({"the", "a", "an"})


def _words(text: str) -> list[str]:
    return re.findall(r"[a-z0-9]+", text.lower())


def name_signed_keys(text: str, keys: Sequence[str], keep: frozenset[str]) -> str:
    """The text with each icon a legend line ties to one key written as that key's name."""
    tokens = {k: _words(k.replace("_", " ")) for k in keys if _words(k.replace("_", " "))}
    if not tokens:
        return text
    marks = set(legend_meanings(text))  # "● = reminder starts ON": a chart's mark, no key
    named: dict[str, set[str]] = {}
    for m in _SIGN_LINE.finditer(text):
        icon = m.group(1)
        if not _icon(icon, keep) or icon in marks:
            continue
        said = _words(m.group(2))
        while said and said[0] in _LEADS:
            said = said[1:]
        # the key's words lead the clause ("❋ — fan speed"); a line of display symbols names
        # what the symbol shows after saying what it looks like ("◐  half-sun symbol  WARM
        # mode", "∞  infinity symbol  continuous operation"): no key of its own
        fits = {k for k, ws in tokens.items() if said[: len(ws)] == ws}
        # ("(D) ☾ Backlight." for ``light``: the key's one word closing the legend's noun)
        fits = fits or {k for k, ws in tokens.items() if _closes(said, ws)}
        named.setdefault(icon, set()).update(fits)
    names = {
        icon: next(iter(ks)).replace("_", " ").upper() for icon, ks in named.items() if len(ks) == 1
    }
    names.update(_last_left(text, tokens, named))
    if len(set(names.values())) != len(names):
        return text  # two icons for one key: which is which is not told
    lines = text.split("\n")
    for icon, name in names.items():
        lines = [_put(line, icon, name) if icon in line else line for line in lines]
    return "\n".join(lines)


def _closes(said: list[str], ws: list[str]) -> bool:
    """Whether the clause is one compound noun ending in the key's one word ("backlight" for
    ``light``, "nightlight"), at least three letters before it."""
    return (
        len(ws) == 1
        and len(said) == 1
        and said[0].endswith(ws[0])
        and len(said[0]) >= len(ws[0]) + 3
    )


def _last_left(
    text: str, tokens: dict[str, list[str]], named: dict[str, set[str]]
) -> dict[str, str]:
    """The one legend icon no key's words name, given to the one key the manual never names in
    words ("⑤ ⏰ — reminder." on a panel whose actions include ``timer``, a word the manual
    never prints): the legend draws every key, so the icon left over is the key left over. Only
    an icon a step presses, or one in the block of the keys' legend lines, counts: a warning
    sign's line ("⚠ — hot surface") is no key's."""
    unnamed = [icon for icon, ks in named.items() if not ks and _worked(text, icon, named)]
    said = set(_words(text))
    unseen = [k for k, ws in tokens.items() if not set(ws) & said]
    if len(unnamed) != 1 or len(unseen) != 1:
        return {}
    return {unnamed[0]: unseen[0].replace("_", " ").upper()}


_PRESS_RE = r"\b(?:press|touch|tap|push|hold)\s+(?:the\s+)?"


def _worked(text: str, icon: str, named: dict[str, set[str]]) -> bool:
    """Whether the icon is a key's: a step presses it ("Touch ⌛"), or its legend line stands
    in one block (no blank line between) with a line whose icon names a key."""
    if re.search(_PRESS_RE + re.escape(icon), text, re.I):
        return True
    keyed = {i for i, ks in named.items() if ks}
    for block in re.split(r"\n[ \t]*\n", text):
        signs = {m.group(1) for m in _SIGN_LINE.finditer(block)}
        if icon in signs and signs & keyed:
            return True
    return False
