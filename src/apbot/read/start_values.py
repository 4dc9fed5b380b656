"""Where a numeric setting starts, in the setting's own unit: a start value read near the
setting ("The default is 30 minutes.") is only its start when it measures the same thing — a
figure in minutes is no start for a temperature, and a time's start is said in a time unit.
"""

from __future__ import annotations

from apbot.model.values import unit_of
from apbot.read.shapes import Evidence
from apbot.read.text import Unit
from apbot.read.value_steps import find_initial, find_step
from apbot.read.values import Range, is_time_unit, rescale, seconds


def start_in(value: float, said: str, unit: str, as_time: bool) -> float | None:
    """``value`` (said in ``said``) in the setting's ``unit`` (seconds for a time); None when
    the units measure different things."""
    if as_time:
        return float(seconds(value, said)) if is_time_unit(said) else None
    if not said or not unit or said == unit:
        return value
    if is_time_unit(said) or is_time_unit(unit):
        if is_time_unit(said) != is_time_unit(unit):
            return None
        return seconds(value, said) / seconds(1, unit)
    kinds = unit_of(said.lower()), unit_of(unit.lower())
    if kinds[0] and kinds[1] and kinds[0][0] != kinds[1][0]:
        return None  # "30 min" said of a setting in °C: another setting's start
    scaled = rescale(value, said, unit)
    return value if scaled is None else scaled


def on_grid(value: float, pieces: list[list[float]]) -> bool:
    """Whether the value is one a stepped range reaches."""
    for lo, hi, st in pieces:
        off = (value - lo) / st
        if lo <= value <= hi and abs(off - round(off)) < 1e-9:
            return True
    return False


# the state it leaves the factory in, said of a setting: "Out of the box it is set to 10 hours",
# "when you unpack the trimmer, the length is 3 mm", "on delivery: 20 °C"
# "… on first use 56.0 °C"
_AS_DELIVERED = r"|out of the box|on delivery|as supplied|unpack(?:ed|ing)?|on first use"


def said_after(units: list[Unit], at: int) -> tuple[tuple[float, str], int] | None:
    """A start value with its unit said right after a setting's range, in the same item of
    the same section ("… can be set from 4 to 24 hours. The factory setting is 8 hours."):
    the sentences after a range go on about that setting."""
    for k in range(at, min(at + 4, len(units))):
        unit = units[k]
        if k > at and (unit.heading != units[at].heading or unit.bullet or unit.cells):
            break  # another section, item or table: about something else
        found = find_initial(unit.text, _AS_DELIVERED)
        if found and found[1]:
            return found, k
    return None


def said_on(units: list[Unit], at: int) -> str:
    """The sentence a setting's range was found in, with the sentences after it in the same
    section ("Temperature setting range: 25 – 90 °C. Each click of the dial changes the
    temperature by 0.5 °C."): a step said right after the range is the range's."""
    texts = [units[at].text]
    for k in range(at + 1, min(at + 3, len(units))):
        if units[k].heading != units[at].heading or units[k].bullet or units[k].cells:
            break
        texts.append(units[k].text)
    return " ".join(texts)


def with_said_step(ev: Evidence, r: Range, text: str, at: int) -> Evidence:
    """The step said in the sentence a setting's range was found in elsewhere ("can be set
    from 4 to 24 hours, in increments of 1 hour"), when nothing else gave one."""
    if ev.step is not None or r.step is not None or not (step := find_step(text)):
        return ev
    if step[1] != r.unit and not (is_time_unit(step[1]) and is_time_unit(r.unit)):
        return ev
    return Evidence(**{**ev.__dict__, "step": step, "step_at": at})
