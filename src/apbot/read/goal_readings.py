"""A reading held on the display: "hold the reading", "freeze the value on the screen",
"freeze what it shows" ask for the switch named HOLD (a meter's, a scale's, a thermometer's
DATA HOLD) — on. "hold" alone is a verb of every kind ("hold the key 3 s", "hold it at 60
degrees") and names no setting; only with the thing a display shows as its object does it
name the switch that freezes it."""

from __future__ import annotations

from apbot.read.goal_text import Text
from apbot.read.goal_values import name_words
from apbot.read.goal_view import Goal, Model

_FREEZING = frozenset({"hold", "holds", "holding", "freeze", "freezes", "freezing", "frozen"})
_SHOWN = frozenset(
    {"reading", "readings", "display", "value", "screen", "measurement", "result", "figure"}
)
_CONTROLS = frozenset({"button", "buttons", "key", "keys", "switch", "knob", "dial", "pad"})
_BETWEEN = frozenset({"the", "a", "its", "this", "that", "my", "current", "last"})


def frozen_readings(view: Model, text: Text, goal: Goal, where: dict[str, int]) -> None:
    """Set the one HOLD switch on when the instruction freezes or holds what the display
    shows."""
    holds = [
        info
        for info in view.infos.values()
        if info.role == "switch" and "hold" in (w.casefold() for w in name_words(info.name))
    ]
    if len(holds) != 1 or holds[0].name in goal or holds[0].on is None:
        return
    for k in range(len(text.tokens)):
        if text.word(k) not in _FREEZING:
            continue
        j = k + 1
        while text.word(j) in _BETWEEN:
            j += 1
        shown = text.word(j) in _SHOWN or (
            text.word(j) == "what" and text.word(j + 1) in ("it", "the")
        )  # "freeze what it shows"
        if text.word(j + 1) in _CONTROLS:
            continue  # "hold the DISPLAY button": a key held, no reading
        if shown:
            goal[holds[0].name] = holds[0].on
            where[holds[0].name] = k
            return
