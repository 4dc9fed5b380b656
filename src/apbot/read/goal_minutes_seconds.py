"""Minutes and seconds said as a clock reads them: "five minutes thirty on the clock", "two
minutes fifteen left" are 5:30 and 2:15, as "1 hr 20" is an hour and twenty minutes. The bare
number after "minutes" (under 60, ending its phrase: a comma, "on", "left", "remaining", the
end) is written as seconds before the sentence is read, so it is no value of another setting
(a score of 30).
"""

from __future__ import annotations

import re

from apbot.model.values import words_to_number
from apbot.read.goal_view import Model

_SAID = re.compile(
    r"\b(minutes?|mins?)\s+(\d{1,2}|(?:[a-z]+-)?[a-z]+)"
    r"(?=\s*(?:[,.;:!?]|$|\s+(?:on|left|remaining|to\s+go|of\s+play)\b))",
    re.IGNORECASE,
)


def said_minutes_seconds(view: Model, instruction: str) -> str:
    """ "five minutes thirty on the clock" as "five minutes thirty seconds on the clock"."""
    del view

    def seconds(m: re.Match[str]) -> str:
        value = words_to_number(m[2])
        if value is None or not value.is_integer() or not 0 < value < 60:
            return m[0]
        return f"{m[1]} {m[2]} seconds"

    return _SAID.sub(seconds, instruction)
