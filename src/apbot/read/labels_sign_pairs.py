"""Keys printed as a setting's name and an arrow or sign ("SPEED ▲", "TIME ▲", "TEMP ▲"): a
sentence with the bare sign names only the pair whose name it also says.

A panel with one pair of arrows is mentioned by every "▲" of its manual. A panel with a pair
per setting ("Each value has its own pair of arrow keys") is not: "Use TIME ▲ and TIME ▼" is
the time's pair, and taking it for the speed's pair lent the speed the run time's range.
"""

from __future__ import annotations

import re

from apbot.read.labels import SYMBOLS, Label, words
from apbot.read.text import Unit

_SIGNS = frozenset(s for group in SYMBOLS.values() for s in group if not s.isalnum())


def _sign_of(text: str) -> tuple[str, str] | None:
    """The name and the sign of a label printed "NAME ▲" (a name of letters, then one sign)."""
    m = re.fullmatch(r"([A-Za-z][A-Za-z .'-]*?)\s?(\S)", text.strip())
    if m is None or m.group(2) not in _SIGNS or not words(m.group(1)):
        return None
    if max(len(w) for w in words(m.group(1))) < 3:
        return None  # a channel's letter ("A ▲", "B ▲"): too short to tell its sentences apart
    return m.group(1), m.group(2)


def narrow_sign_pairs(units: list[Unit], labels: dict[str, Label]) -> None:
    """Where two or more labels share a sign under different names, drop each one's mentions
    that say neither its name (or a word it abbreviates: TEMP in "temperature") nor its whole
    label: those sentences name the sign of another pair."""
    signed = {
        t: s for t, lab in labels.items() if lab.line is not None and (s := _sign_of(lab.text))
    }
    by_sign: dict[str, set[str]] = {}
    for name, sign in signed.values():
        by_sign.setdefault(sign, set()).add(name.upper())
    for token, (name, sign) in signed.items():
        if len(by_sign[sign]) < 2:
            continue
        # a name of four letters or more may be shortened (TEMP for "temperature"); a
        # shorter one ("FAN") is said whole
        said = [rf"{re.escape(w)}\w*" if len(w) >= 4 else rf"{re.escape(w)}\b" for w in words(name)]
        own = re.compile(r"\b(?:" + "|".join(said) + r")", re.IGNORECASE)
        label = labels[token]
        kept = {i for i in label.mentions if own.search(units[i].text)}
        # a sentence or row led by the setting's name ("Steeping time: 1 to 10 minutes") is
        # about the pair as surely as the bare sign was
        led = re.compile(r"^\W*(?:" + "|".join(said) + r")\b", re.IGNORECASE)
        kept |= {i for i, u in enumerate(units) if led.match(u.text)}
        label.mentions = sorted(kept)
