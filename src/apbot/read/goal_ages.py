"""How old someone is, said the way people say it, is an AGE setting's number.

"a 27-year-old woman", "34 years old", "a sixty-year-old" give a profile's age (a scale, a
fitness machine, a hearing aid keep one); the rest of the parser reads a number beside its
setting's word ("age 27"), so the phrase is written that way first. Only on a model with a
setting named AGE; a year said otherwise ("two years of use") stays no value.
"""

from __future__ import annotations

import re

from apbot.model.schema import NumericVariable
from apbot.model.values import DIGIT_WORDS, NUMBER_WORDS
from apbot.read.goal_view import Model

_NUMBER = (
    r"\d{1,3}|(?:"
    + "|".join(
        sorted((w for w in NUMBER_WORDS if w not in ("a", "an", "single", "couple")), key=len)[::-1]
    )
    + r")(?:[- ](?:"
    + "|".join(w for w, n in DIGIT_WORDS.items() if n)
    + "))?"
)
_YEARS_OLD = re.compile(
    rf"\b(?:an?\s+)?({_NUMBER})[- ]years?[- ]olds?\b|\b({_NUMBER})\s+years\s+of\s+age\b",
    re.IGNORECASE,
)


def _has_age(view: Model) -> bool:
    return any(
        isinstance(info.var, NumericVariable) and "age" in re.split(r"[\s_]+", name.casefold())
        for name, info in view.infos.items()
    )


def said_ages(view: Model, instruction: str) -> str:
    """ "a 41-year-old" as "age 41" on a model with an AGE setting."""
    if not _has_age(view):
        return instruction
    return _YEARS_OLD.sub(lambda m: f"age {m[1] or m[2]}", instruction)
