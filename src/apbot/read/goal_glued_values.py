"""A value's name glued to the noun the manual says it of: "autopilot" for AUTO ("AUTO – engage
the pilot"), "ecowash" for ECO beside "wash".

People fuse a mode's name with what it does into one word. Such a word is read as the two
words it is made of — only when it opens with a value's name (four letters or more), the rest
is a word of four letters or more, and one line of the manual prints both words apart (the key
legend or the table row that says what the value does). A word the model itself uses whole
(a value, a setting's name) is left as it is.
"""

from __future__ import annotations

import re

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_view import Model, own_stems
from apbot.read.goal_vocab import stem

_WORD = re.compile(r"\b[A-Za-z]{8,}\b")
_SHORTEST = 4


def _value_names(view: Model) -> set[str]:
    names: set[str] = set()
    for info in view.infos.values():
        if info.role == "setting" and isinstance(info.var, DiscreteVariable):
            names |= {
                str(v).casefold()
                for v in info.values
                if str(v).isalpha() and len(str(v)) >= _SHORTEST
            }
    return names


def _printed_apart(view: Model, name: str, rest: str) -> bool:
    both = (re.compile(rf"\b{re.escape(name)}\b"), re.compile(rf"\b{re.escape(rest)}\b"))
    return any(all(p.search(line) for p in both) for line in view.manual_lines)


def said_glued_values(view: Model, instruction: str) -> str:
    """ "under autopilot" as "under auto pilot" when the manual says AUTO engages the pilot."""
    names = _value_names(view)
    if not names or not view.manual_lines:
        return instruction
    own = {s for info in view.infos.values() for s in own_stems(info)}
    own |= {s for _var, _value, stems, _weight in view.phrases if len(stems) == 1 for s in stems}

    def split(match: re.Match[str]) -> str:
        word = match[0].casefold()
        if stem(word) in own:
            return match[0]
        for name in sorted(names, key=len, reverse=True):
            rest = word[len(name) :]
            if (
                word.startswith(name)
                and len(rest) >= _SHORTEST
                and _printed_apart(view, name, rest)
            ):
                return f"{match[0][: len(name)]} {match[0][len(name) :]}"
        return match[0]

    return _WORD.sub(split, instruction)
