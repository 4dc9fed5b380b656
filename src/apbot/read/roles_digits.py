"""Numbered keys that are no keypad: a row of a few numbers, each choosing its value at once.

A full keypad (0 to 9) types amounts, and the reader makes it the entry of a time or of the
setting a key opens. A row of only some numbers — a touch slider marked 1 to 5, speed keys 1
2 3, a level bar — types nothing: touching a number sets the setting to it. Read as a keypad,
those keys would enter a made-up cooking time; read as what they are, they are one amount
whose range runs from the lowest number to the highest, named by the sentence that says what
the numbers choose ("Touch a segment of the slider to choose the intensity directly: 1 (soft)
to 5 (strong).").
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder

# what a row of numbers chooses; "level" when no sentence names it
_AMOUNT = re.compile(
    r"\b(intensity|level|speed|strength|power|heat|temperature|setting|stage)\b", re.IGNORECASE
)


def _named(b: Builder, low: int, high: int) -> tuple[str, int | None]:
    """The amount a sentence naming both ends of the row ("1 (soft) to 5 (strong)") chooses:
    the word before the numbers; ("level", None) when none says."""
    ends = re.compile(rf"(?<![\d.,:]){low}(?![\d.,:])[^.]{{0,40}}?(?<![\d.,:]){high}(?![\d.,:])")
    for i, unit in enumerate(b.manual.units):
        m = ends.search(unit.text)
        if m is None:
            continue
        nouns = _AMOUNT.findall(unit.text[: m.start()])
        if nouns:
            return nouns[-1].lower(), i
    return "level", None


# a manual that types numbers: "type the cooking time with the number keys", "numeric keypad"
# (a heading "THE KEYPAD" is only the panel)
_TYPED = re.compile(
    r"\b(?:numeric|number|digit)\s*(?:key)?pad\b|\b(?:type|key\s+in|enter)\w*\b[^.]{0,40}?\b(?:numbers?|digits?|"
    r"figures?|time|weight|amount|minutes|seconds)\b"
    # "set the cooking time with the number keys", "number buttons … the clock"
    r"|\b(?:time|weight|clock)\b[^.]{0,40}?\b(?:number|digit|numeric)\s+(?:keys|buttons|pads)\b"
    r"|\b(?:number|digit|numeric)\s+(?:keys|buttons|pads)\b[^.]{0,40}?\b(?:time|weight|clock)\b",
    re.IGNORECASE,
)


def assign_direct_digits(b: Builder, digits: list[ActionInfo]) -> bool:
    """Digit keys that are not a full keypad become one amount they set directly; True when
    they did (the caller then has no keypad)."""
    numbers = {i.digit for i in digits if i.digit is not None}
    if len(numbers) < 2 or len(numbers) >= 10 or 0 in numbers:
        return False
    low, high = min(numbers), max(numbers)
    if numbers != set(range(low, high + 1)):
        return False  # gaps: a keypad missing keys, not a row of levels
    if any(_TYPED.search(u.text) for u in b.manual.units):
        return False  # keys 1 to 9 that type a time: a keypad whose 0 has another name
    noun, at = _named(b, low, high)
    var = b.unique(noun, b.variables)
    b.variables[var] = {"label": noun.upper(), "type": "numeric", "ranges": [[low, high, 1]]}
    names = [i.name for i in sorted(digits, key=lambda i: i.digit or 0)]
    effect = {i.name: {"to": i.digit} for i in digits}
    b.feature(f"set_{var}", [{"actions": names, "variable": var, "effect": effect}])
    b.note(f"variables.{var}", f"keys {low}–{high} choose the {noun} directly (no keypad)", at)
    return True
