"""Characters of a manual's text: which pictographs are dropped and which are kept.

A manual flattened out of a PDF is full of emoji, dingbats and box drawing; most are noise, but
a chart's legend may say a symbol marks the default, or a legend may name a lamp's icon, and
those must survive cleaning for the reader to use them.
"""

from __future__ import annotations

import re
import unicodedata

from apbot.read.marks_legend import legend_meanings

_KEEP = frozenset("▲▼△▽◀▶◄►◁▷⏻°↑↓←→⟳⟲↻↺⎓⏦")  # (⎓ ⏦: DC and AC, a meter's positions)
_SPECIAL = re.compile(r"[^\x20-\x7e\n\t]")  # anything outside printable ASCII


# a chart legend naming the symbol that marks a default: "▣ = default setting", "◎ set when
# the menu is chosen (standard)"; no other symbol between the mark and the word
_DEFAULT_LEGEND = re.compile(
    r"(?:^|\s)(\S)[ \t]*([=:…]|\.{2,})?[^\n=:]{0,40}?\b(?:default|standard|preset|factory)\b",
    re.I | re.M,
)


_DEFAULT_WORD = re.compile(r"\b(?:default|standard|preset|factory)\b", re.I)


def _symbols(text: str) -> set[str]:
    return {c for c in text if unicodedata.category(c) == "So" and c not in _KEEP}


def _legend_marks(text: str) -> tuple[frozenset[str], frozenset[str]]:
    """The symbols a legend says mark a default, and every symbol such a legend explains: kept
    in the text so a chart cell ("Warm ▣", "◎") still says which choice is the default and
    which are possible (every other pictograph becomes a space). A legend sets the symbol
    apart ("▣ = …") or explains two symbols on its line; a bullet in a sentence that says
    "standard" is none."""
    defaults: set[str] = set()
    kept: set[str] = set()
    # a legend lies on one line: only the lines saying "default" are searched (the pattern,
    # tried at every space of a whole manual, was the slowest step of cleaning its text)
    for line in text.split("\n"):
        if not _DEFAULT_WORD.search(line):
            continue
        for m in _DEFAULT_LEGEND.finditer(line):
            mark = m.group(1)
            if mark not in _symbols(mark) or _symbols(m.group(0)[m.end(1) - m.start() :]):
                continue
            if m.group(2) or len(_symbols(line)) >= 2:
                defaults.add(mark)
                kept |= _symbols(line) | {mark}  # the legend's other marks ("● selectable")
    return frozenset(defaults), frozenset(kept)


def default_marks(text: str) -> frozenset[str]:
    """The symbols a chart legend says mark a default ("▣ = default setting")."""
    return _legend_marks(text)[0]


# "Mirror lamp ⇋ (lit when …)": a symbol a legend names as a setting's lamp, which the display
# then shows while the setting is on (``symbol_lamps``)
_LAMP_SYMBOL_RE = re.compile(r"\b[A-Za-z]{3,}\s+(?:lamp|symbol|icon|indicator)\s+(\S)(?=\s)")


def _lamp_symbols(text: str) -> set[str]:
    return {m.group(1) for m in _LAMP_SYMBOL_RE.finditer(text)} & _symbols(text)


def _clean_chars(text: str) -> str:
    """Drop control characters and pictographs; keep letters, digits, punctuation, ▲▼ and °,
    and the symbols a legend says mark a default."""
    keep = _KEEP | _legend_marks(text)[1] | set(legend_meanings(text)) | _lamp_symbols(text)

    def one(match: re.Match[str]) -> str:
        ch = match.group(0)
        cat = unicodedata.category(ch)
        if cat.startswith("C"):
            return "\f" if ch == "\f" else ""  # a form feed marks a page: kept, on its own line
        if ch == "❄":
            return "COLD"  # the snowflake printed for a cold wash or a cold setting
        if "\u2500" <= ch <= "\u257f":
            return "-"  # box drawing: a rule across a table stays a rule
        if cat == "So" and ch not in keep:
            return " "  # emoji and dingbats
        return ch

    return _SPECIAL.sub(one, text)
