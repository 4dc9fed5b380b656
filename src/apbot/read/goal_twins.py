"""Twin settings: one setting per zone, side or drawer ("front_level" and "rear_level").

Many panels repeat a setting per cooking zone, basket or side: the same values under names that
differ only by a qualifier (``prog1``/``prog2`` labelled Z1/Z2, ``left_power``/``right_power``,
``swing_h``/``swing_v``). The rest of the parser reads a value and gives it to *a* setting of
the right kind; this module then decides *which* twin the instruction meant, from the qualifier
words around it — "the rear zone on 3", "zone 2 at 190", "the second drawer", "both sides at
900 W", "the left-right swing" — and moves or copies the value there.

A qualifier holds until the next one: in "left at 700 W with a one-and-a-half-hour timer,
right at 900 W" the timer is the left side's.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from typing import Any

from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, NumericVariable, TimeVariable
from apbot.read.goal_fit import fit
from apbot.read.goal_numbered_times import numbered_family
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model
from apbot.read.numbers import Mention

# Words that stand for one qualifier in an instruction (a model's "2" is "two", "second").
_SAME: dict[str, tuple[str, ...]] = {
    "1": ("1", "one", "first"),
    "2": ("2", "two", "second"),
    "3": ("3", "three", "third"),
    "4": ("4", "four", "fourth"),
    "rear": ("rear", "back"),
    "back": ("rear", "back"),
    "front": ("front",),
    "left": ("left",),
    "right": ("right",),
    "upper": ("upper", "top", "above"),
    "top": ("upper", "top", "above"),
    "lower": ("lower", "bottom", "below", "underneath", "beneath"),
    "bottom": ("lower", "bottom", "below", "underneath", "beneath"),
    "inner": ("inner",),
    "outer": ("outer",),
    # Channels lettered A, B ... (a TENS unit's two outputs): the letter, said after its noun.
    "a": ("a",),
    "b": ("b",),
    "c": ("c",),
    "d": ("d",),
}
_LETTERS = frozenset({"a", "b", "c", "d"})
# Two-way swings: a horizontal swing moves left and right, a vertical one up and down.
_PHRASES: dict[str, tuple[tuple[str, ...], ...]] = {
    "h": (
        ("horizontal",),
        ("left", "-", "right"),
        ("left", "and", "right"),
        ("side", "to", "side"),
    ),
    "v": (("vertical",), ("up", "-", "down"), ("up", "and", "down")),
}
PART_NOUNS = frozenset(  # parts of an appliance that each hold their own settings
    {"zone", "zones", "basket", "baskets", "drawer", "drawers", "side", "sides", "ring", "rings"}
    | {"burner", "burners", "plate", "plates", "element", "compartment", "z", "pot", "one"}
    | {"channel", "channels", "output", "outputs", "outlet", "outlets", "port", "ports"}
)
_ALL = frozenset({"both", "each"})
_BREAKS = frozenset({",", ";", ".", "!", "?", "and", "then", "while"})


@dataclass(frozen=True)
class Twins:
    """Variables that are one setting repeated; ``marks[name]`` is its own qualifier."""

    names: tuple[str, ...]
    marks: dict[str, str]
    nouns: frozenset[str]


def _tokens(text: str) -> list[str]:
    return re.findall(r"[a-z]+|\d+", text.casefold())


def _shape(model: ApplianceModel, name: str) -> str:
    """The kind of setting (type and unit): twins are one kind, named alike. Their values may
    differ (only the top element broils); a value goes only where the twin can take it."""
    var = model.variables[name]
    return json.dumps([var.type, getattr(var, "unit", "")])


_FOUND: dict[int, tuple[ApplianceModel, list[Twins]]] = {}


def find_twins(model: ApplianceModel) -> list[Twins]:
    """Groups of variables of one kind whose names differ by one qualifier each (remembered
    for the last few models)."""
    hit = _FOUND.get(id(model))
    if hit is not None and hit[0] is model:
        return hit[1]
    found = _find_twins(model)
    if len(_FOUND) >= 32:
        _FOUND.pop(next(iter(_FOUND)))
    _FOUND[id(model)] = (model, found)
    return found


def _find_twins(model: ApplianceModel) -> list[Twins]:
    by_shape: dict[str, list[str]] = {}
    for name in model.variables:
        by_shape.setdefault(_shape(model, name), []).append(name)
    groups = []
    for names in by_shape.values():
        if len(names) < 2:
            continue
        families: dict[tuple[str, ...], dict[str, str]] = {}
        for name in names:
            words = _tokens(name.replace("_", " "))
            for i, word in enumerate(words):
                if word in _SAME or word in _PHRASES:
                    key = (*words[:i], "*", *words[i + 1 :])
                    families.setdefault(key, {})[name] = word
        for key, marks in families.items():
            if len(marks) < 2 or len(set(marks.values())) != len(marks):
                continue
            labels = " ".join(model.variables[n].label or "" for n in marks)
            named = (set(key) | set(_tokens(labels))) - {"*"}
            nouns = frozenset(w for w in named if not w.isdigit()) | PART_NOUNS
            groups.append(Twins(tuple(marks), marks, nouns))
    return groups


def _marks_at(twins: Twins, text: Text) -> dict[int, str]:
    """Token index -> the twin it names ("all" for both), where the text qualifies a zone."""
    found: dict[int, str] = {}
    words = [t.text for t in text.tokens]
    n = len(words)
    for name, mark in twins.marks.items():
        for phrase in _PHRASES.get(mark, ()):
            for k in range(n - len(phrase) + 1):
                if tuple(words[k : k + len(phrase)]) == phrase:
                    for j in range(k, k + len(phrase)):
                        found[j] = name
        for k, word in enumerate(words):
            if k in found or word not in _SAME.get(mark, ()):
                continue
            numeral = word[0].isdigit() or word in ("one", "two", "three", "four")
            if numeral and (k == 0 or words[k - 1] not in twins.nouns):
                continue  # a bare number is a zone only right after a zone's noun ("zone 2")
            if word in _LETTERS and not _lettered(words, k, twins.nouns):
                continue  # "a" is an article unless a part's noun stands right before it
            found[k] = name
    for k, word in enumerate(words):
        if word in _ALL and k not in found:
            found[k] = "all"
    return found


def _lettered(words: list[str], k: int, nouns: frozenset[str]) -> bool:
    """A single letter names a lettered part right after the part's noun ("channel A"), or
    (not "a", the article) right before it ("the B channel")."""
    if k > 0 and words[k - 1] in nouns and words[k - 1] not in _LETTERS:
        return True
    return words[k] != "a" and k + 1 < len(words) and words[k + 1] in nouns


def _segments(text: Text) -> list[tuple[int, int]]:
    """Stretches of the instruction between commas, "and", "then" and sentence ends."""
    spans, start = [], 0
    for k, token in enumerate(text.tokens):
        if token.text in _BREAKS:
            if k > start:
                spans.append((start, k))
            start = k + 1
    if start < len(text.tokens):
        spans.append((start, len(text.tokens)))
    return spans


def _qualifiers(twins: Twins, text: Text) -> list[str | None]:
    """For every token, the twin its stretch of text is about (carried over until the next)."""
    marks = _marks_at(twins, text)
    out: list[str | None] = [None] * len(text.tokens)
    current: str | None = None
    for start, end in _segments(text):
        here = [(k, m) for k, m in marks.items() if start <= k < end]
        specific = sorted((k, m) for k, m in here if m != "all")
        if not here:
            for k in range(start, end):
                out[k] = current
            continue
        for k in range(start, end):
            before = [m for j, m in specific if j <= k]
            after = [m for j, m in specific if j > k]
            if before:
                out[k] = before[-1]
            elif after:
                out[k] = after[0]
            else:
                out[k] = "all"
        current = specific[-1][1] if specific else "all"
    return out


def twin_numbers(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
) -> None:
    """A bare number no setting's word stands beside, said where a twin is named ("channel A
    on five", "both channels at eight"), is that twin's: the qualifier names the setting."""
    for twins in find_twins(view.model):
        qualifiers: list[str | None] | None = None
        for mention in mentions:
            if mention.kind != "number" or any(
                k in claimed for k in range(mention.start, mention.end)
            ):
                continue
            if qualifiers is None:
                qualifiers = _qualifiers(twins, text)
            target = qualifiers[mention.start] if mention.start < len(qualifiers) else None
            if target is None:
                continue
            names = twins.names if target == "all" else (target,)
            values = {n: fit(view, view.infos[n], mention, goal) for n in names if n not in goal}
            if not values or any(v is None for v in values.values()):
                continue
            for name, value in values.items():
                goal[name] = value
                where[name] = mention.start
            claimed.update(range(mention.start, mention.end))


def place_twins(view: Model, text: Text, goal: Goal, where: dict[str, int]) -> None:
    """Move (or copy, for "both") each twin setting's value to the twin the text names."""
    for twins in find_twins(view.model):
        taken = [n for n in twins.names if n in goal and n in where]
        if not taken:
            continue
        if len(taken) >= 2 and set(twins.names) <= set(numbered_family(view)):
            continue  # times said in a row, placed in order (goal_numbered_times)
        qualifiers = _qualifiers(twins, text)
        if not any(q is not None for q in qualifiers):
            continue
        items = sorted((where[n], goal.pop(n)) for n in taken)
        placed: dict[str, tuple[int, Any]] = {}
        leftover = []
        for position, value in items:
            target = qualifiers[position] if position < len(qualifiers) else None
            if target == "all":
                for name in twins.names:
                    placed.setdefault(name, (position, value))
            elif target is not None and target not in placed:
                placed[target] = (position, value)
            elif target is not None and placed[target][1] == value:
                continue  # "the longest possible timer, 99 minutes": said twice
            else:
                leftover.append((position, value))
        free = [n for n in twins.names if n not in placed]
        for (position, value), name in zip(leftover, free, strict=False):
            placed[name] = (position, value)
        for name, (position, value) in placed.items():
            if _fits(view, name, value):
                goal[name] = value
                where[name] = position


def _fits(view: Model, name: str, value: Any) -> bool:
    """The value is one the twin can take in some case (its own programme is checked later)."""
    return str(value) in {str(v) for v in all_values(view.infos[name].var)} or isinstance(
        view.infos[name].var, NumericVariable | TimeVariable
    )
