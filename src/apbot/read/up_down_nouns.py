"""What a stepping pair moves, named by a legend that puts the noun before "up / down".

Key legends often print the pair's job as a noun and its two directions, not as a verb:
"▲ / ▼ ..... output up / down", "◄ ► — brightness down / up", "▲ / ▼  Sensitivity up and
down". :mod:`apbot.read.roles_raised` reads the verb form ("raise / lower the heat level"); this
is the one place that reads the noun form (set28b's and settings32's rules, folded), so a pair
whose noun is none the reader knows (output, brightness) keeps a setting of its own instead of
being lent whole to whatever key stands beside it. The noun must be an amount: the manual gives
it a figure somewhere ("changes the output by 10 %"), or it is a quantity noun or a noun of an
amount ("sensitivity"); a part that moves ("headrest up / down") names no setting.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_raised import after_label, an_amount, label_units, quantity_noun
from apbot.read.shapes import SETTING_NOUNS

# "output up / down", "brightness down/up", "level up / down": one or two words after the
# legend's separator (a bar, colon, dash, dots or a run of spaces), then the two directions
_UP_DOWN_RE = re.compile(
    r"(?:^\s*|[|:;—–.]\s*|\s{2,})(?P<noun>[A-Za-z][a-z-]+(?:\s+[a-z][a-z-]+)?)\s+"
    r"(?:up\s*/\s*down|down\s*/\s*up)\b"
)


# "▲ / ▼  Sensitivity up and down", "▲ / ▼ - level up / down": the quantity first, then where
# the pair moves it, with nothing but key names and signs before it (not "press ▲ to move the
# cursor up and down": prose)
_KEYS_ONLY_RE = re.compile(
    r"(?P<noun>[A-Za-z][a-z-]*(?:\s+[a-z][a-z-]*){0,2}?)\s+up\s*(?:/|,|and|or|&)\s*down\b"
)


def _keys_only(rest: str) -> re.Match[str] | None:
    """The noun of "NOUN up and down" when only key names and signs stand before it."""
    m = _KEYS_ONLY_RE.search(rest)
    if m is None or re.search(r"\b[a-z]{2,}\b", rest[: m.start()]):
        return None
    return m


# the legend's bare noun phrase: "ⓒ ▲ ▼  Speaker volume; inside a setting, …" (one to three
# words up to a stop or the end of the line, right after the pair's signs)
_BARE_RE = re.compile(r"^[^A-Za-z]*(?P<noun>[A-Za-z][a-z-]+(?:\s+[a-z][a-z-]+){0,2})\s*(?:[;.]|$)")
# the signs open the line or a sentence of it (legend lines run together when read as prose)
_LEADS_RE = re.compile(r"(?:^|[.;:!?)])[^A-Za-z]*$")
# a bare phrase names the pair's quantity only with a noun of an amount (not "Menu navigation",
# "Mode", "Programme": a list the pair walks)
_BARE_NOUNS = set(SETTING_NOUNS) - {"mode", "programme", "program", "setting"}


def _figured(b: Builder, noun: str) -> bool:
    """A sentence gives the noun a figure close after it ("changes the output by 10 %",
    "Output range | 0 – 100 %"): an amount someone sets, not a part that moves."""
    last = noun.split("_")[-1]
    near = re.compile(rf"\b{re.escape(last)}\b[^.;:\d]{{0,25}}\d", re.I)
    return any(near.search(u.text) for u in b.manual.units)


def up_down_noun(b: Builder, tokens: list[str]) -> tuple[str, int] | None:
    """The quantity the pair's own legend names before "up / down", as a variable name, with the
    unit it was read from; None when no unit naming the pair says so, when its units name two
    quantities, or when the noun is no amount (a legend's noun given no figure anywhere in the
    manual; a noun after the keys alone neither a noun of an amount nor given a figure in its
    clause)."""
    found: dict[str, int] = {}
    figured: dict[str, bool] = {}  # (a legend's noun is an amount when a figure is given it)
    for i, text, label in label_units(b, tokens):
        pos = after_label(text, label)
        k = pos - len(label) if pos else -1  # where the key's printed name starts, if there
        rest = text[pos:]
        keys = _keys_only(rest)
        if keys is not None:  # an amount by its noun, or by a figure in its own clause
            noun = quantity_noun(keys.group("noun"))
            if noun and an_amount(noun, rest[keys.start("noun") :].split(".")[0]):
                found.setdefault(noun, i)
                figured.setdefault(noun, True)
                continue
        m = _UP_DOWN_RE.search(rest)
        bare = None
        if m is None and k >= 0 and _LEADS_RE.search(text[:k]):
            bare = _BARE_RE.match(rest)  # (a legend line led by the pair's signs)
        if m is None and bare is None:
            continue
        noun = quantity_noun((m or bare).group("noun"))  # type: ignore[union-attr]
        if bare is not None and noun not in _BARE_NOUNS:
            continue
        if noun and len(words(noun.replace("_", " "))[-1]) >= 4:
            found.setdefault(noun, i)
            figured.setdefault(noun, _figured(b, noun))
    if len(found) != 1:
        return None
    noun, at = next(iter(found.items()))
    return (noun, at) if figured.get(noun, True) else None
