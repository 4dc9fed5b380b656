"""A code said digit by digit is one number: "new code 4 0 9 6", "code five-one-seven-zero".

People read PINs, access codes and station numbers out one digit at a time. A run of four or
more single digits (figures or the words zero … nine), set apart by spaces or hyphens, is
written as the one number it spells before the rest of the parser reads it — only on a model
with a setting that takes such a number (a range reaching 1000 or more), so a list of small
numbers elsewhere ("levels 1 2 3 4") is left alone.
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.model.values import DIGIT_WORDS
from apbot.read.goal_view import Model

# "oh" as people read a 0 aloud ("four oh nine six")
_DIGIT_WORDS = {w: str(n) for w, n in DIGIT_WORDS.items()} | {"oh": "0"}
_DIGIT = r"(?:\d|" + "|".join(_DIGIT_WORDS) + r")"
_RUN = re.compile(rf"\b{_DIGIT}(?:[ -]{_DIGIT}){{3,}}\b", re.IGNORECASE)


def _takes_long_numbers(view: Model) -> bool:
    for info in view.infos.values():
        if isinstance(info.var, NumericVariable) and info.var.unit in (None, ""):
            try:
                if max(float(v) for v in all_values(info.var)) >= 1000:
                    return True
            except ValueError:
                continue
    return False


def spelled_codes(view: Model, instruction: str) -> str:
    """ "code 4 0 9 6" as "code 4096" on a model with a setting of such numbers."""
    if not _takes_long_numbers(view):
        return instruction

    def joined(match: re.Match[str]) -> str:
        parts = re.split(r"[ -]", match[0])
        return "".join(_DIGIT_WORDS.get(p.casefold(), p) for p in parts)

    return _RUN.sub(joined, instruction)
