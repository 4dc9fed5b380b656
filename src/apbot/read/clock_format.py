"""Whether a manual's clock counts 1-12 (AM / PM, "12-hour format") or 0-23: read from the sentences
that speak of the clock itself, not from "keeps warm for 12 hours" or "ready at 6 a.m." (split
from ``build``)."""

from __future__ import annotations

import re
from typing import Any

_HOURS = r"(?:[- ]?h(?:ou)?rs?\b|[- ]?h\b|[- ]hours?\b)"  # "12-hour", "12 h", "12hr", "24-hours"


_CLOCK_RE = re.compile(
    r"\bclock\b|\btime of (?:the )?day\b|\bcurrent time\b|\btime (?:display|format)\b", re.I
)


def _hour_clock_re(number: str) -> re.Pattern[str]:
    """ "12-hour" (any spelling); "12-hour format/clock" says it of a clock by itself."""
    return re.compile(rf"{number}{_HOURS}(?:\s+(?:time\s+)?(?:format|clock)\b)?", re.I)


_TWELVE_RE = _hour_clock_re(r"(?:\b12|\btwelve)")


_TWENTY_FOUR_RE = _hour_clock_re(r"(?:\b24|\btwenty[- ]four)")


_AM_PM_RE = re.compile(  # "AM", "7:30 pm", "8 a.m.", "am/pm" (not the verb "am", not "PM 2.5")
    r"(?-i:\bAM\b|\bPM\b(?!\s?\d))|\d(?::\d\d)?\s*[ap]\.?m\b"
    r"|\b(?:am|a\.m\.)\s*/\s*(?:pm|p\.m\.)",
    re.I,
)


def _of_the_clock(sentence: str, hours: re.Pattern[str], am_pm: bool) -> bool:
    """A sentence giving the clock's format: its hours (or AM/PM) beside the clock, or "12-hour
    format". "Keeps warm for 12 hours" or "ready at 6 a.m." speaks of no clock."""
    said = hours.search(sentence)
    if said and said.group(0).lower().endswith(("format", "clock")):
        return True
    format_said = bool(said or (am_pm and _AM_PM_RE.search(sentence)))
    return format_said and bool(_CLOCK_RE.search(sentence))


_SENTENCE_RE = re.compile(r"(?<=[.;!?])\s+(?=[A-Z])")


_CUT_SHORT_RE = re.compile(r"\b(?:e\.g|i\.e|approx|ca|eg|ie)\.$", re.I)


def twelve_hour_clock(units: list[Any]) -> bool:
    """Whether the clock counts 1–12 (AM/PM, "12-hour clock"): "keeps warm for 12 hours" is no
    such clock, and a manual that speaks of a 24-hour clock has none."""
    texts = [s for u in units for s in _SENTENCE_RE.split(u.text)]  # (its clock in the sentence)
    for i in range(len(texts) - 1):
        if _CUT_SHORT_RE.search(texts[i]):
            texts[i + 1] = f"{texts[i]} {texts[i + 1]}"
    if any(_of_the_clock(t, _TWENTY_FOUR_RE, am_pm=False) for t in texts):
        return False
    return any(_of_the_clock(t, _TWELVE_RE, am_pm=True) for t in texts)
