"""A late pass: a setting whose range is still the reader's guess (0–10, or a guessed hour or
minute span) takes the span its own section states (:mod:`apbot.read.values_stated`).

Late, after the passes that rename or rebuild a guessed setting from what they read (a press's
numbered steps, code spans, a mode's paragraphs), so the span replaces only a guess no other
rule could read; asked early instead, it fixed a name and a range those passes then passed by.
"""

from __future__ import annotations

from typing import Any

from apbot.model.values import format_hms
from apbot.read.build import Builder
from apbot.read.values import Range, seconds
from apbot.read.values_stated import stated_halts, stated_in_section

_TIME_UNITS = {"s", "min", "h"}


def read_stated_ranges(b: Builder) -> None:
    """Give each numeric setting whose range was guessed the span its section states."""
    for var, spec in b.variables.items():
        if var not in b.unread or spec.get("type") != "numeric" or "cases" in spec:
            continue
        if spec.get("depends_on") or len(spec.get("ranges") or []) != 1:
            continue
        label = str(spec.get("label") or "")
        found = stated_in_section(b.manual.units, var, label)
        if found is None:
            continue
        span, at = found
        if span.unit in _TIME_UNITS:
            _as_time(spec, span, label)
        elif not _as_number(spec, span):
            continue
        halts = stated_halts(b.manual.units[at].text)
        if halts:
            spec.pop("wrap", None)  # "the value stops at either end": no wrap past it
        b.unread.discard(var)
        subject = f"variables.{var}"
        gone = {subject, f"{subject}.wrap"} if halts else {subject}
        b.notes = [n for n in b.notes if not (n.guess and n.subject in gone)]
        b.note(subject, f"range {span.low:g}–{span.high:g} {span.unit} (its section)", at)


def _as_number(spec: dict[str, Any], span: Range) -> bool:
    """The span as the setting's range, on the step read before where it fits the span."""
    step = float(spec["ranges"][0][2] or 1)
    count = (span.high - span.low) / step
    if abs(count - round(count)) > 1e-9 or count > 5000:
        step = 1.0 if span.high - span.low >= 1 else (span.high - span.low) / 10
    spec["ranges"] = [[_tidy(span.low), _tidy(span.high), _tidy(step)]]
    if span.unit:
        spec["unit"] = span.unit
    initial = spec.get("initial")
    if initial is not None and not span.low <= float(initial) <= span.high:
        spec.pop("initial")
    return True


def _as_time(spec: dict[str, Any], span: Range, label: str) -> None:
    """A span in seconds, minutes or hours: the setting is a time (whole minutes step by one)."""
    low, high = seconds(span.low, span.unit), seconds(span.high, span.unit)
    step = 60 if low % 60 == 0 and high % 60 == 0 else 1
    wrap = spec.get("wrap")
    spec.clear()
    spec.update(
        {
            "type": "time",
            "ranges": [[format_hms(low), format_hms(high), step]],
            "format": "h:mm" if high >= 3600 and step % 60 == 0 else "mm:ss",
            "label": label,
        }
    )
    if wrap:
        spec["wrap"] = True


def _tidy(x: float) -> float | int:
    return int(x) if float(x).is_integer() else x
