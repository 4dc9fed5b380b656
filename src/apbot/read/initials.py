"""The settings an appliance starts with, read from the list a manual prints of them.

Manuals often list the start state in one line after a colon: "Every time you switch on, the
cushion starts with these settings: programme A1 · zone FULL · heat off · timer 15 min ·
intensity 3", "The appliance starts with the factory settings: fridge +5 °C, freezer -18 °C,
…", "the smoker shows its factory settings: 225°F, 3:00 and …". Each item names a setting
and its value (the value alone when only one setting can hold it: the one time setting for
"3:00"). The plan starts from the belief, so a wrong start value costs presses or a goal;
this reads the start values printed, leaving every setting the list does not name as it was.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import format_hms, parse_hms
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.shapes import GROUP_NOUNS

_START_LIST = re.compile(
    r"\b(?:starts?(?:\s+up)?\s+(?:with|in|on)|shows?)\s+(?:these|the|its)\s+"
    r"(?:factory\s+|default\s+|standard\s+|basic\s+)?settings\s*:\s*(?P<items>.*)$"
    # a sentence of its own: "Factory settings: tracking SID, hemisphere N, backlight 3."
    r"|^\W*(?:the\s+)?(?:factory|default)\s+settings(?:\s+are)?\s*:\s*(?P<own>.+)$",
    re.IGNORECASE,
)
_NUMBER = re.compile(r"[+-]?\d+(?:[.,]\d+)?")
_CLOCK = re.compile(r"\b(\d{1,2}):([0-5]\d)\b")
_DURATION = re.compile(r"\b(\d+(?:[.,]\d+)?)\s*(h|hours?|min|mins|minutes?|s|sec|seconds?)\b", re.I)


def read_initials(b: Builder) -> None:
    """Give the settings a start-settings list names their start values."""
    units = b.manual.units
    for i, unit in enumerate(units):
        m = _START_LIST.search(unit.text)
        if m is None or _of_a_choice(b, unit.text[: m.start()]):
            continue
        listed = (m.group("items") or m.group("own") or "").strip()
        if not listed and i + 1 < len(units):
            listed = units[i + 1].text  # the list on the line after the colon
        if _apply(b, listed, i):
            break
    read_delivered(b)


# a sentence saying how the appliance comes: "On delivery the hair type is NORMAL.", "When
# delivered, the remote shows AUTO STD.", "As supplied, the unit is °C."
_DELIVERED = re.compile(
    r"^\W*(?:on\s+delivery|(?:when|as)\s+(?:delivered|supplied|shipped)|out\s+of\s+the\s+box"
    r"|from\s+the\s+factory|ex\s+works)\b[,:]?\s*(?P<rest>[^.;]+)",
    re.IGNORECASE,
)


def read_delivered(b: Builder) -> None:
    """Start values said in a sentence about how the appliance comes, for the settings that have
    none yet, item by item ("cone 04, speed MED, hold 0"): the setting an item names ("the hair
    type is NORMAL"), or else each word that is a value of exactly one setting ("the remote
    shows AUTO STD": the mode AUTO, the suction STD)."""
    for i, unit in enumerate(b.manual.units):
        m = _DELIVERED.match(unit.text)
        if m is None or unit.cells:
            continue
        for item in re.split(r"\s*(?:·|,|;|\band\b)\s*", m.group("rest")):
            var = _named_in(b, item)
            if var is not None:
                spec = b.variables[var]
                value = _value(spec, item)
                if "initial" not in spec and not spec.get("depends_on") and value is not None:
                    _start(b, var, value, i)
                continue
            for token in re.findall(r"[\w.+-]+", item.lower()):
                owners = [
                    name
                    for name, spec in b.variables.items()
                    if spec.get("type") == "discrete"
                    and not spec.get("depends_on")
                    and token in [str(v).lower() for v in spec.get("values") or []]
                    and token not in ("on", "off")
                ]
                if len(owners) == 1 and "initial" not in b.variables[owners[0]]:
                    values = b.variables[owners[0]]["values"]
                    _start(b, owners[0], next(v for v in values if str(v).lower() == token), i)


def _start(b: Builder, var: str, value: Any, at: int) -> None:
    b.variables[var]["initial"] = value
    b.note(f"variables.{var}.initial", f"starts at {value} (as delivered)", at)


def _of_a_choice(b: Builder, subject: str) -> bool:
    """Whether what starts with the list is a programme, not the appliance: "The FISH
    programme starts with these settings: 160 °C, 12 min" gives that programme's values."""
    said = set(words(subject))
    if said & set(GROUP_NOUNS):
        return True
    values = {
        w
        for spec in b.variables.values()
        if spec.get("type") == "discrete"
        for v in spec.get("values") or []
        for w in words(str(v))
        if len(w) >= 3 and w not in ("off", "on")
    }
    return bool(said & values)


def _apply(b: Builder, listed: str, at: int) -> bool:
    items = [s for s in re.split(r"\s*(?:·|,|;|\band\b)\s*", listed) if s.strip()]
    set_any = False
    named: set[str] = set()
    for item in items:
        var = _named_in(b, item)
        if var is not None:
            named.add(var)
            value = _value(b.variables[var], item)
        else:
            var, value = _by_value(b, item, named)
        if var is None or value is None:
            continue
        b.variables[var]["initial"] = value
        b.note(f"variables.{var}.initial", f"starts at {value} (the start settings listed)", at)
        named.add(var)
        set_any = True
    return set_any


def _named_in(b: Builder, item: str) -> str | None:
    """The setting an item names by its name or its label ("zone FULL", "timer 15 min")."""
    said = set(words(item))
    for name, spec in b.variables.items():
        if name in ("power", "running"):
            continue
        names = words(name.replace("_", " "))
        label = [w for w in words(str(spec.get("label", ""))) if w.isalpha() and len(w) >= 3]
        if (names and set(names) <= said) or (label and set(label) <= said):
            return name
    return None


def _value(spec: dict[str, Any], item: str) -> Any:
    """The value an item gives a setting, when the setting can hold it; else None."""
    text = item.lower()
    kind = spec.get("type")
    if kind == "discrete":
        values = [str(v) for v in spec.get("values") or []]
        shown = {str(c).lower(): v for v, c in (spec.get("show") or {}).items()}
        tokens = [t.rstrip(".") for t in re.findall(r"[+-]?[\w.]+", text)]  # ("off." ends it)
        for token in tokens:  # the value itself first: "child lock off" is off, whatever LOCK shows
            if token in values:
                return token
        for token in tokens:
            if token in shown and shown[token] in values:
                return shown[token]
        return None
    if kind == "time":
        return _time(spec, text)
    if kind == "numeric":
        ranges = spec.get("ranges") or []
        for m in _NUMBER.finditer(text):
            x = float(m.group(0).replace(",", "."))
            if any(r[0] <= x <= r[1] for r in ranges):
                return int(x) if x.is_integer() else x
    return None


def _time(spec: dict[str, Any], text: str) -> str | None:
    """A start time in the setting's range: "15 min", "2 h", or "3:00" read as h:mm or
    mm:ss, whichever the range holds."""
    bounds = [(parse_hms(str(r[0])), parse_hms(str(r[1]))) for r in spec.get("ranges") or []]
    candidates: list[int] = []
    if (m := _CLOCK.search(text)) is not None:
        a, b_ = int(m.group(1)), int(m.group(2))
        candidates += [a * 3600 + b_ * 60, a * 60 + b_]
    elif (m := _DURATION.search(text)) is not None:
        x = float(m.group(1).replace(",", "."))
        unit = m.group(2).lower()
        scale = 3600 if unit.startswith("h") else 60 if unit.startswith("m") else 1
        candidates.append(int(x * scale))
    for seconds in candidates:
        if any(lo <= seconds <= hi for lo, hi in bounds):
            return format_hms(seconds)
    return None


def _by_value(b: Builder, item: str, named: set[str]) -> tuple[str | None, Any]:
    """An item that names no setting: the one setting not yet given a start value that can
    hold its value ("3:00" and a single time setting); None when none or several can."""
    if not re.search(r"\d", item):
        return None, None
    fits = [
        (name, value)
        for name, spec in b.variables.items()
        if name not in named
        and spec.get("type") in ("numeric", "time")
        and not _other_sign(item, str(spec.get("unit") or ""))
        and (value := _value(spec, item)) is not None
    ]
    return fits[0] if len(fits) == 1 else (None, None)


def _other_sign(item: str, unit: str) -> bool:
    """Whether the item's figure carries a sign the setting's unit is not ("20°" for a count
    of passes, "40 %" for a time): an amount of another setting."""
    sign = re.search(r"\d\s*(°[CF]?|%)", item)
    return sign is not None and (not unit or unit[0] != sign[1][0])
