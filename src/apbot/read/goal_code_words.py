"""A panel code cut from a long word the manual writes out beside it: REV for "reverse" ("REV
  reverse running", "DIR — changes between forward and reverse"). A three-letter code is
otherwise named only by a word at most twice its length (``goal_shortened``), so a long word
("reverse") would not name it; the manual's own line pairing the two does."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_vocab import STOP_WORDS, stem

if TYPE_CHECKING:  # goal_view builds the phrases with this module: no import at run time
    from apbot.read.goal_view import VarInfo

_WORD = re.compile(r"[a-z]+")


def code_words(
    infos: dict[str, VarInfo], manual: str
) -> list[tuple[str, Any, tuple[str, ...], float]]:
    """(setting, value, stems, weight) for each three-letter code of a choice setting whose long
    word (beginning with the code, over twice its length) stands in a manual line that prints
    the code itself in capitals or the setting's label; none when the word begins another of
    the setting's codes, or two codes of the manual's lines would share it."""
    if not manual:
        return []
    lines = manual.splitlines()
    found: dict[str, list[tuple[str, Any]]] = {}
    for name, info in infos.items():
        var = info.var
        if not isinstance(var, DiscreteVariable) or info.role != "setting":
            continue
        codes = [v for v in info.values if isinstance(v, str) and len(v) == 3 and v.isalpha()]
        label = (var.label or "").strip()
        for value in codes:
            code = str(value).casefold()
            printed = re.compile(rf"(?<![A-Za-z]){re.escape(code.upper())}(?![A-Za-z])")
            for line in lines:
                if not printed.search(line) and not (
                    len(label) >= 3 and label.isupper() and label in line
                ):
                    continue
                for word in _WORD.findall(line.casefold()):
                    long = len(word) > 2 * len(code) and word.startswith(code)
                    if long and word not in STOP_WORDS and not word.endswith("ly"):
                        found.setdefault(word, []).append((name, value))
    out: list[tuple[str, Any, tuple[str, ...], float]] = []
    for word, owners in found.items():
        if len(set(owners)) == 1:
            name, value = owners[0]
            out.append((name, value, (stem(word),), 0.9))
    return out
