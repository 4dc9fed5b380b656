"""Two times of day said as a span ("from 9 am until 7 pm", "on at 7:30 and off at 21:30")
for a model that keeps a start and an end time of day (lights on and off, sunrise and sunset)."""

from __future__ import annotations

from apbot.model.schema import TimeVariable
from apbot.read.goal_daytimes import whole_day
from apbot.read.goal_fit import fit
from apbot.read.goal_text import Text
from apbot.read.goal_values import name_words
from apbot.read.goal_view import Goal, Model, VarInfo
from apbot.read.goal_vocab import SPAN_ENDS, SPAN_STARTS
from apbot.read.numbers import Mention

_STARTS = SPAN_STARTS
_ENDS = SPAN_ENDS
_FROM = frozenset({"from", "between"})
_UNTIL = frozenset({"to", "until", "till", "til", "and", "-"})


def time_spans(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
) -> list[Mention]:
    """Give a span's two times to the start and the end setting; the mentions left over.

    Only when the model has exactly one pair of times of day (not the clock) whose names say
    which begins and which ends, and the text says the span: "from A to/until B", "between A
    and B", or "on at A … off at B"."""
    pair = _start_and_end(view)
    if pair is None:
        return mentions
    start, end = pair
    used: set[int] = set()
    for i in range(len(mentions) - 1):
        first, second = mentions[i], mentions[i + 1]
        if first.kind != "clock" or second.kind != "clock" or start in goal or end in goal:
            continue
        span = first.lead in _FROM and text.word(first.end) in _UNTIL
        span = span and second.start == first.end + 1
        switched = _after(text, first, "on") and _after(text, second, "off")
        switched = switched and _same_switched(text, first, second)
        if not (span or switched):
            continue
        a = fit(view, view.infos[start], first, goal)
        b = fit(view, view.infos[end], second, goal)
        if a is None or b is None:
            continue
        goal[start], goal[end] = a, b
        where[start], where[end] = first.start, second.start
        for m in (first, second):
            claimed.update(range(m.start, m.end))
        used.update((i, i + 1))
    return [m for i, m in enumerate(mentions) if i not in used]


def _after(text: Text, mention: Mention, word: str) -> bool:
    """ "on at 7:30", "off at 9:30 pm": the time follows ON/OFF and "at"."""
    return mention.lead == "at" and text.word(mention.start - 2) == word


# words before "off" that name nothing switched ("on at 7 AND off at 9", "then TURN it off")
_NO_THING = frozenset(
    {"and", ",", "then", "turn", "turns", "turned", "switch", "switched", "switches", "go"}
) | frozenset({"goes", "it", "them", "they", "back", "be", "but", "later"})


def _same_switched(text: Text, first: Mention, second: Mention) -> bool:
    """ "the mat on at 7 am, and the lights off at 9 pm" switches two things, not one span:
    the thing named before OFF, when there is one, is the one named before ON."""
    before_on, before_off = text.word(first.start - 3), text.word(second.start - 3)
    if before_off in _NO_THING or before_off in ("", "the"):
        return True
    return before_off.rstrip("s") == before_on.rstrip("s")


def _start_and_end(view: Model) -> tuple[str, str] | None:
    """The one time-of-day setting named for a start and the one named for an end."""
    starts, ends = [], []
    for name, info in view.infos.items():
        if info.role != "setting" or not isinstance(info.var, TimeVariable):
            continue
        # two values are no dial of the day's hours, only its ends
        if info.timing == "clock" or len(info.values) <= 2 or not whole_day(info, wraps=False):
            continue
        words = _words(info)
        if words & _STARTS and not words & _ENDS:
            starts.append(name)
        elif words & _ENDS and not words & _STARTS:
            ends.append(name)
    return (starts[0], ends[0]) if len(starts) == 1 and len(ends) == 1 else None


def _words(info: VarInfo) -> set[str]:
    return {w.casefold() for w in name_words(info.name) + name_words(info.var.label or "")}
