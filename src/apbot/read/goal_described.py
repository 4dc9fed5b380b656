"""Settings named by what the manual says they do: "without the fruit-and-nut beep" for an
ADD-IN key whose legend reads "Beep for adding fruit and nuts".

A user often says what they want done, not the panel's name for it, and a robot holding the
manual can look the words up there. Only legend lines count (a value's or a key's name opening
a line, then its first sentence; :func:`apbot.read.goal_manual.descriptions`), and a setting is
named only by three of its description's words close together that no other description, no
setting and no value of the model uses (so "the fan speed" never names what "FAN  Switches the
fan speed" says), and only when one description alone fits best; a key that does two jobs is
described for neither.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from apbot.read.goal_manual import LEGEND_VERBS, descriptions
from apbot.read.goal_text import Text, negated_before, negative_around
from apbot.read.goal_view import Goal, Model
from apbot.read.goal_vocab import STOP_WORDS, concept, stem
from apbot.read.numbers import tokenize

WINDOW = 6
"""Tokens the description's words may spread over in the instruction."""

MIN_WORDS = 3
"""Of the description's own words, found in that stretch: two named settings nobody asked for."""

_COMMON = frozenset(
    {"you", "your", "yours", "them", "they", "their", "its", "are", "was", "were", "has", "have"}
    | {"make", "makes", "keep", "keeps", "set", "sets", "put", "get", "use", "used", "uses"}
    | {"run", "runs", "start", "starts", "stop", "stops", "one", "two", "unit", "appliance"}
    | {"after", "before", "until", "when", "while", "then", "than", "more", "less", "also"}
    | {"can", "will", "not", "all", "any", "some", "each", "every", "here", "there", "other"}
)


@dataclass(frozen=True)
class Described:
    var: str
    value: Any
    words: frozenset[str]  # stems of its description's words no other description, setting
    # or value of the model has


_CACHE: dict[int, tuple[Model, list[Described]]] = {}


def _described(view: Model) -> list[Described]:
    """The model's values and switches with the manual's description of each, remembered."""
    hit = _CACHE.get(id(view))
    if hit is not None and hit[0] is view:
        return hit[1]
    names: dict[str, list[tuple[str, Any]]] = {}
    for name, info in view.infos.items():
        if info.role == "switch" and info.on is not None:
            for label in view.switch_keys.get(name, []):
                names.setdefault(label, []).append((name, info.on))
        elif info.role == "setting" and info.var.type == "discrete":
            for value in info.values:
                if isinstance(value, str) and any(c.isalpha() for c in value):
                    names.setdefault(value, []).append((name, value))
    names = {name: homes for name, homes in names.items() if len(set(homes)) == 1}
    used = {s for _var, _value, stems, _weight in view.phrases for s in stems}
    vocab = {key for info in view.infos.values() for key in info.vocab}
    found: dict[tuple[str, Any], set[str]] = {}
    for var, value, sentence in descriptions(view.manual, names):
        words = {
            t.text
            for t in tokenize(sentence)
            if t.text.isalpha() and len(t.text) >= 3 and t.text not in STOP_WORDS | _COMMON
        }
        found.setdefault((var, value), set()).update(words - LEGEND_VERBS)
    seen: dict[str, int] = {}
    for words in found.values():
        for key in {stem(w) for w in words}:
            seen[key] = seen.get(key, 0) + 1
    out: list[Described] = []
    for (var, value), words in found.items():
        own = frozenset(
            stem(w)
            for w in words
            if stem(w) not in used and concept(w) not in vocab and seen[stem(w)] == 1
        )
        if len(own) >= MIN_WORDS:
            out.append(Described(var, value, own))
    if len(_CACHE) >= 32:
        _CACHE.pop(next(iter(_CACHE)))
    _CACHE[id(view)] = (view, out)
    return out


def _same(a: str, b: str) -> bool:
    """One word inflected or derived ("circulate", "circulation"): a long common start."""
    if a == b:
        return True
    common = 0
    for x, y in zip(a, b, strict=False):
        if x != y:
            break
        common += 1
    return common >= 6 and common >= 0.75 * min(len(a), len(b))


def _best_window(text: Text, claimed: set[int], item: Described) -> tuple[int, int] | None:
    """(words found, first token) of the densest stretch of the description's words."""
    hits = [
        (k, next(w for w in item.words if _same(text.stems[k], w)))
        for k in range(len(text.tokens))
        if k not in claimed
        and text.word(k) not in STOP_WORDS
        and any(_same(text.stems[k], w) for w in item.words)
    ]
    best: tuple[int, int] | None = None
    for i, (k, _word) in enumerate(hits):
        found = {w for j, w in hits[i:] if j - k < WINDOW}
        if len(found) >= MIN_WORDS and (best is None or len(found) > best[0]):
            best = (len(found), k)
    return best


def described_settings(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Set what the instruction names by the manual's description of it (see the module)."""
    if not view.manual:
        return
    scored: dict[str, list[tuple[int, int, Any]]] = {}
    for item in _described(view):
        if item.var in goal:
            continue
        found = _best_window(text, claimed, item)
        if found is not None:
            scored.setdefault(item.var, []).append((found[0], found[1], item.value))
    for var, options in scored.items():
        options.sort(key=lambda o: -o[0])
        count, k, value = options[0]
        if any(o[0] == count and o[2] != value for o in options[1:]):
            continue  # two descriptions fit as well: the words name neither
        info = view.infos[var]
        if info.role == "switch":
            goal[var] = info.off if negative_around(text, k) else value
        elif negated_before(text, k):
            continue
        else:
            goal[var] = value
        where[var] = k
