"""The ends of a numbered scale by the superlatives the manual gives them: "the finest setting".

A dial of numbered positions says in its manual which end is which — "1 (finest) to 12
(coarsest)", a chart row "12 | F12 | cracked (coarsest)" — and the order of the numbers does
not tell it (1 is the finest grind, the *lowest* number). People ask for "the coarsest
setting", "the second finest". A superlative the manual puts in brackets right after an end
number of exactly one number setting (or in a table row that opens with that number) names
that end; an ordinal before it counts in from that end ("the second finest" is 2).
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import DiscreteVariable, NumericVariable
from apbot.read.goal_ordinals import ORDINALS
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model, own_stems
from apbot.read.goal_vocab import stem

# (a code's letters before the number, "l16 (hardest)", are kept to tell whose number it is)
_AFTER_NUMBER = re.compile(r"(?<![\w.,])([a-z]{0,2})(\d+)\s*\(\s*([a-z]+est)\s*\)")
# "from 2 seconds (the fastest feed) to 10 seconds (the slowest)": a unit after the number,
# "the" and the noun the superlative is said of inside the bracket
_AFTER_QUANTITY = re.compile(
    r"(?<![\w.,])()(\d+)\s+[a-z]{1,8}\s*\(\s*the\s+([a-z]+est)(?:\s+([a-z]{3,}))?\s*\)"
)
_ROW = re.compile(r"^\s*\|?\s*(\d+)\s*\|")
_IN_BRACKETS = re.compile(r"\(\s*([a-z]+est)\s*\)")
_SAME = {"quickest": "fastest", "speediest": "fastest", "fastest": "quickest"}
"""Superlatives said for the one the manual prints."""
_NOT_SUPERLATIVES = frozenset({"latest", "request", "interest", "suggest", "honest", "modest"})


def _marked(view: Model) -> dict[str, tuple[str, list[float], int, str]]:
    """superlative -> (setting, its values in order, index of the end it names, the noun the
    manual says it of, "" for none)."""
    ends: dict[float, list[tuple[str, list[float]]]] = {}
    for name, info in view.infos.items():
        if isinstance(info.var, NumericVariable) and info.role == "setting":
            values = sorted({float(v) for v in all_values(info.var)})
            if len(values) >= 3:
                for end in (values[0], values[-1]):
                    ends.setdefault(end, []).append((name, values))
    found: dict[str, set[tuple[str, float]]] = {}
    nouns: dict[str, set[str]] = {}
    joined = " ".join(" ".join(line.split()) for line in view.manual_lines)  # a bracket may
    # span two lines: "" stands for the whole text, read for a quantity's bracket
    quantities = [(m[1], m[2], m[3], m[4] or "") for m in _AFTER_QUANTITY.finditer(joined)]
    for line in ["", *view.manual_lines]:
        pairs = [] if line else list(quantities)
        pairs += [(m[1], m[2], m[3], "") for m in _AFTER_NUMBER.finditer(line)]
        row = _ROW.match(line)
        if row and not _names_a_word_value(view, line):
            pairs += [("", row[1], m[1], "") for m in _IN_BRACKETS.finditer(line)]
        for code, number, word, noun in pairs:
            if len(word) < 6 or word in _NOT_SUPERLATIVES:
                continue  # "(best)", "(latest)": no end of an order
            for name, _values in ends.get(float(number), []):
                if code and not any(w.startswith(code) for w in own_stems(view.infos[name])):
                    continue  # "P9 (gentlest)": a programme's code, no end of the DELAY 1-9
                found.setdefault(word, set()).add((name, float(number)))
                nouns.setdefault(word, set()).add(noun)
    out: dict[str, tuple[str, list[float], int, str]] = {}
    for word, places in found.items():
        if len(places) != 1:
            continue  # two settings end in the same number: which is meant is not said
        ((name, value),) = places
        owners = [values for owner, values in ends[value] if owner == name]
        values = owners[0]
        noun = next(iter(nouns[word])) if len(nouns[word]) == 1 else ""
        out[word] = (name, values, values.index(value), noun)
    return out


def _names_a_word_value(view: Model, line: str) -> bool:
    """A table row one of whose cells is a worded value of a setting ("| 9 | Wool | cold
    (gentlest) |"): a row of that setting's table (a programme chart), whose opening number
    counts the rows — no position of a number setting."""
    cells = {cell.strip() for cell in line.split("|")}
    return any(
        str(value).casefold() in cells
        for info in view.infos.values()
        if isinstance(info.var, DiscreteVariable)
        for value in info.values
        if str(value).isalpha() and len(str(value)) > 2
    )


def of_another(view: Model, text: Text, k: int, name: str) -> bool:
    """ "the highest temperature" where the manual marks a SPEED's 5 (highest): the word after
    the superlative names another setting, whose end is meant."""
    key = text.concepts[k + 1] if k + 1 < len(text.concepts) else ""
    return bool(key) and any(
        other != name and info.vocab.get(key, 0.0) >= 0.8 and key not in view.infos[name].vocab
        for other, info in view.infos.items()
    )


def marked_ends(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """ "the coarsest setting" as 12 where the manual marks 12 (coarsest)."""
    if not any(w.endswith("est") for w in (t.text.casefold() for t in text.tokens)):
        return
    marked = _marked(view)
    if not marked:
        return
    for k, token in enumerate(text.tokens):
        word = token.text.casefold()
        word = word if word in marked else _SAME.get(word, word)
        if word not in marked or k in claimed:
            continue
        name, values, index, noun = marked[word]
        if name in goal or of_another(view, text, k, name):
            continue
        if noun and text.stems[k + 1 : k + 2] != [stem(noun)]:
            continue  # "(the fastest feed)": "the fastest balls" may be the speed's top
        before = text.word(k - 2) if text.word(k - 1) == "-" else text.word(k - 1)
        step = ORDINALS.get(before, 1) - 1
        index = index + step if index == 0 else index - step
        if not 0 <= index < len(values):
            continue
        value = values[index]
        goal[name] = int(value) if value.is_integer() else value
        claimed.add(k)
        where[name] = k
