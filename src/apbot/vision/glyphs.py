"""The character sets of the two display styles: a 5×7 dot-matrix ROM and a seven-segment table.

A dot-matrix LCD shows each character as a 5×7 grid of dots from its character ROM; a
seven-segment display lights some of segments ``a``–``g`` (plus a decimal point and a colon).
Both are fixed by the display hardware, not by the appliance, so the renderer draws with these
tables and the decoder inverts them. Several characters share one pattern (``5``/``S``,
``0``/``O`` on seven segments; ``I``/``l`` style pairs are kept apart in the ROM), so decoding
yields *candidates* per cell; the belief's display rules choose among them later.

>>> SEGMENTS["5"] == SEGMENTS["S"]
True
>>> sorted(seven_segment_candidates(SEGMENTS["0"]))[:2]
['0', 'D']
"""

from __future__ import annotations

from functools import cache

import numpy as np

# --- 5×7 dot matrix -----------------------------------------------------------------------------
# Each glyph: seven rows of five dots, top to bottom ('1' lit). Written for this project in
# the common style of HD44780-like character ROMs; symbols stand for the icons appliances use.
_ROM: dict[str, str] = {
    " ": "00000 00000 00000 00000 00000 00000 00000",
    "!": "00100 00100 00100 00100 00100 00000 00100",
    '"': "01010 01010 00000 00000 00000 00000 00000",
    "#": "01010 11111 01010 01010 01010 11111 01010",
    "%": "11000 11001 00010 00100 01000 10011 00011",
    "&": "01100 10010 10100 01000 10101 10010 01101",
    "'": "00100 00100 01000 00000 00000 00000 00000",
    "(": "00010 00100 01000 01000 01000 00100 00010",
    ")": "01000 00100 00010 00010 00010 00100 01000",
    "*": "00000 00100 10101 01110 10101 00100 00000",
    "+": "00000 00100 00100 11111 00100 00100 00000",
    ",": "00000 00000 00000 00000 01100 00100 01000",
    "-": "00000 00000 00000 11111 00000 00000 00000",
    ".": "00000 00000 00000 00000 00000 01100 01100",
    "/": "00000 00001 00010 00100 01000 10000 00000",
    "0": "01110 10001 10011 10101 11001 10001 01110",
    "1": "00100 01100 00100 00100 00100 00100 01110",
    "2": "01110 10001 00001 00010 00100 01000 11111",
    "3": "11111 00010 00100 00010 00001 10001 01110",
    "4": "00010 00110 01010 10010 11111 00010 00010",
    "5": "11111 10000 11110 00001 00001 10001 01110",
    "6": "00110 01000 10000 11110 10001 10001 01110",
    "7": "11111 00001 00010 00100 01000 01000 01000",
    "8": "01110 10001 10001 01110 10001 10001 01110",
    "9": "01110 10001 10001 01111 00001 00010 01100",
    ":": "00000 01100 01100 00000 01100 01100 00000",
    ";": "00000 01100 01100 00000 01100 00100 01000",
    "<": "00010 00100 01000 10000 01000 00100 00010",
    "=": "00000 00000 11111 00000 11111 00000 00000",
    ">": "01000 00100 00010 00001 00010 00100 01000",
    "?": "01110 10001 00001 00010 00100 00000 00100",
    "A": "01110 10001 10001 10001 11111 10001 10001",
    "B": "11110 10001 10001 11110 10001 10001 11110",
    "C": "01110 10001 10000 10000 10000 10001 01110",
    "D": "11100 10010 10001 10001 10001 10010 11100",
    "E": "11111 10000 10000 11110 10000 10000 11111",
    "F": "11111 10000 10000 11110 10000 10000 10000",
    "G": "01110 10001 10000 10111 10001 10001 01111",
    "H": "10001 10001 10001 11111 10001 10001 10001",
    "I": "01110 00100 00100 00100 00100 00100 01110",
    "J": "00111 00010 00010 00010 00010 10010 01100",
    "K": "10001 10010 10100 11000 10100 10010 10001",
    "L": "10000 10000 10000 10000 10000 10000 11111",
    "M": "10001 11011 10101 10101 10001 10001 10001",
    "N": "10001 10001 11001 10101 10011 10001 10001",
    "O": "01110 10001 10001 10001 10001 10001 01110",
    "P": "11110 10001 10001 11110 10000 10000 10000",
    "Q": "01110 10001 10001 10001 10101 10010 01101",
    "R": "11110 10001 10001 11110 10100 10010 10001",
    "S": "01111 10000 10000 01110 00001 00001 11110",
    "T": "11111 00100 00100 00100 00100 00100 00100",
    "U": "10001 10001 10001 10001 10001 10001 01110",
    "V": "10001 10001 10001 10001 10001 01010 00100",
    "W": "10001 10001 10001 10101 10101 10101 01010",
    "X": "10001 10001 01010 00100 01010 10001 10001",
    "Y": "10001 10001 10001 01010 00100 00100 00100",
    "Z": "11111 00001 00010 00100 01000 10000 11111",
    "[": "01110 01000 01000 01000 01000 01000 01110",
    "]": "01110 00010 00010 00010 00010 00010 01110",
    "_": "00000 00000 00000 00000 00000 00000 11111",
    "a": "00000 00000 01110 00001 01111 10001 01111",
    "b": "10000 10000 10110 11001 10001 10001 11110",
    "c": "00000 00000 01110 10000 10000 10001 01110",
    "d": "00001 00001 01101 10011 10001 10001 01111",
    "e": "00000 00000 01110 10001 11111 10000 01110",
    "f": "00110 01001 01000 11100 01000 01000 01000",
    "g": "00000 01111 10001 10001 01111 00001 01110",
    "h": "10000 10000 10110 11001 10001 10001 10001",
    "i": "00100 00000 01100 00100 00100 00100 01110",
    "j": "00010 00000 00110 00010 00010 10010 01100",
    "k": "10000 10000 10010 10100 11000 10100 10010",
    "l": "01100 00100 00100 00100 00100 00100 00110",
    "m": "00000 00000 11010 10101 10101 10001 10001",
    "n": "00000 00000 10110 11001 10001 10001 10001",
    "o": "00000 00000 01110 10001 10001 10001 01110",
    "p": "00000 00000 11110 10001 11110 10000 10000",
    "q": "00000 00000 01101 10011 01111 00001 00001",
    "r": "00000 00000 10110 11001 10000 10000 10000",
    "s": "00000 00000 01110 10000 01110 00001 11110",
    "t": "01000 01000 11100 01000 01000 01001 00110",
    "u": "00000 00000 10001 10001 10001 10011 01101",
    "v": "00000 00000 10001 10001 10001 01010 00100",
    "w": "00000 00000 10001 10001 10101 10101 01010",
    "x": "00000 00000 10001 01010 00100 01010 10001",
    "y": "00000 00000 10001 10001 01111 00001 01110",
    "z": "00000 00000 11111 00010 00100 01000 11111",
    "|": "00100 00100 00100 00100 00100 00100 00100",
    # symbols appliances print
    "°": "01100 10010 10010 01100 00000 00000 00000",
    "℃": "11000 11000 00111 01000 01000 01000 00111",
    "·": "00000 00000 00000 01100 01100 00000 00000",
    "•": "00000 00000 01110 01110 01110 00000 00000",
    "●": "00000 01110 11111 11111 11111 01110 00000",
    "½": "10000 10000 10010 00101 00001 00010 00111",
    "×": "00000 10001 01010 00100 01010 10001 00000",
    "é": "00010 00100 01110 10001 11111 10000 01110",
    "–": "00000 00000 00000 01110 00000 00000 00000",
    "↔": "00000 00100 01010 11111 01010 00100 00000",
    "↕": "00100 01110 10101 00100 10101 01110 00100",
    "≈": "00000 01000 10101 00010 01000 10101 00010",
    "≋": "01000 10101 00010 01000 10101 00010 00000",
    "⊘": "01110 10011 10101 10101 11001 01110 00000",
    "⊞": "11111 10101 10101 11111 10101 10101 11111",
    "▣": "11111 10001 10111 10111 10111 10001 11111",
    "▲": "00000 00100 01110 11111 00000 00000 00000",
    "▼": "00000 00000 11111 01110 00100 00000 00000",
    "▶": "01000 01100 01110 01111 01110 01100 01000",
    "▸": "00000 01000 01100 01110 01100 01000 00000",
    "☀": "10101 01110 11011 01110 10101 00000 00000",
    "☕": "00000 11110 10011 10011 10010 01100 11111",
    "☾": "00110 01100 11000 11000 11000 01100 00110",
    "⚙": "10101 01110 11011 10001 11011 01110 10101",
    "⚡": "00010 00100 01000 11111 00010 00100 01000",
    "✚": "01110 01110 11111 11111 11111 01110 01110",
    "❄": "00100 10101 01110 11111 01110 10101 00100",
    "⟳": "01101 10011 10111 10000 10001 10001 01110",
    "⌚": "01110 01110 10001 10101 10111 01110 01110",
    "⏰": "10001 01110 10101 10111 10001 01110 10001",
    "⏱": "01110 00100 01110 10101 10111 10001 01110",
    "⏲": "00000 01110 10001 10101 10011 10001 01110",
    "🌙": "01110 11100 11000 11000 11000 11100 01110",
    "💡": "01110 10001 10001 10001 01110 01110 00100",
    "🔑": "01110 10001 01110 00100 00110 00100 00110",
    "🔒": "01110 10001 10001 11111 11011 11011 11111",
    "⏻": "00100 10101 10101 10001 10001 10001 01110",
}
BLANK = " "
UNKNOWN_GLYPH = "?"
"""What the renderer draws for a character the ROM lacks (an LCD shows a placeholder)."""
INVISIBLE = "\ufe0e\ufe0f\u200b"
"""Variation selectors and zero-width marks: part of a string, never of what a display shows."""


def dot_pattern(char: str) -> np.ndarray:
    """The 7×5 boolean pattern of ``char`` (the ROM's ``?`` for a character it lacks)."""
    return _rom_array()[char if char in _ROM else UNKNOWN_GLYPH].copy()


@cache
def _rom_array() -> dict[str, np.ndarray]:
    table = {}
    for char, rows in _ROM.items():
        bits = [[c == "1" for c in row] for row in rows.split()]
        assert len(bits) == 7 and all(len(r) == 5 for r in bits), char
        table[char] = np.array(bits, dtype=bool)
    return table


def rom_chars() -> list[str]:
    """Every character the dot-matrix ROM can show."""
    return list(_ROM)


@cache
def _rom_matrix() -> tuple[list[str], np.ndarray]:
    chars = list(_ROM)
    return chars, np.stack([_rom_array()[c].ravel() for c in chars]).astype(np.float32)


def dot_candidates(lit: np.ndarray, limit: int = 3) -> list[tuple[str, float]]:
    """Characters whose ROM pattern is nearest to ``lit`` (7×5 lit probabilities in 0..1), as
    (character, distance in dots), nearest first."""
    chars, matrix = _rom_matrix()
    distance = np.abs(matrix - lit.reshape(1, -1).astype(np.float32)).sum(axis=1)
    order = np.argsort(distance, kind="stable")[:limit]
    return [(chars[i], float(distance[i])) for i in order]


# --- seven segments ----------------------------------------------------------------------------
# Segment order: a (top), b (upper right), c (lower right), d (bottom), e (lower left),
# f (upper left), g (middle). A character missing here cannot be shown on seven segments.
_SEG_LETTERS: dict[str, str] = {
    "0": "abcdef", "1": "bc", "2": "abdeg", "3": "abcdg", "4": "bcfg", "5": "acdfg",
    "6": "acdefg", "7": "abc", "8": "abcdefg", "9": "abcdfg", " ": "", "-": "g", "_": "d",
    "°": "abfg", "=": "dg", "'": "f",
    "A": "abcefg", "b": "cdefg", "C": "adef", "c": "deg", "d": "bcdeg", "E": "adefg",
    "F": "aefg", "G": "acdef", "H": "bcefg", "h": "cefg", "I": "bc", "i": "c", "J": "bcde",
    "L": "def", "n": "ceg", "o": "cdeg", "O": "abcdef", "P": "abefg", "q": "abcfg",
    "r": "eg", "S": "acdfg", "t": "defg", "U": "bcdef", "u": "cde", "y": "bcdfg",
    "Z": "abdeg", "B": "abcdefg", "D": "abcdef", "N": "ceg", "R": "eg", "T": "defg",
    "Y": "bcdfg", "Q": "abcfg",
}  # fmt: skip
SEGMENT_NAMES = "abcdefg"
SEGMENTS: dict[str, frozenset[str]] = {}
for _char, _segs in _SEG_LETTERS.items():
    SEGMENTS[_char] = frozenset(_segs)
    # a letter with one form on seven segments shows it in either case
    if _char.isalpha() and _char.swapcase() not in _SEG_LETTERS:
        SEGMENTS[_char.swapcase()] = frozenset(_segs)
SEG_EXTRAS = {":": "colon", ".": "point"}
"""Characters a seven-segment cell shows with its colon or decimal point instead of segments."""


def seven_segment_ok(text: str) -> bool:
    """Whether every character of ``text`` can be shown on a seven-segment display."""
    return all(c in SEGMENTS or c in SEG_EXTRAS or c in INVISIBLE for c in text)


def seven_segment_candidates(lit: frozenset[str]) -> list[str]:
    """Every character shown by exactly the segments ``lit``, digits first (``S`` also reads
    as ``5``; the display rules decide which it was)."""
    found = [c for c, segs in SEGMENTS.items() if segs == lit]
    return sorted(found, key=lambda c: (not c.isdigit(), not c.isupper(), c))


def segment_distance_candidates(bits: dict[str, float], limit: int = 4) -> list[tuple[str, float]]:
    """Characters by distance from lit probabilities per segment (for a cell read uncertainly)."""
    scored = []
    for char, segs in SEGMENTS.items():
        distance = sum(abs((name in segs) - bits.get(name, 0.0)) for name in SEGMENT_NAMES)
        scored.append((char, distance))
    scored.sort(key=lambda item: (item[1], not item[0].isdigit(), not item[0].isupper()))
    return scored[:limit]
