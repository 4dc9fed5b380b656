"""Names a display spells otherwise than the belief: shorter or longer, or inside a longer one.

Manuals and panels name the same choice in different lengths: the manual's "3 hone" is
``STAGE 3`` on the panel, its "conv bake" is ``convection bake``. The display reader
(:mod:`apbot.agent.reader`) reads such a text as the one value it spells, and reads no value out
of a longer name it merely ends (``bake`` inside ``convection bake``).
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, DiscreteVariable

_WORD_BEFORE = re.compile(r"(?:^|\s)([^\W\d_]{2,}) $")  # a word one space before the end
_WORD = re.compile(r"[^\W\d_]+")


def spelt_otherwise(text: str, values: tuple[Any, ...] | list[Any]) -> Any | None:
    """The one value of a choice that ``text`` spells in the other length: panels print a
    long name short (``3`` for "3 hone", ``conv bake`` for "convection bake") and manuals do
    too, the other way round. Word by word, each is the other's start (a figure whole, a word
    cut to two letters at least), and one list of words begins the other; a name of two words
    or more on one side (one word for another is an abbreviation, which the walk learns as the
    value's word: :mod:`apbot.agent.renamed`). None when no value or several fit.

    >>> spelt_otherwise("STAGE 3", ["1 coarse", "3 hone"]) is None
    True
    >>> spelt_otherwise("3", ["1 coarse", "2 fine", "3 hone"])
    '3 hone'
    >>> spelt_otherwise("convection bake", ["bake", "conv bake", "broil"])
    'conv bake'
    >>> spelt_otherwise("low", ["low fan", "low heat"]) is None
    True
    """
    shown = text.casefold().split()
    found = [
        value
        for value in values
        if isinstance(value, str) and _same_words(shown, value.casefold().split())
    ]
    return found[0] if len(found) == 1 else None


def _same_words(shown: list[str], named: list[str]) -> bool:
    if not shown or not named or shown == named or len(shown) + len(named) < 3:
        return False  # one word for one word is an abbreviation, learnt as such elsewhere
    for a, b in zip(shown, named, strict=False):
        short, long = sorted((a, b), key=len)
        if short == long:
            continue
        if not (short.isalpha() and len(short) >= 2 and long.startswith(short)):
            return False
    return True


def ends_longer_name(before: str, values: dict[str, Any], known: set[str]) -> bool:
    """Whether a choice of ``values`` read inside a longer display is the last word of a longer
    name: the text ``before`` it ends in a word none of ``known`` (the belief's words), one
    space apart — displays part their screens by wider gaps, and a name qualifies its head word
    from the front. The name is one the belief lacks or spells otherwise, for the loose screens
    (and a walk) to read.

    >>> ends_longer_name("FUNCTION convection ", {"function": "bake"}, {"function"})
    True
    >>> ends_longer_name("FUNCTION ", {"function": "bake"}, {"function"})
    False
    """
    word = _WORD_BEFORE.search(before)
    if word is None or word.group(1).casefold() in known:
        return False
    return any(isinstance(v, str) and v[:1].isalpha() for v in values.values())


def known_words(model: ApplianceModel) -> set[str]:
    """Every word ``model`` prints or names: labels, show texts, values, guard messages."""
    texts: list[str] = [model.display.idle or ""]
    for name, spec in model.variables.items():
        texts += [name, str(spec.display_label(name))]
        show = getattr(spec, "show", None)
        texts += list(show.values()) if isinstance(show, dict) else [str(show or "")]
        if isinstance(spec, DiscreteVariable):
            texts += [str(v) for v in all_values(spec)]
    texts += [str(g.display or "") for g in model.guards]
    return {w.casefold() for t in texts for w in _WORD.findall(t)}
