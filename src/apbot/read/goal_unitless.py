"""A quantity said with a unit, for a numeric setting read without one and named beside it.

Readers miss units: a manual prints "FRIDGE 4°C" on the display and "+5 °C" in a list, and the
belief ends up with a FRIDGE setting 2…8 and no unit. The user then says "fridge at 3 degrees"
and no setting takes a temperature, so the goal lost the fridge altogether. A setting of no
known kind (no unit, none guessed from its name) named right beside the quantity takes its
number — only when no open setting has the quantity's kind (that one would be meant) and the
number is one of the setting's values.

So with a length of time: a number setting without a unit whose own name calls it a time or a
duration (SESSION TIME 1-10, shown "5:00"), or for switching itself off after a while (AUTO
OFF 1-10, SLEEP), takes a duration said without naming it ("ten minutes at speed 15"), as the
number said, when no setting has a unit of time to take it.
"""

from __future__ import annotations

from typing import Any

from apbot.model.schema import DiscreteVariable, NumericVariable, TimeVariable
from apbot.read.goal_text import Text, near_vocab
from apbot.read.goal_values import bare_number, name_words, unit_text
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values
from apbot.read.numbers import TIME_UNITS, Mention

_NAMED = 0.3
"""How strongly the words beside the quantity must name the setting: an own word of it within
three words ("the fridge to 3 °C", "6 °C in the fridge")."""


def unitless_named(view: Model, text: Text, mention: Mention, goal: Goal) -> str | None:
    """The setting the quantity goes to (set in ``goal``), or None when none is named so."""
    if mention.kind != "quantity" or mention.dimension is None:
        return None
    open_settings = [
        info for name, info in view.infos.items() if info.role == "setting" and name not in goal
    ]
    if any(info.dimension == mention.dimension for info in open_settings):
        return None
    scored = sorted(
        (
            (near_vocab(info, text, mention.start, mention.end), info)
            for info in open_settings
            if _of_no_kind(info)
        ),
        key=lambda pair: -pair[0],
    )
    if not scored or scored[0][0] < _NAMED or (len(scored) > 1 and scored[1][0] == scored[0][0]):
        return None
    info = scored[0][1]
    value = _value(view, info, mention, goal)
    if value is None:
        return None
    goal[info.name] = value
    return info.name


def _of_no_kind(info: VarInfo) -> bool:
    """A number range without a unit, or a list of bare numbers ("-16", "-17" …), of no kind."""
    var = info.var
    if info.dimension is not None:
        return False
    if isinstance(var, NumericVariable):
        return not unit_text(var)
    return isinstance(var, DiscreteVariable) and all(
        bare_number(v) is not None for v in info.values
    )


def _value(view: Model, info: VarInfo, mention: Mention, goal: Goal) -> Any:
    return listed_number(view, info, goal, mention.value)


def listed_number(view: Model, info: VarInfo, goal: Goal, said: float) -> Any:
    """The value of the setting's domain printed as the bare number said ("3" for "three"), or
    None: a number said without a unit the setting shares is matched as the manual prints it."""
    for value in domain_values(view, info, goal):
        number = bare_number(value)
        if number is not None and abs(number - said) < 1e-6:
            return value
    return None


_TIME_NAMES = frozenset({"time", "duration", "timer", "timeout"})
# a setting named for switching itself off after a while (AUTO OFF, SHUT-OFF, SLEEP) counts time
_SWITCH_OFF_NAMES = frozenset({"off", "sleep"})


def unitless_duration(view: Model, text: Text, mention: Mention, goal: Goal) -> str | None:
    """A duration for the one open number setting named a time but read without a unit (set in
    ``goal``, the number as said: "five minutes" is 5), or None."""
    unit = mention.unit or _said_unit(text, mention)
    if mention.kind != "duration" or unit.casefold() not in TIME_UNITS:
        return None
    open_settings = [
        info for name, info in view.infos.items() if info.role == "setting" and name not in goal
    ]
    if any(isinstance(i.var, TimeVariable) or i.dimension == "time" for i in open_settings):
        return None
    said = mention.value / _seconds_per(unit)
    fits = [
        (info, value)
        for info in open_settings
        if _of_no_kind(info) and isinstance(info.var, NumericVariable) and _named_a_time(info)
        for value in domain_values(view, info, goal)
        if abs(float(value) - said) < 1e-6
    ]
    if not fits:
        fits = _listed_minutes(view, text, mention, goal, open_settings, said)
    if len(fits) != 1:
        return None
    info, value = fits[0]
    goal[info.name] = value
    return info.name


def _listed_minutes(
    view: Model,
    text: Text,
    mention: Mention,
    goal: Goal,
    open_settings: list[VarInfo],
    said: float,
) -> list[tuple[VarInfo, Any]]:
    """A list of bare numbers with an OFF (a sleep timer OFF / 15 / 30 / 60, a stand-up
    reminder OFF / 30 / 45 …) is a choice of lengths of time, counted in minutes when the panel
    does not say: it takes a duration ("after half an hour" is its 30, "a two-hour reminder" its
    120) when its name calls it a time or stands beside the words (as said first, then in
    minutes)."""
    minutes = mention.value / 60.0
    fits: list[tuple[VarInfo, Any]] = []
    for info in open_settings:
        if not _offered_lengths(info):
            continue
        if not (_named_a_time(info) or near_vocab(info, text, mention.start, mention.end) > 0):
            continue
        values = domain_values(view, info, goal)
        for amount in (said, minutes):
            hit = [
                v for v in values if (n := bare_number(v)) is not None and abs(n - amount) < 1e-6
            ]
            if hit:
                fits.append((info, hit[0]))
                break
    return fits


def _offered_lengths(info: VarInfo) -> bool:
    """Two or more bare numbers and, besides them, only an OFF (and perhaps an AUTO: a ramp
    OFF / AUTO / 5 … 45 lets the machine choose the length): how long, of no unit read."""
    var = info.var
    if info.dimension is not None or not isinstance(var, DiscreteVariable):
        return False
    numbers = [v for v in info.values if bare_number(v) is not None]
    rest = sorted(str(v).casefold() for v in info.values if bare_number(v) is None)
    return len(numbers) >= 2 and rest in (["off"], ["auto", "off"])


def _named_a_time(info: VarInfo) -> bool:
    words = [w.casefold() for w in name_words(info.var.label or "") + name_words(info.name)]
    return any(word in _TIME_NAMES or word in _SWITCH_OFF_NAMES for word in words)


def _said_unit(text: Text, mention: Mention) -> str:
    """The last unit of time said within the duration: "ten minutes", "an hour and a half"
    (its "hour": the words after it only add a part), "" when none is said."""
    for k in range(mention.end - 1, mention.start - 1, -1):
        if text.word(k).casefold() in TIME_UNITS:
            return text.word(k)
    return ""


def _seconds_per(unit: str) -> float:
    return float(TIME_UNITS.get(unit.casefold(), 1))
