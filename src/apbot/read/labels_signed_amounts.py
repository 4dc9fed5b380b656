"""A key named by a signed amount ("minus1", "plus10"): printed as the sign and the number.

Course, score and trim keys print only their amount ("−1", "+10"). The action names spell the
sign as a word and glue the number on (``press_minus10``), which the word matching of
``labels`` cannot tie to "−10": the key was left unnamed, so no sentence mentioned it and every
step with it ("Press +1 to raise the level") was lost. A bare sign word and amount is read here
as that printing, where the manual has it with the sign glued to the number.
"""

from __future__ import annotations

import re

from apbot.read.text import Manual

_TOKEN_RE = re.compile(r"^(plus|minus)_?(\d{1,3})$")
_MINUS = "−–-"


def signed_amount(manual: Manual, token: str) -> tuple[str, int] | None:
    """The printed label of a bare signed-amount token, and the line first printing it."""
    m = _TOKEN_RE.match(token)
    if m is None:
        return None
    signs = "+" if m.group(1) == "plus" else _MINUS
    pattern = re.compile(rf"(?<![\w.+{_MINUS}])([{re.escape(signs)}]){m.group(2)}(?![\w.])")
    for unit in manual.units:
        found = pattern.search(unit.text)
        if found:
            return found.group(0), unit.line
    return None
