"""Lists of single amounts and worked examples, which look like ranges but are none.

"The settings are 40 %, 50 %, 60 % and 70 %": "A and B" with a unit is read as a range
("between 60 % and 70 %"), but after an item and a comma the pair closes a list of single
values; the whole list, evenly spaced, is the range with its step (40–70 % by 10 %).
"Example: from 50 % to 60 %, press + once": a worked example moves a setting from one value to
another, it does not state the setting's limits. Their own module so these rules stay apart
from the range patterns of values.py.
"""

from __future__ import annotations

import itertools
import re

_AMOUNT = r"\d+(?:[.,]\d+)?"
_SIGN = r"(?:%|°\s?[CF]|°|(?!(?:and|or)\b)[A-Za-z]{1,7}\b)"
# an item of a list just before: a number, maybe its unit, then a comma
_ITEM_BEFORE = re.compile(rf"(?<![\w:.]){_AMOUNT}\s*{_SIGN}?\s*,\s*$", re.IGNORECASE)
# four or more amounts, the last two joined by "and": "40 %, 50 %, 60 % and 70 %", "20, 40, 60
# and 80 °C" (three may be a sample: "only 60, 80 and 100 °C below 100 °C")
_LIST_RE = re.compile(
    rf"(?<![\w:.,])((?:{_AMOUNT}\s*{_SIGN}?\s*,\s*){{2,}}{_AMOUNT}\s*{_SIGN}?\s+and\s+"
    rf"{_AMOUNT})\s*({_SIGN})?(?![\w:])",
    re.IGNORECASE,
)
# a worked example: the unit opens with "Example", "For example" or "E.g."
_EXAMPLE_RE = re.compile(r"^\W*(?:for\s+)?(?:example|e\.\s?g\.)\b", re.IGNORECASE)


def listed_tail(text: str, match: re.Match[str]) -> bool:
    """Whether a range match "A and B" is the end of a list of single values ("40, 50, 60 and
    70 %"): joined by "and" and following a listed number and a comma."""
    joined = re.search(r"\d\s*\S{0,8}?\s+and\s+\d", match.group(0), re.IGNORECASE)
    return bool(joined) and bool(_ITEM_BEFORE.search(text[: match.start()]))


def gaps(figures: list[float]) -> set[float]:
    """The gaps between neighbouring figures, rounded past float noise: one gap, an even list."""
    return {round(b - a, 6) for a, b in itertools.pairwise(figures)}


def listed_amounts(text: str) -> list[tuple[float, float, str, float]]:
    """Evenly spaced lists of amounts ("40 %, 50 %, 60 % and 70 %"), rising, in one unit:
    (first, last, unit as printed, gap) each."""
    out = []
    for m in _LIST_RE.finditer(text):
        items = re.findall(rf"({_AMOUNT})\s*({_SIGN})?", m.group(1))
        signs = {s.lower().replace(" ", "") for _, s in items if s} | (
            {m.group(2).lower().replace(" ", "")} if m.group(2) else set()
        )
        if len(signs) != 1:
            continue  # a unit must be named, and only one
        figures = [float(a.replace(",", ".")) for a, _ in items]
        between = gaps(figures)
        if len(between) == 1 and (gap := between.pop()) > 0:
            out.append((figures[0], figures[-1], m.group(2) or items[-1][1], gap))
    return out


def worked_example(text: str) -> bool:
    """Whether the unit is a worked example ("Example: from 50 % to 65 % press HUMIDITY four
    times (50 – 55 – 60 – 65)"): the values it passes through are no limits."""
    return bool(_EXAMPLE_RE.match(text))
