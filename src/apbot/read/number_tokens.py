"""Tokens of an instruction and the numbers written in them: "12", "1.5", "twenty-five", "an hour
and a half"'s "a half", "three quarters" — the pieces :mod:`apbot.read.numbers` reads quantities,
durations and clock times from (split from it; nothing here knows about units or a model)."""

from __future__ import annotations

import re
from dataclasses import dataclass

from apbot.model.values import NUMBER_WORDS

# --- tokens -----------------------------------------------------------------------------------

_TOKEN = re.compile(
    r"\d+:\d{2}(?::\d{2})?"  # 7:30, 1:30:00
    r"|\d+(?:\.\d+)?"  # 12, 1.5
    r"|°[cf]?"
    r"|[a-z]+(?:'[a-z]+)?"  # words, don't, o'clock
    r"|[%+/&,;.()!?:-]"
)

_REWRITES = (
    (re.compile(r"\ba\.m\.?(?=\W|$)"), " am "),
    (re.compile(r"\bp\.m\.?(?=\W|$)"), " pm "),
    (re.compile(r"\bper\s+cent\b"), " percent "),
    (re.compile(r"\bo'clock\b"), " oclock "),
    (re.compile(r"\bnon-(?=[a-z])"), "non"),  # non-stop
    (re.compile(r"(?<=\d),(?=\d{3}\b)"), ""),  # 1,000 -> 1000
    (re.compile(r"(?<![a-z])[\u00b5\u03bc]m\b"), "micron"),  # 150 µm: no "m" for minutes
    (re.compile(r"(?<![a-z])[\u00b5\u03bc]l\b"), "microlitre"),  # 625 µL: no "l" for litres
    (re.compile(r"(?<=\d)(?=[a-z°%])"), " "),  # 12min -> 12 min
    (re.compile(r"\s[-\u2013\u2014]+\s|\u2014"), " ; "),  # a dash between clauses
    (re.compile(r"[\u2010-\u2015\u2212]"), "-"),  # typographic dashes and minus
    # a sign spaced off the word before and glued to the digits: "freezer -20" (not "XR-18")
    (re.compile(r"(?<=[a-z]) -(?=\d)"), " minus "),
    (re.compile(r"[\u2018\u2019`]"), "'"),
    (re.compile(r"º"), "°"),
    (re.compile(r"½"), " and a half "),
    (re.compile(r"¼"), " and a quarter "),
)


@dataclass(frozen=True)
class Token:
    """One word, number or sign of the instruction, with its place in the token list."""

    text: str
    index: int


def tokenize(text: str) -> list[Token]:
    """Lower-case tokens of an instruction; units glued to numbers are split off.

    >>> [t.text for t in tokenize("Bake at 350°F for 12min.")]
    ['bake', 'at', '350', '°f', 'for', '12', 'min', '.']
    """
    cleaned = str(text).casefold()
    for pattern, replacement in _REWRITES:
        cleaned = pattern.sub(replacement, cleaned)
    words = _TOKEN.findall(cleaned)
    return [Token(word, i) for i, word in enumerate(words)]


# --- numbers in words --------------------------------------------------------------------------

_COUNTING = {w: n for w, n in NUMBER_WORDS.items() if w not in ("a", "an", "single", "couple")}
_UNITS_WORDS = {w: n for w, n in _COUNTING.items() if n < 20}
_TENS_WORDS = {w: n for w, n in _COUNTING.items() if 20 <= n < 100}
_ARTICLES = {"a", "an", "one", "single"}


@dataclass(frozen=True)
class Number:
    """A number read from tokens ``start``..``end`` (exclusive)."""

    value: float
    start: int
    end: int
    words: bool  # written in words (or with an article) rather than digits


def _is_digits(text: str) -> bool:
    return re.fullmatch(r"\d+(?:\.\d+)?", text) is not None


def read_number(tokens: list[Token], i: int) -> Number | None:
    """The longest number starting at token ``i``: digits, words, or both with fractions.

    "two hundred fifty", "twenty-five", "two and a half", "1.5", "a half", "three quarters".

    >>> read_number(tokenize("two hundred twenty-five degrees"), 0).value
    225.0
    >>> read_number(tokenize("four and a half hours"), 0).value
    4.5
    """
    n = len(tokens)
    j = i
    total = 0.0
    current = 0.0
    seen = False
    words = False

    def word(k: int) -> str:
        return tokens[k].text if k < n else ""

    if word(j) == "three" and word(j + 1) in ("quarter", "quarters"):
        return Number(0.75, i, j + 2, True)
    last = ""  # the kind of the previous number word: unit, tens or hundred
    if j < n and _is_digits(word(j)):
        current = float(word(j))
        j += 1
        seen = True
    else:
        if word(j) == "a" and word(j + 1) in ("hundred", "thousand"):
            # "a hundred and forty-four": the article counts one hundred, as people say it
            current = 1.0
            last = "unit"
            j += 1
        while j < n:
            w = word(j)
            if w in _UNITS_WORDS and (
                last in ("", "hundred") or (last == "tens" and _UNITS_WORDS[w] < 10)
            ):
                current += _UNITS_WORDS[w]
                last = "unit"
            elif w in _TENS_WORDS and last in ("", "hundred"):
                current += _TENS_WORDS[w]
                last = "tens"
            elif w == "-" and last == "tens" and word(j + 1) in _UNITS_WORDS:
                j += 1
                continue
            elif w == "hundred" and last in ("unit",) and current < 10:
                current *= 100
                last = "hundred"
            elif w == "thousand" and last in ("unit", "tens", "hundred"):
                total += current * 1000
                current = 0
                last = "hundred"
            elif (
                w == "and"
                and last == "hundred"
                and (word(j + 1) in _UNITS_WORDS or word(j + 1) in _TENS_WORDS)
            ):
                j += 1
                continue
            else:
                break
            seen = True
            words = True
            j += 1
    if not seen:
        return _fraction_alone(tokens, i)
    value = total + current
    # "... and a half", "... and a quarter", "... and three quarters"
    if word(j) == "and" and word(j + 1) in ("a", "an") and word(j + 2) in ("half", "quarter"):
        value += 0.5 if word(j + 2) == "half" else 0.25
        j += 3
        words = True
    elif word(j) == "and" and word(j + 1) == "three" and word(j + 2) in ("quarter", "quarters"):
        value += 0.75
        j += 3
        words = True
    elif [word(j + d) for d in range(4)] in (["-", "and", "a", "half"], ["-", "and", "an", "half"]):
        value += 0.5  # "two-and-a-half"
        j += 4
    return Number(value, i, j, words)


def _fraction_alone(tokens: list[Token], i: int) -> Number | None:
    """ "half", "a half", "a quarter", "three quarters", "a", "an" (one of a unit)."""
    n = len(tokens)

    def word(k: int) -> str:
        return tokens[k].text if k < n else ""

    j = i
    if word(j) in ("three",) and word(j + 1) in ("quarter", "quarters"):
        return Number(0.75, i, j + 2, True)
    if word(j) in ("a", "an", "one") and word(j + 1) in ("half", "quarter"):
        return Number(0.5 if word(j + 1) == "half" else 0.25, i, j + 2, True)
    if word(j) in ("half", "quarter"):
        return Number(0.5 if word(j) == "half" else 0.25, i, j + 1, True)
    if word(j) in ("a", "an") and word(j + 1) == "single":
        return Number(1.0, i, j + 2, True)
    if word(j) in ("a", "an", "single"):
        return Number(1.0, i, j + 1, True)
    if word(j) in ("twice", "thrice"):
        return Number(2.0 if word(j) == "twice" else 3.0, i, j + 1, True)
    if word(j) == "couple":
        return Number(2.0, i, j + 1, True)
    return None
