"""Times of day said in a row fill numbered time settings in that order.

A pill dispenser keeps ALARM 1 … ALARM 4, a feeder MEAL 1 … MEAL 4: settings of one kind whose
names differ only by a number. People list the times ("three doses: 9 am, 3 pm and 9 pm",
"twice a day, at seven a.m. and seven p.m.") and mean the first for the first setting, the
second for the second; "the last at 10 pm" is the highest one the goal leaves in use, "the
second at noon" the second. The rest of the parser gives every time to the one setting its
words name best, so it fills one alarm and drops the others; this step places them all.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.schema import TimeVariable
from apbot.read.goal_fit import fit
from apbot.read.goal_ordinals import ORDINALS
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model, domain_values
from apbot.read.numbers import Mention

_NUMBERED = re.compile(r"(.*?)[_ ]?(\d)$")
_LAST = frozenset({"last", "final"})


def numbered_family(view: Model) -> list[str]:
    """The time settings named alike but for a closing number 1, 2, 3 … (in that order)."""
    groups: dict[str, dict[int, str]] = {}
    for name, info in view.infos.items():
        match = _NUMBERED.fullmatch(name)
        if match and isinstance(info.var, TimeVariable) and info.role == "setting":
            groups.setdefault(match[1], {})[int(match[2])] = name
    for members in groups.values():
        if len(members) >= 2 and sorted(members) == list(range(1, len(members) + 1)):
            return [members[k] for k in sorted(members)]
    return []


def numbered_times(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
) -> None:
    """Give the times of day said, in order, to the numbered time settings."""
    family = numbered_family(view)
    if not family:
        return
    others = {where[n] for n in goal if n in where and n not in family}
    times = [m for m in mentions if m.kind == "clock" and m.start not in others]
    if len(times) < 2 and not any(_ordinal_before(text, m) for m in times):
        return  # one time said: the rest of the parser has placed it by its words
    for name in family:
        goal.pop(name, None)
        where.pop(name, None)
    in_use = [n for n in family if domain_values(view, view.infos[n], goal)]
    free = list(in_use)
    for mention in times:
        said = _ordinal_before(text, mention)
        if said == -1 and in_use:
            name = in_use[-1]
        elif said and said <= len(family):
            name = family[said - 1]
        else:
            name = next((n for n in free if n not in goal), "")
        if not name or name in goal:
            continue
        value: Any = fit(view, view.infos[name], mention, goal)
        if value is None:
            continue
        goal[name] = value
        where[name] = mention.start
        claimed.update(range(mention.start, mention.end))


def _ordinal_before(text: Text, mention: Mention) -> int:
    """ "the first at 6:30", "the last at 10 pm", "dose 2 at noon": the number the words just
    before the time give it (-1 for the last; 0 when none)."""
    for k in range(mention.start - 1, max(-1, mention.start - 6), -1):
        word = text.word(k)
        if word in (",", ";", "and", "."):
            return 0
        if word in ORDINALS:
            return ORDINALS[word]
        if word in _LAST:
            return -1
    return 0
