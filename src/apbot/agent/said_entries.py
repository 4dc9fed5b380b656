"""Quantities the user said that the goal, as read, does not hold: handed to the variable finder.

The goal parser opens an entry for a setting the read belief lacks only where the panel points
at it (:mod:`apbot.read.goal_open`: a key's own noun, a kind no belief setting takes), since a
wrong entry there would mislead eval-goals' precision. Everything else it cannot place is left
out, and the run could only end "partly done: not understood: 180 ml" — a failure whatever it
set. A quantity said with its unit ("180 ml", "99 seconds", "57 °C") asks for *some* setting of
the appliance, so where the goal holds it nowhere the agent looks for it on the panel as well:
an entry named by its kind (``volume``, ``time``, ``temperature``), which the finder
(:mod:`apbot.agent.discovery`) walks the keys the belief gives no role for, exactly as it does
for the parser's open entries. If the panel shows nothing of it, the run ends as before (the
rest set, no claim), so a task that could not succeed is all this can change.

Only quantities with a unit — a bare number ("code 2580", "user 2") names no kind a display
could be matched against — and never a clock time, a count of things, or a number the
unread-parts judge says asks nothing (:mod:`apbot.agent.unread`).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from apbot.agent.unread import _asks_nothing, _goal_numbers, _held
from apbot.model.schema import ApplianceModel
from apbot.read.goal_error import GoalParseError
from apbot.read.goal_open import KIND_NAMES, quantity_kind
from apbot.read.goal_remarks import without_remarks
from apbot.read.goal_said import as_said, in_days
from apbot.read.goal_text import Text
from apbot.read.goal_view import model_view
from apbot.read.numbers import find_mentions


def said_entries(
    belief: ApplianceModel, instruction: str, goal: Mapping[str, Any], manual: str = ""
) -> dict[str, Any]:
    """Entries (new name → the value as said) for the quantities with a unit that
    ``instruction`` says and no value of ``goal`` holds; names never a belief variable's or a
    goal setting's."""
    view = model_view(belief, manual)
    try:
        plain = without_remarks(view, instruction)
    except (GoalParseError, ValueError):
        plain = instruction
    text = Text.of(plain)
    tokens = text.tokens
    named = {  # a coded value the manual gives as a quantity: knob mark 2 is "160 °C"
        f"{name} {label}": value
        for name, pairs in view.named_quantities.items()
        for value, label in pairs
        if name in goal and str(value) == str(goal[name])
    }
    held = _goal_numbers({**goal, **named})
    taken = set(belief.variables) | set(goal)
    entries: dict[str, Any] = {}
    for mention in find_mentions(tokens):
        kind = quantity_kind(mention)  # a number of things ("3 cups") is no quantity here
        if kind is None or kind == "count" or kind not in KIND_NAMES:
            continue
        if _asks_nothing(mention, tokens) or _held(mention, tokens, held):
            continue
        value = as_said(text, mention)
        if value is None:
            continue
        name = "days" if kind == "time" and in_days(text, mention) else KIND_NAMES[kind]
        base, n = name, 2
        while name in taken or name in entries:
            name, n = f"{base}_{n}", n + 1
        entries[name] = value
    return entries
