"""When a time setting acts: a clock of the day, a delay, a time to finish at, a duration —
read from its own words and from the clock beside it. Split from goal_view (the model as the
parser sees it) so each job stays small."""

from __future__ import annotations

from typing import TYPE_CHECKING

from apbot.model.schema import NumericVariable, TimeVariable
from apbot.read.goal_daytimes import day_dial, switch_time, whole_day
from apbot.read.goal_values import in_days, name_words, quantity_dimensions
from apbot.read.goal_vocab import concept

if TYPE_CHECKING:
    from apbot.read.goal_view import VarInfo


def mark_timings(infos: dict[str, VarInfo]) -> None:
    """Set each time setting's ``timing`` (and ``turns``: the state it leaves at its end)."""
    for info in infos.values():
        if isinstance(info.var, TimeVariable) or (
            isinstance(info.var, NumericVariable) and info.dimension == "time"
        ):
            if "clock" in info.vocab and not in_days(info.var) and not _minutes_seconds(info):
                info.timing = "clock"
            elif concept("delay") in info.vocab:
                info.timing = "delay"
            elif concept("finish") in info.vocab:
                # a time of day to finish at ("READY AT") or a wait ("READY IN", "END 3h")
                at = isinstance(info.var, TimeVariable) and not (
                    {"in", "after"} & set(name_words(f"{info.name} {info.var.label or ''}"))
                )
                info.timing = "finish" if at else "delay"
    clocked = any(info.timing == "clock" for info in infos.values())
    for info in infos.values():
        if clocked and info.timing == "duration" and whole_day(info) and switch_time(info):
            info.timing = "at"  # beside the clock, ON TIME / START: when it switches
        elif clocked and info.timing == "duration" and whole_day(info):
            # beside the clock, a TIMER that wraps at 23:59 is a time of day: when it is done
            info.timing = "finish"
            info.vocab.setdefault(concept("finish"), 0.5)
        elif info.timing == "duration" and day_dial(info):
            info.timing = "at"  # no clock beside it, yet a dial of the day's hours
    for info in infos.values():
        if info.timing in ("duration", "delay") and (
            isinstance(info.var, TimeVariable)
            or info.dimension == "time"
            or quantity_dimensions(info.values) == {"time"}
        ):
            words = set(name_words(f"{info.name} {info.var.label or ''}".casefold()))
            # a SLEEP timer lets the appliance go to sleep: off at its end
            info.turns = "off" if words & {"off", "sleep"} else "on" if "on" in words else None


def _minutes_seconds(info: VarInfo) -> bool:
    """A clock shown as minutes and seconds (a game clock, a countdown's "mm:ss") holds a
    span of time, not a time of day: "twelve minutes on the game clock" is 12:00 on it."""
    var = info.var
    return isinstance(var, TimeVariable) and "h" not in (var.format or "hh").casefold()
