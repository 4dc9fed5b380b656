"""Other names a manual gives a value in brackets: "12V COLD … (winter mode)", "CLASSIC (plain,
salted)", "CO (continuous)". Manuals put a programme's everyday name in brackets right after
its panel name (written as the panel writes it), or alone on the line below its row; a user
says the everyday name ("winter mode", "plain popcorn"), so the goal parser names the value by
it too. A superlative ("SYNTH (coolest)") says where it sits on a scale, and a count noun
("PIZZA (slice)") how it is counted, not what it is.

>>> manual = "  NORMAL   12 V\\n  COLD     below 5 °C\\n  (winter)\\nthe NORMAL (everyday) mode"
>>> sorted(bracket_aliases({"mode": {"normal": ["normal"], "cold": ["cold", "12V COLD"]}}, manual))
[('mode', 'cold', ('winter',)), ('mode', 'normal', ('everyday',))]
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.goal_values import kind_noun
from apbot.read.goal_vocab import STOP_WORDS, concept, stem
from apbot.read.numbers import COUNT_NOUNS

_BRACKET = re.compile(r"\(([^()]{3,40})\)")
_SPLIT = re.compile(r",|/|;|\bor\b")
_NOT_NAMES = frozenset(
    {"default", "optional", "recommended", "only", "see", "page", "factory", "standard", "basic"}
    | {"approx", "max", "min", "maximum", "minimum", "example", "e", "g", "eg", "ie", "not"}
    | {"all", "each", "every", "and", "with", "without", "models", "model", "note", "off", "on"}
)
_COMPOUND = re.compile(r"[a-z]+-[a-z]+", re.IGNORECASE)
MAX_ALIAS_WORDS = 2
"""Words of one bracketed name (more is a remark, not a name)."""


def bracket_aliases(
    forms: dict[str, dict[Any, list[str]]],
    manual: str,
    settings: tuple[str, ...] = (),
    appliance: frozenset[str] = frozenset(),
) -> list[tuple[str, Any, tuple[str, ...]]]:
    """(setting, value, stems) for each name a bracket gives one value. ``forms``: setting ->
    value -> the texts it is written as (its name, its display text); ``settings``: the
    names of every setting. A name two values would share, or one with a word of a value's
    own name or of a setting's name ("AUTO (humidity)": what AUTO follows, not AUTO), is
    dropped. A word of ``appliance`` (the concepts that name the appliance) is left out of a
    name as a kind noun is: "M (manual flash)" on a flash names M "manual"."""
    if not manual:
        return []
    lines = manual.splitlines()
    own = {
        stem(w)
        for values in forms.values()
        for texts in values.values()
        for t in texts
        for w in _words(t)
    } | {stem(w) for name in settings for w in _words(name)}
    found: dict[tuple[str, ...], set[tuple[str, Any]]] = {}
    for name, values in forms.items():
        for value, texts in values.items():
            for text in {t.strip() for t in texts}:
                if not any(c.isalpha() for c in text) or (len(text) < 2 and not text.isupper()):
                    continue
                for alias in _aliases(text, lines, appliance):
                    stems = tuple(stem(w) for w in alias)
                    if stems and not set(stems) & own:
                        found.setdefault(stems, set()).add((name, value))
    return [(n, v, stems) for stems, said in found.items() if len(said) == 1 for n, v in said]


def _aliases(text: str, lines: list[str], appliance: frozenset[str]) -> list[list[str]]:
    """The bracketed names of ``text`` in the manual: right after it on its line, or alone
    on the next line, in its column or under the row it opens. A one-letter code ("M") only
    where it opens its line, as a heading does: in prose a letter is too often something
    else."""
    said = re.compile(rf"(?<![\w-]){re.escape(text)}(?![\w-])", re.IGNORECASE)
    out: list[list[str]] = []
    for index, line in enumerate(lines):
        for match in said.finditer(line):
            if match[0] != match[0].upper():
                continue  # as the panel writes it ("COLD"), not a word of the prose ("cold")
            if len(text) < 2 and line[: match.start()].strip():
                continue
            after = _BRACKET.match(line, _skip_spaces(line, match.end()))
            if after is not None:
                out += _names(after[1], appliance)
                continue
            below = lines[index + 1] if index + 1 < len(lines) else ""
            alone = _BRACKET.fullmatch(below.strip())
            if alone is None:
                continue
            opens = not line[: match.start()].strip()  # the row's own name: all it says is its
            if opens or abs(below.index("(") - match.start()) <= 2:
                out += _names(alone[1], appliance)
    return out


def _skip_spaces(line: str, k: int) -> int:
    """The first place at or after ``k`` that is not a space."""
    return len(line) - len(line[k:].lstrip(" "))


def _names(inside: str, appliance: frozenset[str] = frozenset()) -> list[list[str]]:
    """The names one bracket holds ("plain, salted"), each one plain word, with or without a
    kind noun ("winter mode": the user's own "mode" is read as such)."""
    out: list[list[str]] = []
    if _words(inside)[:1] in (["or"], ["and"], ["if"], ["when"], ["but"]):
        return out  # "°F (or back)": a remark on the sentence, no name
    for part in _SPLIT.split(inside):
        words = _words(part)
        if not words or len(words) > MAX_ALIAS_WORDS or not all(w.isalpha() for w in words):
            continue
        if _COMPOUND.fullmatch(part.strip(" \"'“”")) and not set(words) & _NOT_NAMES:
            out.append(words)  # "2T (two-stroke)": one name written as a compound
            continue
        if any(w in _NOT_NAMES for w in words) or len(part.split()) != len(words):
            continue
        words = [
            w for w in words if not kind_noun(concept(w)) and concept(w) not in appliance
        ] or words
        if len(words) != 1 or words[0] in STOP_WORDS or words[0].endswith("est"):
            continue  # one plain word: "(winter mode)", not "(right stop)" nor "(coolest)"
        if words[0] in COUNT_NOUNS:
            continue  # "PIZZA (slice)": how it is counted, not a name ("apple slices")
        out.append(words)
    return out


def _words(text: str) -> list[str]:
    return re.findall(r"[a-z0-9]+", text.casefold())
