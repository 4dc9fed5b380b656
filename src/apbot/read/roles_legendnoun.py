"""The noun two stepping keys' legends share: what the pair itself sets.

A key legend often gives each key of a pair the same noun with opposite words around it:
"▲  custom target one step up" / "▼  custom target one step down", "◄  previous melody" /
"►  next melody", "−  shorter wait" / "+  longer wait". What the two legends have in common,
once the words of direction are taken away, names the setting the pair moves — even when
that noun is none the reader knows as an amount (target, melody, wait), and even when the
same pair also serves settings other keys open ("; in the night period: one hour earlier").
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_raised import quantity_noun

# words saying which way a key moves, or how far: not what it moves
_WAY = {
    "up", "down", "next", "previous", "prev", "higher", "lower", "more", "less", "longer",
    "shorter", "larger", "smaller", "bigger", "increase", "increases", "decrease",
    "decreases", "raise", "raises", "lowers", "reduce", "reduces", "earlier", "later",
    "forward", "forwards", "back", "backward", "backwards", "faster", "slower", "warmer",
    "cooler", "hotter", "colder", "one", "step", "steps", "by", "the", "a", "an", "to", "of",
    "plus", "minus", "go", "goes", "move", "moves", "select", "selects", "choose", "chooses",
    "each", "press", "per", "left", "right", "stronger", "weaker", "louder", "softer",
}  # fmt: skip
# words describing the printed sign in a legend column, not what the key does
_SHAPES = {"arrow", "arrows", "symbol", "icon", "triangle", "pointing", "key", "button", "sign"}


def legend_noun(b: Builder, up: list[str], down: list[str]) -> str:
    """The noun the legends of the pair's two keys share ("target", "melody", "wait") as a
    variable name, or "" when the two keys have no legend of their own or share none."""
    ups = [_clauses(b, t) for t in up]
    downs = [_clauses(b, t) for t in down]
    if not ups or not downs or not all(ups) or not all(downs):
        return ""
    nouns = {_shared(a, z) for a in ups for z in downs}
    if len(nouns) != 1:
        return ""
    return nouns.pop()


def _clauses(b: Builder, token: str) -> list[list[str]]:
    """The first clause of each column of the key's own legend line (a table row whose cell is
    the key's sign alone, or a line that starts with the sign), as words; [] when none."""
    lab = b.labels.get(token)
    if lab is None or not lab.text:
        return []
    sign = re.escape(lab.text)
    alone = re.compile(rf"^\W*(?:[a-z0-9]{{1,2}}\W+)?{sign}\W*$", re.I)  # "D ▲", "(3) [▲]"
    lead = re.compile(rf"^\s*{sign}\s+(?=\w)", re.I)
    for i in lab.mentions:
        unit = b.manual.units[i]
        texts: list[str]
        if unit.cells:
            at = [k for k, c in enumerate(unit.cells) if alone.match(c.strip())]
            if len(at) != 1 or len(unit.cells) > 4:
                continue
            texts = list(unit.cells[at[0] + 1 :])
        elif re.search(sign, unit.text) is None:
            texts = [unit.text]  # the sign led the line and was taken as its bullet ("► next …")
        elif (m := lead.match(unit.text)) is not None:
            texts = [unit.text[m.end() :]]
        else:
            continue
        found = [words(re.split(r"[;,/(:]|\bor\b|\s[–—-]\s", t, maxsplit=1)[0]) for t in texts]
        if found and 2 <= len(found[0]) <= 6:
            return found
    return []


def _shared(up: list[list[str]], down: list[list[str]]) -> str:
    """The words both keys' clauses of one column hold, directions taken away (the first
    column that gives a setting's name): a name of one or two words."""
    for a, z in zip(up, down, strict=False):
        if a == z or len(a) < 2:
            continue  # one legend for both, or no words to compare
        common = [w for w in a if w in z and w not in _WAY and w.isalpha()]
        if not common or len(common) > 2 or set(common) & _SHAPES:
            continue  # ("arrow pointing left": the sign described, not its use)
        if not (set(a) - set(common) - {"the", "a", "an"}):
            continue  # no word of direction at all: not a pair's legend
        return quantity_noun(" ".join(common))
    return ""
