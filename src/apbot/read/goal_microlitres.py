"""Small volumes on a setting counted in microlitres: "one millilitre" is 1000.

A pipette or a dosing pump counts its volume in µL, and people say either µL or the millilitre
it makes. On a model with a setting in µL (and none in mL or L), millilitres said (in figures or
in words) are written as the microlitres they make, before the instruction is read. ("625 µL"
itself is read as microlitres by the tokeniser, `number_tokens`, on every model.)
"""

from __future__ import annotations

import re

from apbot.model.schema import NumericVariable
from apbot.model.values import words_to_number
from apbot.read.goal_view import Model

_MICRO = ("µl", "μl", "ul")
_MILLI = re.compile(
    r"\b((?:[a-z]+[ -]){0,3}[a-z]+|\d+(?:\.\d+)?)\s*(?:ml|millilit(?:re|er)s?)\b", re.IGNORECASE
)


def _in_microlitres(view: Model) -> bool:
    units = {
        (info.var.unit or "").casefold()
        for info in view.infos.values()
        if isinstance(info.var, NumericVariable)
    }
    return bool(units & set(_MICRO)) and not units & {"ml", "l"}


def _number(said: str) -> tuple[float, str] | None:
    """The number the longest tail of ``said`` reads as, and the words before it."""
    words = re.split(r"([ -])", said)
    for k in range(0, len(words), 2):
        tail = "".join(words[k:])
        number = 1.0 if tail.casefold() in ("a", "one") else words_to_number(tail)
        if number is not None:
            return number, "".join(words[:k])
    return None


def said_microlitres(view: Model, instruction: str) -> str:
    """ "one millilitre" as "1000 microlitres", "0.5 ml" as "500 microlitres"."""
    if not _in_microlitres(view):
        return instruction

    def milli(match: re.Match[str]) -> str:
        read = _number(match[1])
        if read is None:
            return match[0]
        number, before = read
        return f"{before}{number * 1000:g} microlitres"

    return _MILLI.sub(milli, instruction)
