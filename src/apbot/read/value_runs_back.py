"""Two list shapes a key's sentence prints that the other finders pass over.

- Counts with the noun they count after each ("1/6 stop > 1/3 stop > 1 stop", "2 slices > 4
  slices > 6 slices"): the noun is the setting's, not part of each value (the display shows
  the figure alone), so the values are the figures. A noun the reader already takes as a unit
  (minutes, cups) is left to the other finders.
- A run of whole numbers that wraps ("each press adds one: 5, 6, 7, 8, 9, then back to 3"):
  the setting counts from the number it goes back to up to the run's last, on the run's step;
  the run starts at the present value, so the numbers between the wrap target and the run's
  first are filled in.
"""

from __future__ import annotations

import itertools
import re
import unicodedata

from apbot.read.values import UNIT

_FIGURE = r"\d+(?:[.,]\d+)?(?:/\d+)?"
_COUNTED = re.compile(rf"({_FIGURE})\s+([a-z]{{3,12}})")


def counted_figures(items: list[str]) -> list[str] | None:
    """Three or more figures each followed by the same lower-case noun (a plural folded to its
    singular): the figures alone; None for any other list. A bare figure at the end that is
    the first one again ("… > 1 stop > back to 1/6") is the list coming round, no value."""
    first = _COUNTED.fullmatch(items[0].strip()) if items else None
    if first and len(items) >= 4 and items[-1].strip() == first.group(1):
        items = items[:-1]
    found = [_COUNTED.fullmatch(i.strip()) for i in items]
    if len(items) < 3 or not all(found):
        return None
    nouns = {m.group(2).removesuffix("s") for m in found if m}
    if len(nouns) != 1:
        return None
    figures = [m.group(1) for m in found if m]
    return figures if len(set(figures)) == len(figures) else None


_WRAPPED = re.compile(
    r"(?<![\d.,/])(\d{1,3}(?:\s*,\s*\d{1,3}){2,})\s*,?\s*(?:and\s+)?then\s+(?:back\s+)?"
    rf"(?:round\s+)?to\s+(\d{{1,3}})(?!\d|[.,/]\d|\s*{UNIT}(?!\w))",
    re.IGNORECASE,
)


def wrapped_run(text: str) -> list[str] | None:
    """A run of three or more whole numbers on one step, then "then back to N" with N below the
    run's first: the numbers from N to the run's last, on that step."""
    m = _WRAPPED.search(text)
    if not m:
        return None
    run = [int(x) for x in re.split(r"\s*,\s*", m.group(1))]
    back = int(m.group(2))
    step = run[1] - run[0]
    if step <= 0 or any(b - a != step for a, b in itertools.pairwise(run)):
        return None
    if back >= run[0] or (run[0] - back) % step:
        return None
    return [str(n) for n in range(back, run[-1] + 1, step)]


def drawn_sign(item: str) -> bool:
    """A position printed as the sign on the panel ("Ω·)))▶|" for resistance, continuity and
    diode; "⊣⊢"): one piece, no opening bracket (so no aside "(default)"), a sign character in
    it. Such items fail the value test only for their closing brackets."""
    return (
        bool(re.fullmatch(r"\S{1,12}", item))
        and "(" not in item
        and "[" not in item
        and any(unicodedata.category(c).startswith("S") for c in item)
    )
