"""Assemble an appliance model from what the manual says about each control.

Each action is given a *role* from its name and the sentences that mention its control: power,
start, stop, lock, a stepping pair (▲/▼, +/−), a digit, a dial, or a setting key. A setting key's
sentences decide what it sets: a value list it cycles, an on/off toggle, a range it steps or that
the stepping pair / keypad enters after it. Keys the manual only lists together (programme pads)
become one variable with a go-to value each. Where the manual is silent the reader picks the
guess the closed loop repairs most cheaply — a cyclic ``next`` over a small domain — and says so.

This module reads numbers (range, step, unit, start: the longest job); the ledger every role reader
writes to (notes, lists, on/off settings, features) is ``BuilderBase`` in build_base.py.
"""

from __future__ import annotations

import math
import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.build_base import PLACEHOLDERS, BuilderBase
from apbot.read.chart_steps import charted_values
from apbot.read.clock_format import twelve_hour_clock
from apbot.read.first_piece import table_pieces
from apbot.read.labels import words
from apbot.read.part_seconds import part_seconds
from apbot.read.quantity_units import _guess_step, _tidy, _unit_from_words
from apbot.read.shapes import (
    CHOICE_WORDS,
    Evidence,
)
from apbot.read.start_values import on_grid, said_after, said_on, start_in, with_said_step
from apbot.read.values import Range, number, rescale, seconds, unit_name
from apbot.read.values_pieces import split_range
from apbot.read.values_signed import signed_in_section
from apbot.read.values_upto import stated_low
from apbot.read.values_zero import from_zero, zero_told

_PRINTED_UNITS = r"kg|g|lbs?|ml|l|litres?|W|watts?|rpm|%"  # quantities, not times or degrees


"""What a sentence about the clock itself names ("mode", "display" alone are any feature's)."""


"""A unit the parser ended at an abbreviation ("… time of day, e.g." + "7:30 pm.")."""


_DIGITS_RE = re.compile(r"\b(one|two|three|1|2|3)[- ]digits?\b", re.I)
_UNITED_AMOUNT_RE = re.compile(r"\d+(?:[.,]\d+)?\s*(?:W|kW|°[CF]|%|g|kg|lb|ml|l|rpm)", re.I)


def united_amounts(name: str, values: list[str] | None) -> bool:
    """Whether a control named for a thing besides its kind (HEAT SELECTOR, not MENU or MODE
    alone) lists amounts all printed with a unit ("750 W", "1500 W"): it chooses amounts."""
    named = set(words(name.replace("_", " ")))
    if not named - CHOICE_WORDS - {"key", "button", "switch"}:
        return False  # a menu's or a mode key's list of amounts is another key's, in its menu
    return bool(values) and all(_UNITED_AMOUNT_RE.fullmatch(v.strip()) for v in values or [])


_QUANTITY_WORDS = {"temp", "temperature", "humidity", "weight", "volume", "speed", "watt"}


class Builder(BuilderBase):
    """Collects variables, features, guards and notes; ``data()`` gives the model as plain data.

    Adds the reading of a number's range, step, unit and start to the ledger of ``BuilderBase``."""

    def _digit_count(self, name: str, label: str) -> tuple[Range, int] | None:
        """A time whose amount the manual says is written in so many digits of one unit ("type
        the minutes (two digits at most)", "| two digits + dot | Timer minutes |"): 0 to 99 of
        it. Only a sentence or row naming the setting (or its key) and the unit."""
        ws = {w for w in words(name.replace("_", " ")) if len(w) >= 4} | set(words(label))
        for i, unit in enumerate(self.manual.units):
            m = _DIGITS_RE.search(unit.text)
            uw = set(words(unit.text))
            if m is None or not uw & ws:
                continue
            counted = number(m.group(1))
            spans = [u for u in ("seconds", "minutes", "hours") if u in uw]
            if counted and 1 <= counted <= 3 and len(spans) == 1:
                top = 10 ** int(counted) - 1
                return Range(0, top, {"seconds": "s", "minutes": "min", "hours": "h"}[spans[0]]), i
        return None

    def _zero_for_none(
        self, subject: str, name: str, label: str, ranges: list[Range], ev: Evidence
    ) -> list[Range]:
        """A timer read from its first real value whose zero a sentence naming it says is none
        ("0 h = no timer"): zero is one of its settings."""
        names = {w for w in words(name.replace("_", " ")) + words(label) if len(w) >= 3}
        texts = [u.text for u in self.manual.units]
        at = zero_told(texts, names, ranges[0].unit)
        if at is None:
            return ranges
        step = ev.step[0] if ev.step and ev.step[1] == ranges[0].unit else None
        self.note(subject, "zero is one of its settings (none)", at)
        return from_zero(ranges, step)

    def add_number(
        self, name: str, label: str, ev: Evidence, cyclic: bool, amounts: bool = False
    ) -> str:
        """A numeric or time variable from the ranges and steps read (guessed where absent);
        ``amounts``: its own list gave amounts with a unit, so even a selector takes them."""
        named = set(words(name.replace("_", " ")))
        choice = bool(named & CHOICE_WORDS) and not named & _QUANTITY_WORDS  # (TEMP SELECT)
        # a selector whose own list gives amounts with a unit ("750 W / 1500 W") chooses amounts
        choice = choice and not amounts
        if choice:  # a programme is not an amount
            ev = Evidence(**{**ev.__dict__, "ranges": [r for r in ev.ranges if not r.unit]})
        if not ev.ranges and choice:
            # a programme/mode selector the manual lists no values for: a few placeholder
            # choices the loop replaces with what the display shows (a number would stop it)
            var = self.add_discrete(name, ["1", "2", "3", "4", "5"], label, None)
            self.note(f"variables.{var}.values", PLACEHOLDERS)
            return var
        name = self.unique(name, self.variables)
        subject = f"variables.{name}"
        ranges = list(ev.ranges)
        found: tuple[Range, int] | None = None
        clock = "clock" in words(name.replace("_", " "))
        if clock and any(r.unit not in ("s", "h") for r in ranges):
            ranges = []  # a clock's range is the day, whatever numbers stand nearby
        if len(ranges) == 1 and ranges[0].low == 0 and ev.range_at is not None:
            told = self._range_anywhere(name, label)  # "up to 45 °C", "set from 30 °C to 40 °C"
            ranges = [stated_low(ranges[0], self.manual.units[ev.range_at].text, told)]
        if len(ranges) == 1 and ev.range_at is not None:  # a range-and-step table's first row
            ranges = table_pieces(ranges[0], self.manual.units, ev.range_at) or ranges
        if ranges:
            shown = ", ".join(f"{r.low:g}–{r.high:g}" for r in ranges)
            self.note(subject, f"range {shown} {ranges[0].unit}", ev.range_at)
        elif clock:
            twelve = twelve_hour_clock(self.manual.units)
            low, high = (3600, 12 * 3600 + 59 * 60) if twelve else (0, 23 * 3600 + 59 * 60)
            self.note(subject, "a clock: the time of day (its range is the clock's, not read)")
            ranges = [Range(low, high, "s", 60)]
        elif (found := self._range_anywhere(name, label)) is not None:
            at = found[1]
            ev = with_said_step(ev, found[0], said_on(self.manual.units, at), at)
            said = [] if at is None else [u.text for u in self.manual.units[at : at + 3]]
            ranges = (
                table_pieces(found[0], self.manual.units, at)  # a table's rows
                or split_range(found[0], said, label)
                or [found[0]]
            )
            r0 = found[0]
            self.note(
                subject, f"range {r0.low:g}–{r0.high:g} {r0.unit} (named elsewhere)", found[1]
            )
        elif (digits := self._digit_count(name, label)) is not None:
            ranges = [digits[0]]
            r0 = digits[0]
            self.note(subject, f"range {r0.low:g}–{r0.high:g} {r0.unit} (its digits)", digits[1])
        elif ev.longest is not None:
            ranges = [ev.longest[0]]
            r0 = ev.longest[0]
            self.note(
                subject, f"range {r0.low:g}–{r0.high:g} {r0.unit} (its longest)", ev.longest[1]
            )
        elif (signed := signed_in_section(self.manual.units, name, label)) is not None:
            ranges = [signed[0]]  # "TRANSPOSE … The range is -6 to +6 semitones."
            self.note(
                subject, f"range {ranges[0].low:g}–{ranges[0].high:g} (below zero)", signed[1]
            )
        else:
            unit = ev.step[1] if ev.step else _unit_from_words(name)
            low, high = {"": (0, 10), "h": (0, 12), "min": (1, 60), "°C": (30, 100)}.get(
                unit, (0, 100)
            )
            self.note(subject, f"range {low:g}–{high:g} {unit} (the manual gives none)")
            ranges = [Range(low, high, unit)]
            self.unread.add(name)
        if ranges[0].low > 0 and not clock and name not in self.unread:
            ranges = self._zero_for_none(subject, name, label, ranges, ev)
        unit = ranges[0].unit or (ev.step[1] if ev.step else "") or _unit_from_words(name)
        if unit == "°C" and not ranges[0].unit and self.fahrenheit():
            unit = "°F"  # a temperature read without its unit, in a manual that speaks °F
        finer = bool(ev.step and ev.step[1] in ("s", "min") and unit == "h")  # 0–3 h by 1 min
        hmm = ev.shown_hmm if unit == "h" and not clock else None  # "the display shows 9:30"
        as_time = ranges[0].unit == "s" or unit in ("s", "min") or finer or hmm is not None
        if as_time and part_seconds(ev.step, ranges):
            as_time, unit = False, "s"  # "2 to 10 seconds in half-second steps": shown "3.5 s"
        if hmm is not None:
            self.note(f"{subject}.type", "a time: the display shows it as h:mm", hmm[1])
        factor = 1 if ranges[0].unit == "s" else seconds(1, unit) if as_time else 1
        chart = (  # "It steps through this chart: 1.0 1.3 1.6 … 128" and "stops at 1.0 and 128"
            charted_values(self.manual.units, ranges[0].low, ranges[0].high)
            if len(ranges) == 1 and not ranges[0].step and not ev.step and name not in self.unread
            else None
        )
        if chart:
            chart_unit = ranges[
                0
            ].unit  # ("16 s": the unit said with the range, as the screen shows)
            charted = [f"{v} {chart_unit}" if chart_unit else v for v in chart[0]]
            self.variables[name] = {"type": "discrete", "values": charted, "label": label}
            self.variables[name]["wrap"] = cyclic
            self.note(f"{subject}.values", f"the {len(chart[0])} values of a chart", chart[1])
            return name

        def base_step(r: Range) -> float | None:
            """The step in the variable's base unit (seconds for a time)."""
            if r.step:
                return r.step * factor
            if not ev.step:
                return None
            value, step_unit = ev.step
            if as_time and step_unit in ("s", "min", "h"):
                return float(seconds(value, step_unit))
            if not as_time and step_unit and (scaled := rescale(value, step_unit, unit)):
                return scaled * factor  # "0.1 – 1.5 kg in 100 g steps": 0.1 kg
            if step_unit in ("", unit) or not as_time:
                return value * factor
            return None

        pieces: list[list[float]] = []
        for index, r in enumerate(ranges):
            lo, hi = r.low * factor, r.high * factor
            if as_time:  # whole seconds: "10 s" read in minutes is 0.166667 min, not 10.00002 s
                lo, hi = float(round(lo)), float(round(hi))
            st = base_step(r)
            if st and not as_time and hi > lo and st > hi - lo:
                st = _in_thousands(st, hi - lo) or st  # "by 1,000 rpm", shown 3–35: thousands
            if st:
                self.note(
                    f"{subject}.step",
                    f"step {st / factor:g} {unit}",
                    ev.step_at if not r.step else ev.range_at,
                )
            elif hmm is not None:  # "shows 9:30": set in minutes, ten at a time or fewer
                st = float(seconds(math.gcd(hmm[0], 10) or 10, "min"))
                self.note(f"{subject}.step", f"step {st / 60:g} min (guessed from h:mm shown)")
            else:
                st = _guess_step(r.high - r.low, unit) * factor
                if as_time and st < 60 and lo % 60 == 0 and hi % 60 == 0 and hi - lo >= 600:
                    st = 60.0  # a clock-written range ("0:20 – 1:30") steps in minutes
                self.note(f"{subject}.step", f"step {st / factor:g} {unit} (the manual gives none)")
            if as_time:
                st = max(1.0, float(round(st)))
            if pieces:
                lo = max(lo, pieces[-1][1])
            count = int((hi - lo) / st + 1e-9)
            if count > 5000:
                st = (hi - lo) / 5000 if not as_time else float(-(-(hi - lo) // 5000))
                count = int((hi - lo) / st + 1e-9)
            hi = lo + count * st
            if hi <= lo:
                if index:
                    continue
                hi = lo + st
            pieces.append([lo, hi, st])
        spec: dict[str, Any]
        if as_time:
            spec = {
                "type": "time",
                "ranges": [
                    [format_hms(int(lo)), format_hms(int(hi)), int(st)] for lo, hi, st in pieces
                ],
                "format": "h:mm"
                if pieces[-1][1] >= 3600 and all(p[2] % 60 == 0 for p in pieces)
                else "mm:ss",
                "label": label,
            }
        else:
            if not unit and (found_unit := self._printed_unit(name, label, pieces[-1][1])):
                unit = found_unit[0]
                self.note(
                    f"{subject}.unit", f"in {unit} (printed beside its values)", found_unit[1]
                )
            spec = {
                "type": "numeric",
                "ranges": [[_tidy(lo), _tidy(hi), _tidy(st)] for lo, hi, st in pieces],
                "unit": unit,
                "label": label,
            }
        read_at = ev.range_at if ev.range_at is not None else found[1] if found else None
        after = said_after(self.manual.units, read_at) if read_at is not None else None
        if ev.initial is None and after:
            ev = Evidence(**{**ev.__dict__, "initial": after[0], "initial_at": after[1]})
        if ev.initial and isinstance(ev.initial, tuple):
            start = start_in(ev.initial[0], ev.initial[1], unit, as_time)
            if start is not None and on_grid(start, pieces):
                spec["initial"] = format_hms(int(start)) if as_time else _tidy(start)
                start_said = f"{ev.initial[0]:g}" + (f" {ev.initial[1]}" if as_time else "")
                self.note(f"{subject}.initial", f"starts at {start_said}", ev.initial_at)
        if cyclic:
            spec["wrap"] = True
            self.note(f"{subject}.wrap", "stepping past the end wraps around (each press adds)")
        self.variables[name] = spec
        return name

    def _printed_unit(self, name: str, label: str, high: float) -> tuple[str, int] | None:
        """The unit printed after the setting's largest value where a table column or a
        sentence names the setting ("| Loaf weight | … 500 / 750 / 1000 g |" for LOAF): a
        quantity read from numbers alone ("(500 / 750 / 1000)") is in that unit."""
        own = {w for w in words(name.replace("_", " ")) + words(label) if len(w) >= 3}
        if not own:
            return None
        pattern = re.compile(rf"(?<![\d.,]){_tidy(high)}\s*({_PRINTED_UNITS})(?![\w°])", re.I)
        for i, unit in enumerate(self.manual.units):
            if unit.cells and unit.header and len(unit.header) == len(unit.cells):
                places = [
                    c for h, c in zip(unit.header, unit.cells, strict=True) if own & set(words(h))
                ]
            else:
                places = [unit.text] if own & set(words(unit.text)) else []
            for place in places:
                m = pattern.search(place)
                if m:
                    return unit_name(m.group(1)), i
        return None


def _in_thousands(step: float, span: float) -> float | None:
    """A step wider than the whole range it steps is said in the unit the display shows in
    thousands ("each click 1,000 rpm; 12 means 12,000 rpm"): a thousandth of it, when that
    fits (else None: the step stays as read)."""
    if step % 1000 == 0 and step / 1000 <= span:
        return step / 1000
    return None
