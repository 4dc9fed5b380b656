"""The unit a setting's name calls for ("heat time" is minutes, "volume" ml, "spin" rpm), the unit
families a range must fall in to belong to it, and a step to guess when the manual gives none
(split from ``shapes``)."""

from __future__ import annotations

from apbot.read.labels import words


def _unit_from_words(name: str) -> str:
    """The unit a setting's name calls for; its last word, the head noun, decides first
    ("heat time" is a time, "time temp" a temperature)."""
    listed = words(name.replace("_", " "))
    head = listed[-1] if len(listed) >= 2 else ""
    if head in ("temp", "temperature"):
        return "°C"
    if head in ("time", "timer", "delay", "duration"):
        return "min"
    ws = set(listed)
    if ws & {"temp", "temperature", "heat"}:
        return "°C"
    if ws & {"humidity", "percent"}:
        return "%"
    if ws & {"time", "timer", "delay", "duration", "cook"}:
        return "min"
    return ""


QUANTITY_FAMILIES = {  # a setting named for a quantity takes a range in one of its units
    "ml": frozenset({"ml", "l", "cl", "dl", "cups", "cup", "µl", "μl"}),
    "g": frozenset({"g", "kg", "lb", "lbs"}),
    "W": frozenset({"W", "kw"}),
    "rpm": frozenset({"rpm"}),
}


QUANTITY_WORDS = {
    "volume": "ml", "capacity": "ml", "weight": "g",
    "watt": "W", "watts": "W", "wattage": "W", "output": "W", "spin": "rpm", "rpm": "rpm",
    "speed": "rpm",  # (a speed read with a unit is rpm; km/h, spm are read without one)
}  # fmt: skip


def _quantity_unit(name: str) -> str:
    """:func:`_unit_from_words`, and for a quantity its unit (volume → ml, weight → g, watts →
    W, spin → rpm): a range must be in that unit's family to belong to the setting."""
    unit = _unit_from_words(name)
    if unit:
        return unit
    for w in words(name.replace("_", " ")):
        if w in QUANTITY_WORDS:
            return QUANTITY_WORDS[w]
    return ""


def _quantity_units(tokens: list[str]) -> list[str]:
    """The units the words of a setting's name call for, in order: each word's own
    (:func:`_quantity_unit`), and ml where water is the setting's own noun ("water", "amount of
    water") — in "water hardness" or "water level" it names what is measured, in another unit."""
    units = [u for u in (_quantity_unit(t) for t in tokens) if u]
    ws = [w for t in tokens for w in words(t.replace("_", " "))]
    if ws and (ws[-1] == "water" or {"water", "amount"} <= set(ws)):
        units.append("ml")
    return units


def _guess_step(span: float, unit: str) -> float:
    if unit == "%":
        return 5
    if unit in ("°C", "°F"):
        return 5 if span > 40 else 1
    if unit in ("min", "s", "h"):
        return 1
    for step in (1, 5, 10, 50, 100, 500, 1000):
        if span / step <= 40:
            return step
    return max(1.0, span / 40)


def _tidy(x: float) -> float | int:
    return int(x) if float(x).is_integer() else round(float(x), 4)
