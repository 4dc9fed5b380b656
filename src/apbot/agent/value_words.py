"""How a word a display lights names a value: its own word, an abbreviation of it, a switch's
mark, or (for an on/off setting) the setting's own name lit.

Shared by the display learner and the renaming walk, which both match shown words against the
values of the one setting whose key was pressed.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

_OFF = {"off", "no", "none", "0", "false"}
_MARKS = {"on": {"on", "i", "1", "|"}, "off": {"off", "0", "o"}}


def spells_value(said: str, value: Any) -> bool:
    """Whether a shown word is the value's own word or an abbreviation of it (``DIST`` for
    distance), or the mark a switch prints for it (``I`` / ``0`` for on / off).

    >>> spells_value("dist", "distance"), spells_value("i", "on"), spells_value("std", "on")
    (True, True, False)
    """
    said, word = said.strip().casefold(), str(value).casefold()
    return (len(said) >= 2 and word.startswith(said)) or said in _MARKS.get(word, set())


def names_value(spec: Any, name: str, word: str, value: Any, domain: Sequence[Any]) -> bool:
    """Whether a display word says by itself that it shows ``value``: the value's own word or
    an abbreviation of it (``ECO`` for eco, ``I`` for on), or, for the one value of an on/off
    setting that is not "off", the setting's own name or a word of its label lit (``GLOW`` for
    a night glow). A word like neither (``STD``) could show either value.

    >>> names_value(None, "glow", "GLOW", "on", ["off", "on"])
    True
    >>> names_value(None, "boost", "STD", "on", ["off", "on"])
    False
    """
    said, word_of = word.strip().casefold(), str(value).casefold()
    if spells_value(said, value):
        return True
    if word_of in _OFF or not any(str(v).casefold() in _OFF for v in domain):
        return False
    label = str(spec.display_label(name)) if spec is not None else name
    own = {w.casefold() for w in re.split(r"[\W_]+", f"{label} {name}") if len(w) >= 2}
    parts = [w for w in re.split(r"[\W_]+", said) if w]
    if bool(parts) and all(p in own for p in parts):
        return True
    whole = {re.sub(r"[\W_]+", "", t.casefold()) for t in (label, name)}
    return len(parts) == 1 and any(_abbreviates(parts[0], w) for w in own | whole)


def _abbreviates(short: str, word: str) -> bool:
    """Whether ``short`` abbreviates ``word`` as panels print a setting's name: its first
    letter, then letters of it in order (``LD`` for lockdown, ``SF`` for superfreeze) — looser
    than the goal parser's ``goal_vocab.cut_short`` (a word's start), because here a lit word is
    only matched against the one setting whose key was pressed.

    >>> _abbreviates("ld", "lockdown"), _abbreviates("std", "boost"), _abbreviates("dl", "lockdown")
    (True, False, False)
    """
    if not 2 <= len(short) < len(word) or not short.isalpha() or short[0] != word[0]:
        return False
    rest = iter(word[1:])
    return all(c in rest for c in short[1:])
