"""A mode whose panel name cuts a word short, said in full before "mode": "discrimination mode"
for DISC, "jewellery mode" for JEWEL. The full word may be another setting's name (a detector's
DISC LV level is its discrimination too); said right before "mode" it names the mode. Written
as the panel's value before the sentence is read, only where one value of a setting named
"mode" starts the word (three letters or more), the word is no value itself, and no other
setting's name is the word followed by "mode".
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import DiscreteVariable
from apbot.read.goal_view import Model
from apbot.read.goal_vocab import concept

_SAID = re.compile(r"\b([A-Za-z]{5,})(\s+mode)\b", re.IGNORECASE)
_MODE = concept("mode")


def said_mode_cuts(view: Model, instruction: str) -> str:
    """ "Discrimination mode" as "disc mode" where the mode setting lists DISC."""
    values = [
        str(v)
        for info in view.infos.values()
        if isinstance(info.var, DiscreteVariable) and info.vocab.get(_MODE, 0.0) >= 1.0
        for v in all_values(info.var)
        if re.fullmatch(r"[a-z]{3,}", str(v).casefold())
    ]
    if not values:
        return instruction

    def cut(m: re.Match[str]) -> str:
        word = m[1].casefold()
        if word in (v.casefold() for v in values):
            return m[0]
        starts = [v for v in values if word.startswith(v.casefold())]
        return f"{starts[0]}{m[2]}" if len(starts) == 1 else m[0]

    return _SAID.sub(cut, instruction)
