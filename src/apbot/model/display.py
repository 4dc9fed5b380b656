"""What a model's display rules print: the one definition the simulator renders with and the
agent's display reader inverts.

A value is printed in its variable's notation (a time in its display ``format``, a number with
its unit, a discrete value as written); a variable being adjusted is shown through its ``show``
template (default: its label and value); an indicator lamp shows a short text or nothing.
Keeping these rules here, in the model, means a belief model predicts its display with exactly
the code that a simulator of the same model would use.

>>> from apbot.model.schema import NumericVariable, TimeVariable
>>> display_value(TimeVariable(type="time", ranges=[("00:00:00", "01:00:00", 60)],
...                            format="mm:ss"), "00:01:30")
'01:30'
>>> display_value(NumericVariable(type="numeric", ranges=[(0, 100, 5)], unit="%"), 40)
'40%'
"""

from __future__ import annotations

from typing import Any

from apbot.model.domain import AnyVariable, all_values
from apbot.model.schema import (
    TEMPLATE_FIELD,
    DiscreteVariable,
    Entry,
    NumericVariable,
    TimeVariable,
)
from apbot.model.values import format_time, parse_hms

ABSENT_TEXT = "--"  # a programme-dependent setting that does not exist in this programme
OFF_WORDS = frozenset({"off", "no", "none", "false", "disabled"})
DEFAULT_SHOW = "{label} {value}"


def display_value(spec: AnyVariable, value: Any) -> str:
    """A canonical value as the display prints it (``--`` for no value)."""
    if value is None:
        return ABSENT_TEXT
    if isinstance(spec, TimeVariable):
        return format_time(parse_hms(str(value)), spec.format)
    if isinstance(spec, NumericVariable) and spec.unit:
        return f"{value}{spec.unit}" if not spec.unit[0].isalnum() else f"{value} {spec.unit}"
    return str(value)


def show_template(spec: AnyVariable, value: Any) -> str:
    """The template the display uses for a variable being adjusted, when it has ``value``."""
    show = spec.show
    if isinstance(show, dict):
        show = show.get(str(value))
    return DEFAULT_SHOW if show is None else show


def lamp_for(spec: AnyVariable, name: str, value: Any, values: tuple[Any, ...] = ()) -> str:
    """What an indicator lamp shows when its variable has ``value`` (``values``: the whole
    domain, to tell an on/off lamp): the ``show`` text for the value when it names no other
    variable ("LOCK", "" for unlit); without one, nothing for an off value, else the label (an
    on/off lamp) or the label and the value ("CRUST DARK").

    >>> from apbot.model.schema import DiscreteVariable
    >>> lock = DiscreteVariable(type="discrete", values=["off", "on"])
    >>> lamp_for(lock, "child_lock", "on", ("off", "on")), lamp_for(lock, "child_lock", "off")
    ('CHILD LOCK', '')
    """
    if not spec.visible:
        return ""
    label = spec.display_label(name)
    show = spec.show.get(str(value)) if isinstance(spec.show, dict) else spec.show
    if show is not None:
        if set(template_fields(show)) <= {"value", "label"}:
            text = display_value(spec, value)
            return show.replace("{value}", text).replace("{label}", label).strip()
        return ""
    if value is None or str(value).casefold() in OFF_WORDS:
        return ""
    if (
        isinstance(spec, DiscreteVariable)
        and len(values) == 2
        and any(str(v).casefold() in OFF_WORDS for v in values)
    ):
        return label
    return f"{label} {display_value(spec, value)}".strip()


def template_fields(template: str) -> list[str]:
    """The variable names (and ``value``/``label``) a template prints."""
    return TEMPLATE_FIELD.findall(template)


def typed_text(entry: Entry, buffer: str) -> str:
    """Keypad digits as a display that shows them as typed prints them (``Entry.shows``):
    zero-padded into the entry's clock format, or as a number.

    >>> typed_text(Entry(format="hh:mm:ss"), "80"), typed_text(Entry(format="mm:ss"), "130")
    ('00:00:80', '01:30')
    >>> typed_text(Entry(format="number"), "07")
    '7'
    """
    fmt = entry.format
    if fmt in ("number", "minutes", "seconds"):
        return str(int(buffer or "0"))
    width = {"hh:mm:ss": 6, "h:mm": 3}.get(fmt, 4)
    padded = buffer.zfill(width)
    if fmt == "hh:mm:ss":
        return f"{padded[:-4]}:{padded[-4:-2]}:{padded[-2:]}"
    return f"{padded[:-2]}:{padded[-2:]}"


def can_show(model: Any, name: str) -> bool:
    """Whether any screen of ``model`` tells ``name``'s values apart: a lamp, another screen's
    template printing it, or its own screen (by default its label and value). An oven lamp whose
    own screen shows the same text whichever its value, and that nothing else prints, cannot be
    read off the display at all — nor can a ``visible: false`` setting.

    >>> from apbot.examples import load_example
    >>> can_show(load_example("microwave_keypad"), "cook_time")
    True
    """
    spec = model.variables[name]
    if not spec.visible:
        return False
    if name in model.display.indicators:
        return True
    field = "{" + name + "}"
    others = [model.display.idle, *(g.display or "" for g in model.guards)]
    for other, var in model.variables.items():
        if other != name:
            show = var.show
            others += list(show.values()) if isinstance(show, dict) else [show or ""]
    if any(field in text for text in others):
        return True
    if not isinstance(spec.show, dict):
        return "{value}" in show_template(spec, None)
    values = all_values(spec)
    texts = {show_template(spec, v).replace("{value}", display_value(spec, v)) for v in values}
    return len(texts) > 1 or len(values) < 2
