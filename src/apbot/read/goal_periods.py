"""Quantities said in weeks and periods, and a quantity said twice.

"two weeks" is a duration of 14 days for a setting that counts days, while "twice a week" is
how often — no setting's value; "at 9 pm (21:00)" says one time twice. Kept apart from the
assignment of mentions to settings because it only rewrites the list of mentions.
"""

from __future__ import annotations

from dataclasses import replace

from apbot.read.goal_text import Text
from apbot.read.numbers import Mention

_WEEKS = {"week": 7, "weeks": 7, "wk": 7, "wks": 7, "fortnight": 14, "fortnights": 14}
_NOT_COUNTED = frozenset({"month", "months", "year", "years", "yr", "yrs"})


_HOW_OFTEN = frozenset({"once", "twice", "thrice", "times", "every", "per", "each"})


def in_weeks(text: Text, mentions: list[Mention], daily: bool = True) -> list[Mention]:
    """ "two weeks", "a fortnight" are durations of 14 days (not a bare 2) when a setting counts
    in days (``daily``); a number of months or years is no setting's value (a "two-year-old",
    "twice a year"). How often ("twice a week", "every two weeks") is no duration at all."""
    out: list[Mention] = []
    covered = {k for m in mentions for k in range(m.start, m.end)}
    for mention in mentions:
        unit = text.word(mention.end + (text.word(mention.end) == "-"))
        if mention.kind == "number" and unit in _NOT_COUNTED:
            continue
        if mention.kind == "number" and _how_often(text, mention):
            continue  # "twice a week", "3 times a day": how often, no setting's value
        often = text.word(mention.start - 1) in _HOW_OFTEN
        if mention.kind == "number" and unit in _WEEKS and daily and not often:
            days = mention.value * _WEEKS[unit]
            end = mention.end + 1 + (text.word(mention.end) == "-")
            mention = replace(mention, kind="duration", value=days * 86400, end=end)
            mention = replace(mention, dimension="time", unit="")
        out.append(mention)
    for k, token in enumerate(text.tokens):  # "a week", "one fortnight": no number of its own
        if not daily or text.word(k - 2) in _HOW_OFTEN:
            continue  # "twice a week", "three times a week": how often, no duration
        if token.text in _WEEKS and k - 1 not in covered and text.word(k - 1) in ("a", "one"):
            days = 86400.0 * _WEEKS[token.text]
            out.append(Mention("duration", days, k - 1, k + 1, "time", words=True))
    return sorted(out, key=lambda m: m.start)


_PERIODS = frozenset({"day", "days", "night", "week", "weeks", "month", "year", "fortnight"})


def _how_often(text: Text, mention: Mention) -> bool:
    """A count of times in a period ("twice a week", "3 times per day")."""
    end = mention.end + (text.word(mention.end) == "times")
    counted = end > mention.end or text.word(mention.start) in ("once", "twice", "thrice")
    return (
        counted
        and text.word(end) in ("a", "per", "every", "each")
        and text.word(end + 1) in _PERIODS
    )


def distinct(mentions: list[Mention]) -> list[Mention]:
    """Drop a quantity that repeats the one just before it ("at 9 pm (21:00)", "a day, 24 h")."""
    kept: list[Mention] = []
    for mention in mentions:
        last = kept[-1] if kept else None
        if (
            last is not None
            and last.kind == mention.kind
            and abs(last.value - mention.value) < 1e-6
            and mention.start - last.end <= 3
        ):
            continue
        kept.append(mention)
    return kept
