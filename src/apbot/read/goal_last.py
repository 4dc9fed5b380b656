"""The last of a numbered setting: "the last kit" is kit 30 where kits run 1-30, as "the first
kit" is kit 1 (:mod:`apbot.read.goal_ordinals`). Only before a word of a unitless setting of
whole numbers (kits, slots, presets, channels counted one by one), written as that setting's
number before the sentence is read.
"""

from __future__ import annotations

import re
from itertools import pairwise

from apbot.model.domain import build_domain
from apbot.model.schema import NumericVariable
from apbot.read.goal_view import Model
from apbot.read.goal_vocab import concept

_LAST = re.compile(r"\b(the\s+(?:very\s+)?)(last|final)\s+([A-Za-z]+)\b", re.IGNORECASE)


def said_last(view: Model, instruction: str) -> str:
    """ "the last kit" as "the kit 30"."""

    def last(m: re.Match[str]) -> str:
        key = concept(m[3].casefold())
        named = [
            info
            for info in view.infos.values()
            if info.role == "setting"
            and isinstance(info.var, NumericVariable)
            and not info.var.unit
            and not info.var.depends_on
            and info.vocab.get(key, 0.0) >= 1.0
        ]
        if len(named) != 1:
            return m[0]
        numbers = build_domain(named[0].var).magnitudes or ()
        whole = all(float(n).is_integer() for n in numbers)
        steps = {b - a for a, b in pairwise(numbers)}
        if len(numbers) < 3 or not whole or steps != {1.0}:
            return m[0]
        return f"{m[1]}{m[3]} {int(numbers[-1])}"

    return _LAST.sub(last, instruction)
