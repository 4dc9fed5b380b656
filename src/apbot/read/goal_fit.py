"""Whether a quantity fits a variable: the canonical value a mention (number, duration, clock
time, quantity with a unit) gives one setting, in that setting's unit and domain."""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

from apbot.model.schema import NumericVariable, TimeVariable
from apbot.model.values import format_hms
from apbot.read.goal_bare import bare_choice
from apbot.read.goal_values import parse_quantity, shown_count, unit_kind, unit_text
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values
from apbot.read.goal_vocab import concept
from apbot.read.number_tokens import tokenize
from apbot.read.numbers import Mention, find_mentions


def fit(view: Model, info: VarInfo, mention: Mention, goal: Goal) -> Any:
    """The canonical value a mention gives this variable, or None when it does not fit."""
    counted = mention.kind == "number" and mention.unit
    if counted and concept(mention.unit) not in info.vocab and not _COUNTING & set(info.vocab):
        return None  # "two slices" counts slices: only a quantity setting takes it
    domain = domain_values(view, info, goal)
    var = info.var
    if isinstance(var, TimeVariable):
        if mention.kind == "duration" and info.timing not in ("clock", "finish", "at"):
            seconds = round(mention.value)
        elif mention.kind == "clock" and info.timing in ("duration", "delay"):
            if not mention.colon or mention.meridiem or mention.lead not in ("for", "to", "of"):
                return None
            hours, minutes = divmod(round(mention.value) // 60, 60)
            # "for 1:30": minutes and seconds on a mm:ss display, else hours and minutes
            seconds = hours * 60 + minutes if var.format == "mm:ss" else round(mention.value)
        elif mention.kind == "clock":
            seconds = round(mention.value)
            if format_hms(seconds) not in domain and seconds >= 13 * 3600:
                # a 12-hour clock: 19:00 is 7:00
                seconds -= 12 * 3600
        else:
            return None
        value = format_hms(seconds)
        return value if value in domain else None
    if isinstance(var, NumericVariable):
        unit = unit_text(var)
        number = number_for(info, unit, mention)
        if number is None:
            return _percent_of_level(info, mention, domain)
        fahrenheit_dial = unit.casefold() in ("°f", "f")
        converted = (mention.kind == "fahrenheit" and not fahrenheit_dial) or (
            fahrenheit_dial and mention.unit in ("°c", "c", "celsius")
        )
        tolerance = (_F_TOLERANCE * (1.8 if fahrenheit_dial else 1.0)) if converted else 1e-6
        return _in_numeric(number, domain, tolerance=tolerance)
    if mention.kind == "clock":
        said = clock_value(domain, mention)
        if said is not None:
            return said
    # discrete values that are numbers ("60", "1000") or quantities ("1.75 oz", "450 W")
    measured = _measure(mention)
    if measured is None:
        return None
    amount, dimension = measured
    for value in sorted(domain, key=lambda v: _zero_led(v) != mention.zero_led):
        q = parse_quantity(str(value))
        if q is None:
            continue
        if q[1] is not None:
            if q[1] == dimension and abs(q[0] - amount) < 1e-6 * max(1.0, abs(amount)):
                return value
        elif dimension is None or dimension == info.dimension or _per_hundred(info, dimension):
            if abs(q[0] - amount) < 1e-6:
                return value
        elif (
            dimension == "fahrenheit"
            and info.dimension == "temperature"
            and abs(q[0] - (amount - 32) * 5 / 9) < 0.6
        ):
            return value
    return (
        _coded(domain, mention)
        or _coded_show(info, domain, mention)
        or _show_quantity(info, mention)
        or _named_quantity(view, info, mention, domain)
        or bare_choice(info, domain, mention)
    )


_TIME_OF_DAY = re.compile(r"(\d{1,2})(?:[:.](\d\d))?\s*(?:([ap])\.?m\.?)?", re.IGNORECASE)


def clock_value(domain: list[Any], mention: Mention) -> Any:
    """The value written as a time of day ("7:00 AM", "18:30") a time said names: a list of
    opening or feeding times kept as text. A time said without am / pm takes the one value
    of its hour and minute, morning or evening, when only one is listed."""
    seconds = round(mention.value) % (24 * 3600)
    found = []
    for value in domain:
        match = _TIME_OF_DAY.fullmatch(str(value).strip())
        if match is None or (match[2] is None and match[3] is None):
            continue
        hour, minute = int(match[1]), int(match[2] or 0)
        if match[3]:
            hour = hour % 12 + (12 if match[3].casefold() == "p" else 0)
        at = hour * 3600 + minute * 60
        if at == seconds:
            return value
        if not mention.meridiem and (at - seconds) % (12 * 3600) == 0:
            found.append(value)
    return found[0] if len(found) == 1 else None


def _zero_led(value: Any) -> bool:
    """A code written with a leading zero ("06" beside "6" on a kiln's cone list): the user
    who says "cone 6" means 6, and "cone 06" means 06."""
    text = str(value)
    return len(text) > 1 and text[0] == "0" and text.isdigit()


def _per_hundred(info: VarInfo, dimension: str | None) -> bool:
    """ "80 percent brightness" on levels listed 20, 40, … 100 without a unit: a percentage
    of a setting with no unit of its own whose numbers end at exactly 100."""
    if dimension != "ratio" or info.dimension is not None:
        return False
    numbers = [q[0] for v in info.values if (q := parse_quantity(str(v))) is not None]
    return len(numbers) == len(info.values) >= 2 and max(numbers) == 100 and min(numbers) >= 0


CODE = re.compile(r"[A-Za-z]{1,2}[- ]?(\d+)")


def _coded(domain: list[Any], mention: Mention) -> Any:
    """ "programme 5" for a value written P5, "menu 6" for A-6: a short prefix and the number."""
    if mention.kind != "number" or mention.value != int(mention.value):
        return None
    found = [v for v in domain if (m := CODE.fullmatch(str(v))) and int(m[1]) == mention.value]
    return found[0] if len(found) == 1 else None


def _coded_show(info: VarInfo, domain: list[Any], mention: Mention) -> Any:
    """ "programme 4" for the value the display shows as P4 (a name the panel codes)."""
    show = info.var.show if isinstance(info.var.show, dict) else {}
    if not show:
        return None
    shown = {v: show[str(v)] for v in domain if str(v) in show and "{" not in show[str(v)]}
    codes = [v for v, text in shown.items() if CODE.fullmatch(text.strip())]
    if len(codes) < 2 or len(codes) < len(shown) - 1:
        return None  # not a coded list ("ICE CREAM", "GELATO")
    said = mention
    if mention.kind == "quantity" and mention.dimension == "ratio":
        said = replace(mention, kind="number")  # "the 50 percent UV setting" for UV50
        codes = [v for v in codes if _own_prefix(info, show[str(v)])]
    found = [v for v in codes if _coded([show[str(v)].strip()], said) is not None]
    return found[0] if len(found) == 1 else None


def _own_prefix(info: VarInfo, shown: str) -> bool:
    """The code's letters are the setting's own name or label (UV50 on a UV setting): the
    panel writes the level as the setting and its percentage."""
    match = CODE.fullmatch(shown.strip())
    letters = shown.strip()[: match.start(1)].strip(" -").casefold() if match else ""
    own = {w.casefold() for w in re.findall(r"[A-Za-z]+", f"{info.name} {info.var.label or ''}")}
    return bool(letters) and letters in own


def _percent_of_level(info: VarInfo, mention: Mention, domain: list[Any]) -> Any:
    """ "50% power" on a power level of 1-10 is level 5."""
    if mention.dimension != "ratio" or not domain or info.dimension is not None:
        return None
    if not ({concept("power"), concept("level")} & set(info.vocab)):
        return None
    top = max(float(v) for v in domain)
    if top not in (10, 100):
        return None
    return _in_numeric(mention.value * top / 100, domain)


_COUNTING = frozenset(
    concept(w) for w in ("quantity", "qty", "count", "number", "servings", "pieces", "portions")
)


def _measure(mention: Mention) -> tuple[float, str | None] | None:
    if mention.kind == "number":
        return mention.value, None
    if mention.kind in ("quantity", "fahrenheit"):
        return mention.value, mention.dimension
    if mention.kind == "duration":
        return mention.value, "time"
    return None


def _base_unit(dimension: str) -> str:
    return {"temperature": "°C", "ratio": "%", "speed": "rpm"}.get(dimension, "")


def _show_quantity(info: VarInfo, mention: Mention) -> Any:
    """A discrete value whose display text holds the mentioned quantity ("POT 600mL"), or
    the duration (a timer whose values "1", "2", "4" show as "1H", "2H", "4H")."""
    show = info.var.show if isinstance(info.var.show, dict) else {}
    if mention.kind not in ("quantity", "duration") or not show:
        return None
    for value, text in show.items():
        for m in find_mentions(tokenize(text)):
            same = m.kind == mention.kind and m.dimension == mention.dimension
            if same and abs(m.value - mention.value) < 1e-6:
                return value
    if mention.kind == "duration" and mention.lead == "every":  # "every 3 days": "d3", "W 3d"
        found = [v for v, t in show.items() if shown_count(str(t)) == round(mention.value)]
        return found[0] if len(found) == 1 else None
    return None


def _named_quantity(view: Model, info: VarInfo, mention: Mention, domain: list[Any]) -> Any:
    """A coded value the manual gives as this quantity ("60 %" for knob mark 2)."""
    for value, text in view.named_quantities.get(info.name, []):
        for m in find_mentions(tokenize(text)):
            same = m.dimension == mention.dimension and m.kind == mention.kind
            if same and abs(m.value - mention.value) < 1e-6 and value in domain:
                return value
    return None


def number_for(info: VarInfo, unit: str, mention: Mention) -> float | None:
    """The mention as a number in ``unit`` (None when the dimensions differ)."""
    target = unit_kind(unit) if unit else None
    if mention.kind == "number":
        return mention.value
    if mention.kind == "duration":
        if target is None or target[0] != "time":
            return None
        return mention.value / target[1]
    if mention.kind == "fahrenheit":
        if unit.casefold() in ("°f", "f"):
            return mention.value
        if target is not None and target[0] == "temperature":
            return round((mention.value - 32) * 5 / 9, 6)
        return None
    if mention.kind == "quantity":
        if target is None:
            if unit:
                return None
            return mention.value if mention.dimension in (None, info.dimension) else None
        if unit.casefold() in ("°f", "f") and mention.dimension == "temperature":
            if mention.unit in ("°c", "c", "celsius"):
                return round(mention.value * 9 / 5 + 32, 6)  # "180 °C" on a Fahrenheit dial
            return mention.value  # "350 degrees" on a Fahrenheit dial
        if target[0] != mention.dimension:
            return None
        return mention.value / target[1]
    return None


_F_TOLERANCE = 5.0
"""°C a Fahrenheit figure may miss a Celsius dial by: 350 °F is 176.7 °C, printed as 180 °C."""


def _in_numeric(number: float, domain: list[Any], tolerance: float = 1e-6) -> Any:
    """The domain value equal to ``number`` (or nearest within ``tolerance``)."""
    best = min(domain, key=lambda v: abs(float(v) - number), default=None)
    if best is not None and abs(float(best) - number) <= tolerance:
        return best
    return None
