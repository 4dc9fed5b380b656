"""How many times a day, said as "twice a day", "four times a day", "once daily", is the count
of a setting the panel writes with a times sign ("2x", "x3": doses, feeds, cycles a day).

The count has no noun of the setting beside it ("three doses a day" is read by the setting's
word), so the phrase is written as the setting's name and the number first. Only on a model
with exactly one such setting; "every day" and "once a week" stay how often (goal_every).
"""

from __future__ import annotations

import re

from apbot.model.values import NUMBER_WORDS
from apbot.read.goal_view import Model

_COUNT = "|".join(w for w, n in NUMBER_WORDS.items() if 2 <= n <= 12)
_TIMES_A_DAY = re.compile(
    rf"\b(?:(once|twice|thrice)|(\d{{1,2}}|{_COUNT})\s+times)\s+(?:a|per|each)\s+day\b"
    r"|\b(once|twice|thrice)\s+daily\b",
    re.IGNORECASE,
)
_ADVERBS = {"once": 1, "twice": 2, "thrice": 3}
_TIMES_SIGN = re.compile(r"\s*(?:\{value\}\s*[x×]|[x×]\s*\{value\})\s*", re.IGNORECASE)


def _times_setting(view: Model) -> str | None:
    """The one setting whose display writes its value with a times sign."""
    found = [
        name
        for name, info in view.infos.items()
        if info.role == "setting"
        and isinstance(info.var.show, str)
        and _TIMES_SIGN.fullmatch(info.var.show)
    ]
    return found[0] if len(found) == 1 else None


def said_times_a_day(view: Model, instruction: str) -> str:
    """ "twice a day" as "doses 2" where DOSES is shown "2x"."""
    if not _TIMES_A_DAY.search(instruction):
        return instruction
    name = _times_setting(view)
    if name is None:
        return instruction

    def count(match: re.Match[str]) -> str:
        word = (match[1] or match[3] or match[2]).casefold()
        number = _ADVERBS.get(word) or (int(word) if word.isdigit() else NUMBER_WORDS[word])
        return f"{name.replace('_', ' ')} {number}"

    return _TIMES_A_DAY.sub(count, instruction)
