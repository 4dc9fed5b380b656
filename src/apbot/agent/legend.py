"""A sign the display lights for a setting's value, looked up in the manual's legend.

Manuals explain their display's signs beside the value they stand for: a legend ("♫ bell · ♪
chirp · ∅ silenced"), a table row ("∅ | SILENT | no sound"), a list of states ("off → mild
(lamp amber) → strong (lamp crimson)", "narrow (BEAM N)"), a sentence ("the star ✱ lights up:
keep warm is on"). A reader that missed the legend leaves the belief printing the value's own
word, and a walk of the setting's key then shows signs the belief cannot read (or reads as
values it does not have: ``AMBER``, ``N``). The walk itself cannot say which sign is which
value when the value it started from was a guess; the manual can. Each sign the walk showed is
looked up where the manual prints it, and the value word nearest to it there (after it, or
before the brackets it stands in) is its value; only a sign that names one value everywhere it
names any, and only signs that name different values, are kept. For an on/off setting only a
glyph (no letter or figure) counts, and only a line with the glyph, the setting's own name and
"on" (and no "off") names "on" ("on" is said of too much to stand beside a word); a sign shown
on one press and gone on the next leaves "off" printed as nothing.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterable, Sequence
from typing import Any

_WORD = re.compile(r"[^\W\d_][\w'-]*")
_TOKEN = re.compile(r"\S+")
_REACH = 3  # words between a sign and its value in a legend ("♫ BELL", "BEAM N ... narrow")
_BEFORE = 2  # words back to the value a bracketed sign belongs to ("mild (lamp amber)")


def signs(texts: Iterable[str], known: set[str]) -> list[str]:
    """The parts of ``texts`` that come and go between them (a glyph, a short word) — of one
    text, each of its parts — the belief's own words and anything with a figure left out."""
    seen = [set(_TOKEN.findall(t)) for t in dict.fromkeys(texts)]
    if not seen:
        return []
    common = set.intersection(*seen) if len(seen) > 1 else set()  # one text: each of its parts
    found = sorted({p for parts in seen for p in parts} - common)
    return [p for p in found if not any(c.isdigit() for c in p) and p.casefold() not in known]


def legend(
    manual: str, signs: Sequence[str], values: Sequence[Any], names: Iterable[str]
) -> dict[str, Any]:
    """Each sign's value where the manual's lines agree on one (sign → value), only when no
    two signs share a value. ``names``: the setting's own name words (for an on/off setting:
    a line naming it and "on" names "on")."""
    words = {str(v).casefold(): v for v in values}
    own = {n.casefold() for n in names}
    switch = set(words) == {"on", "off"}
    found: dict[str, Any] = {}
    for sign in signs:
        if switch and any(c.isalnum() for c in sign):
            continue
        votes: Counter[str] = Counter()
        for line in manual.splitlines():
            for match in _occurrences(sign, line):
                # a switch's "on" is said of anything: only a glyph's line naming the setting
                vote = _switched(line, own) if switch else _nearest(line, match, words)
                if vote is not None:
                    votes[vote] += 1
        if len(votes) == 1:
            found[sign] = words[next(iter(votes))]
    if len(set(map(str, found.values()))) != len(found):
        return {}
    return found


def _occurrences(sign: str, line: str) -> list[re.Match[str]]:
    flags = re.IGNORECASE if len(sign) > 2 and sign.isalpha() else 0
    return list(re.finditer(rf"(?<![\w]){re.escape(sign)}(?![\w])", line, flags))


def _nearest(line: str, match: re.Match[str], words: dict[str, Any]) -> str | None:
    """The value the sign at ``match`` stands for on ``line``: the one before the brackets
    it stands in, else the first after it within a few words, else the one right before it.
    A value of several words ("out only") counts only said whole."""
    before, after = line[: match.start()], line[match.end() :]
    opened = before.rfind("(")
    if opened > before.rfind(")"):  # "mild (lamp amber)": the bracket belongs to "mild"
        return _said(_tail(before[:opened], _BEFORE), words, last=True)
    return _said(_head(after, _REACH), words) or _said(_tail(before, 1), words, last=True)


def _head(text: str, count: int) -> str:
    """``text`` up to the end of its ``count``-th word."""
    ends = [m.end() for m in _WORD.finditer(text)][:count]
    return text[: ends[-1]] if ends else ""


def _tail(text: str, count: int) -> str:
    """``text`` from the start of its ``count``-th word from the end."""
    starts = [m.start() for m in _WORD.finditer(text)][-count:]
    return text[starts[0] :] if starts else ""


def _said(window: str, words: dict[str, Any], last: bool = False) -> str | None:
    """The value said in ``window``, whole (the first, or the ``last``); a single word may be
    said in a longer form ("silenced" for silence)."""
    found: list[tuple[int, str]] = []
    for value in words:
        if not value.strip():
            continue
        for m in re.finditer(rf"(?<!\w){re.escape(value)}(?!\w)", window, re.IGNORECASE):
            found.append((m.start(), value))
    for m in _WORD.finditer(window):
        if (longer := _value(m.group(0), words)) is not None:
            found.append((m.start(), longer))
    if not found:
        return None
    return max(found)[1] if last else min(found)[1]


def _value(word: str, words: dict[str, Any]) -> str | None:
    """The single-word value ``word`` names: itself, or a longer form of it ("silenced" for
    silence)."""
    folded = word.casefold()
    if folded in words:
        return folded
    hits = [w for w in words if len(w) >= 4 and folded.startswith(w) and len(folded) - len(w) <= 2]
    return hits[0] if len(hits) == 1 else None


def _switched(line: str, own: set[str]) -> str | None:
    """ "on" for a line that names the setting and says it is on, and not off."""
    said = {w.casefold() for w in _WORD.findall(line)}
    if own and own <= said and "on" in said and "off" not in said:
        return "on"
    return None
