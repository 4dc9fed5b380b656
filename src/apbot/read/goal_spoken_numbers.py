"""Numbers people say in ways the number reader does not take: hundreds counted past ten
("thirty-two hundred kelvin" is 3200, "fifteen hundred and fifteen" 1515), decimals read
out digit by digit ("three point three volts" is 3.3, "one point nine five" 1.95), and a
musician's steps ("a whole step down" is two semitones, "half a step" one).

The number reader stops at "hundred" after a number above nine, and at "point", so these
phrases lost their setting or gave it a wrong number ("one point eight volts" read 8 V). They
are written as their figures before the instruction is read. A time said the military way
("nineteen hundred hours") is a time of day, not a count, and is left as it is.
"""

from __future__ import annotations

import re

from apbot.model.values import NUMBER_WORDS
from apbot.read.goal_text import Text
from apbot.read.goal_view import Model

# words that count but are no figure of a said number ("twelve hundred a minute" is 1200 per
# minute, "one point five A" 1.5 amps): never a digit or a number's ones
_NO_FIGURES = frozenset({"a", "an", "single", "couple"})
_FIGURES = {w: n for w, n in NUMBER_WORDS.items() if w.isalpha() and w not in _NO_FIGURES}
_DIGITS = {w: n for w, n in _FIGURES.items() if n < 10} | {
    "oh": 0,
    "nought": 0,
    "naught": 0,
}
_TEENS = {w: n for w, n in _FIGURES.items() if 10 <= n < 20}
_TENS = {w: n for w, n in _FIGURES.items() if 20 <= n < 100}
_ONES = {w: n for w, n in _FIGURES.items() if 0 < n < 10}


def _alt(words: dict[str, int]) -> str:
    return "|".join(sorted(words, key=len, reverse=True))


_TWO_FIGURES = rf"(?:{_alt(_TEENS)}|(?:{_alt(_TENS)})(?:[- ](?:{_alt(_ONES)}))?)"
_UP_TO_99 = rf"(?:{_TWO_FIGURES}|{_alt(_ONES)})"
_TIME_AFTER = r"(?!\s*(?:hours?|hrs?|h)\b)"

_HUNDREDS = re.compile(
    rf"\b(?P<lead>{_TWO_FIGURES})[ -]hundred(?:(?:\s+and)?\s+(?P<rest>{_UP_TO_99})\b)?\b"
    + _TIME_AFTER,
    re.IGNORECASE,
)
# the minutes of a time said the military way, after its hundred ("… thirty hours")
_TIME_MINUTES = re.compile(rf"(?:\s+and)?\s+{_UP_TO_99}\s*(?:hours?|hrs?|h)\b", re.IGNORECASE)
_POINT = re.compile(
    rf"\b(?P<whole>{_UP_TO_99}|zero|nought|naught|\d+)\s+point"
    rf"(?P<digits>(?:\s+(?:{_alt(_DIGITS)}))+)\b",
    re.IGNORECASE,
)


def _value(words: str) -> int:
    """ "thirty-two" as 32, "fifteen" as 15, "seven" as 7."""
    if words.isdigit():
        return int(words)
    return sum(NUMBER_WORDS[w] for w in re.split(r"[- ]", words.casefold()) if w)


def said_hundreds_past_ten(view: Model, instruction: str) -> str:
    """ "thirty-two hundred" as "3200", "fifteen hundred and fifteen" as "1515"."""
    del view  # the phrase means one number whatever the model

    def figure(match: re.Match[str]) -> str:
        if not match["rest"] and _TIME_MINUTES.match(instruction, match.end()):
            return match[0]  # "nineteen hundred thirty hours": a time, minutes and all
        value = 100 * _value(match["lead"]) + (_value(match["rest"]) if match["rest"] else 0)
        return str(value)

    return _HUNDREDS.sub(figure, instruction)


def said_points(view: Model, instruction: str) -> str:
    """ "three point three" as "3.3", "one point nine five" as "1.95"."""
    del view

    def figure(match: re.Match[str]) -> str:
        digits = "".join(str(_DIGITS[w.casefold()]) for w in match["digits"].split())
        whole = match["whole"].casefold()
        return f"{0 if whole in ('nought', 'naught') else _value(whole)}.{digits}"

    return _POINT.sub(figure, instruction)


_STEPS = re.compile(
    r"\b(?:(?P<half>half\s+a\s+(?:step|tone)|(?:a|one)\s+half[\s-]+(?:step|tone))"
    r"|(?P<whole>(?:a|one)\s+(?:whole|full)[\s-]+(?:step|tone)))\b",
    re.IGNORECASE,
)


def said_steps(view: Model, instruction: str) -> str:
    """ "a whole step" as "2 semitones", "half a step" as "1 semitone" where the manual
    counts the setting in semitones (a tuner's flat tuning, a keyboard's transpose)."""
    if not _STEPS.search(instruction) or not {"semitone", "semitones"} & view.manual_words:
        return instruction

    def semitones(match: re.Match[str]) -> str:
        return "1 semitone" if match["half"] else "2 semitones"

    return _STEPS.sub(semitones, instruction)


_NUMBER_WORD = rf"(?:{_alt(_FIGURES)}|hundred|thousand)"
_HYPHENATED = re.compile(
    rf"\b{_NUMBER_WORD}(?:-(?:and-)?{_NUMBER_WORD})*-(?:and-)?(?:hundred|thousand)"
    rf"(?:-(?:and-)?{_NUMBER_WORD})*\b",
    re.IGNORECASE,
)
_HALF_THOUSAND = re.compile(rf"\b(?P<lead>{_UP_TO_99}|\d+) and a half thousand\b", re.IGNORECASE)


def said_hyphenated(view: Model, instruction: str) -> str:
    """ "the seven-hundred-and-fifty-volt range" as "seven hundred and fifty-volt" (a number
    written as one compound before its unit), "six and a half thousand" as "6500"."""
    del view

    def spaced(match: re.Match[str]) -> str:
        return match[0].replace("-", " ")

    def half(match: re.Match[str]) -> str:
        return str(1000 * _value(match["lead"]) + 500)

    return _HALF_THOUSAND.sub(half, _HYPHENATED.sub(spaced, instruction))


_POSSESSIVE = re.compile(rf"\b(?:([A-Za-z]+)\s+)?({_UP_TO_99}|\d+)'s\b", re.IGNORECASE)
# words before "one's" that make it a pronoun, no number ("no one's home", "each one's part")
_PRONOUN_AFTER = frozenset(
    {"no", "each", "every", "any", "some", "the", "this", "that", "which", "either", "neither"}
    | {"another", "other", "little", "loved", "only", "last", "next", "right", "wrong"}
)


def numbers_owning(view: Model, instruction: str) -> str:
    """ "dog one's level" as "dog one level": a numbered thing's possessive keeps its number
    (the tokenizer read "one's" as one word, no number); a pronoun's ("no one's home") is
    left as it is."""
    del view

    def owner(match: re.Match[str]) -> str:
        before = match[1]
        if before is None or before.casefold() in _PRONOUN_AFTER:
            return match[0]
        return f"{before} {match[2]}"

    return _POSSESSIVE.sub(owner, instruction.replace("\u2019", "'"))


def a_number_for_a_name(text: Text, start: int, end: int, value: object) -> bool:
    """The words a value was matched from are a number said ("one", "ten") and the value a
    word of counting places (ONES, TENS, HUNDREDS of a digit cursor) that only shares their
    stem: "a one-minute press", "for ten seconds" ask for no cursor position."""
    name = str(value).casefold()
    if not name.isalpha() or name in NUMBER_WORDS:
        return False
    words = [text.word(k) for k in range(start, end)]
    return bool(words) and all(w in NUMBER_WORDS and w != name for w in words)
