"""Which settings of a belief are programmes: choosing one may bring others back to defaults.

A manual says far less often than the panel does that choosing a programme (a menu, a mode)
puts its settings back to that programme's defaults; nothing on the display shows it happen.
The agent therefore orders programmes first when plans tie (:mod:`apbot.agent.planning`) and
doubts what the display showed of other settings once a programme was chosen again
(:mod:`apbot.agent.pressing`).
"""

from __future__ import annotations

import re

from apbot.model.schema import ApplianceModel, DiscreteVariable


def programmes(model: ApplianceModel) -> set[str]:
    """The belief's programme-like settings: those others depend on, and choices among several
    named values (a mode, a menu, a programme: three or more values, not figures). Choosing
    one of them is what brings other settings back to its defaults on many appliances, said in
    the manual or not; choosing one first costs nothing when the plans' lengths tie."""
    found = {v.depends_on for v in model.variables.values() if v.depends_on}
    for name, spec in model.variables.items():
        values = [str(v) for v in (spec.values or ())] if isinstance(spec, DiscreteVariable) else []
        named = len(values) > 2 and sum(not _figure(v) for v in values) > len(values) // 2
        if named or (len(values) == 2 and _selector(values)):
            found.add(name)
    return {n for n in found if n is not None}


def selectors(model: ApplianceModel) -> set[str]:
    """The programmes that choose a part (two named values, :func:`_selector`): chosen before
    the other programmes, for a part (the right bowl) may keep its own mode as well."""
    return {
        name
        for name, spec in model.variables.items()
        if isinstance(spec, DiscreteVariable)
        and len(spec.values or ()) == 2
        and _selector([str(v) for v in spec.values or ()])
    }


_SWITCH_WORDS = frozenset({"off", "on", "no", "yes", "none", "0", "1"})


def _selector(values: list[str]) -> bool:
    """Two named values neither of which is a switch's word (``left``/``right``, ``upper``/
    ``lower``, ``A``/``B``): a choice of which part the other keys act on, which may keep its
    own settings, so it comes first like a programme. A switch (on/off, yes/no, a lock's
    locked/unlocked, a value and ``none``) adjusts, it does not select."""
    words = [v.strip().casefold() for v in values]
    if any(_figure(v) or w in _SWITCH_WORDS for v, w in zip(values, words, strict=True)):
        return False
    first, second = words
    return not (first in second or second in first)  # locked / unlocked


def _figure(value: str) -> bool:
    """Whether a value is a number (``3``, ``1.5``, ``40%``): a level, not a named choice."""
    return bool(re.fullmatch(r"[\d.,:]+\s*\S{0,3}", value.strip()))
