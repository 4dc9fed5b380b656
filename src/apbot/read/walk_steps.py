"""The steps of a walk as the manual writes them: numbered steps, or a paragraph of prose.

Many manuals tell a walk in running prose rather than numbered steps: "Press and hold SET for
3 seconds. The hour flashes. Press + or - to set the hour. Press SET again and the minutes
flash. Press + or - to set the minutes." Each sentence that tells the reader to work a key
begins a step; a sentence that only says what the display does ("The hour flashes.") belongs
to the step before it. Read so, a prose walk has the same steps as its numbered form.
"""

from __future__ import annotations

import re

from apbot.read.text import Unit

# a sentence that works a key, so begins a step: "Press SET again …", "Then hold ▲ …"
_ACTS_RE = re.compile(
    r"^(?:then,?\s+|now,?\s+|next,?\s+)?(?:press|touch|tap|push|hold|turn|use|keep)\b", re.I
)
_MAX_STEPS = 9


def walk_steps(units: list[Unit], i: int) -> list[tuple[int, str]]:
    """The steps from unit ``i`` on, each with the sentences that follow it: numbered steps
    when unit ``i`` is one, else the sentences of its prose (within its section, up to a
    table, a list or a heading)."""
    if units[i].step is not None:
        return _numbered(units, i)
    return _prose(units, i)


def _numbered(units: list[Unit], i: int) -> list[tuple[int, str]]:
    out: list[tuple[int, str]] = []
    first = units[i].step
    for u in units[i:]:
        if u.step is not None:
            if first is None or u.step != first + len(out) or len(out) >= _MAX_STEPS:
                break
            out.append((u.step, u.text))
        elif u.cells or u.heading != units[i].heading:
            break
        else:
            out[-1] = (out[-1][0], f"{out[-1][1]} {u.text}")
    return out


def _prose(units: list[Unit], i: int) -> list[tuple[int, str]]:
    out: list[tuple[int, str]] = []
    for u in units[i:]:
        if u.cells or u.bullet or u.step is not None or u.heading != units[i].heading:
            break
        if not out or _ACTS_RE.match(u.text):
            if len(out) >= _MAX_STEPS:
                break
            out.append((len(out) + 1, u.text))
        else:
            out[-1] = (out[-1][0], f"{out[-1][1]} {u.text}")
    return out


def prose_opener(unit: Unit, paired: bool) -> bool:
    """A sentence of running prose (not a step, a list item or a table row) that may open a
    walk told in prose; not a hold of a stepping key ("Hold ▲ or ▼ for 2 seconds: the desk
    travels 10 cm"), which steps a value fast rather than opening fields."""
    return unit.step is None and not unit.bullet and not unit.cells and not paired
