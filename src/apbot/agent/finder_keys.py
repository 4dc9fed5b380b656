"""The keys the variable finder presses and the screens it reads, apart from the finder itself.

The finder (:mod:`apbot.agent.discovery`) and its last resort, re-entering a procedure
(:mod:`apbot.agent.reentry`), both type digits, press keys the belief does not know, and read a
setting's part of a display; these small helpers are that shared ground, kept here so that
both import them without importing each other.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from apbot.agent.session import Executed, Session
from apbot.agent.setting_texts import GAP
from apbot.model.key_roles import adjusted_by, is_switch, misread_key
from apbot.plan.plan import PlannedAction
from apbot.read.actions import action_info


def _digit_keys(actions: Sequence[str]) -> dict[str, str]:
    """The keypad: digit → action (``press_7``, ``press_7_button``)."""
    return {str(action_info(a).digit): a for a in actions if _is_digit(a)}


def _is_digit(action: str) -> bool:
    """A keypad digit: typing is not walking (a missing keypad setting is not looked for)."""
    return action_info(action).digit is not None


def _unknown(done: Executed) -> bool:
    """The press showed text the belief cannot read (or reads only in part, or only as a value
    its setting cannot have: ``DELAY 0:00`` for a ``DELAY MODE`` of standard/intensive)."""
    seen = done.seen
    return seen is not None and (
        seen.unknown or seen.partial or (seen.screen is not None and seen.screen in seen.outside)
    )


# the last word of a stepping pair's forward key's name → its backward key's (▲ ▼, + −)
_PAIRS = {"up": "down", "plus": "minus", "next": "prev"}


def _is_reverse(action: str) -> bool:
    """The backward key of a pair: the finder walks the forward one."""
    info = action_info(action)
    return info.skill == "turn_ccw" or info.token.rsplit("_", 1)[-1] in _PAIRS.values()


def _press_digit(session: Session, action: str) -> Executed:
    """One key of a typed entry, as the belief plans it where it knows the key."""
    known = action in session.belief.model.actions
    planned = (session.planned(action) if known else None) or _planned(action)
    return session.press(planned, exploring=True)


def _planned(action: str) -> PlannedAction:
    """An action the belief does not know, as the panel would take it (a hold held long)."""
    skill = action_info(action).skill
    return PlannedAction(action, skill, (), 5.0 if skill == "hold" else None)


def _main(text: str, lamps: set[str]) -> str:
    """The main display: what comes before the lamps (two spaces apart), known or not."""
    parts = GAP.split(text.strip())
    while len(parts) > 1 and parts[-1].casefold() in lamps:
        parts.pop()
    return parts[0]  # a lamp the belief does not know is no part of the setting's screen


def _is_forward(action: str) -> bool:
    """The forward key of a stepping pair (▲, +, a dial turned clockwise), as named."""
    info = action_info(action)
    return info.skill == "turn_cw" or info.token.rsplit("_", 1)[-1] in _PAIRS


def stepping_suspects(session: Session, roled: Sequence[str], goal_value: Any) -> list[str]:
    """The forward stepping keys (▲, +, a dial turned clockwise) among ``roled`` whose role in
    the belief cannot hold ``goal_value`` ("57 °C" on ▲/▼ read as a timer's), the goal making
    no choice with them: a level is stepped on such keys, whatever the reader gave them to, so
    the finder walks them last. Never a long press: it does something else (a lock, a boost)."""
    model = session.belief.model
    goal = session.context.goal
    return [
        key
        for key in roled
        if _is_forward(key)
        and action_info(key).skill != "hold"
        and not _is_digit(key)
        and goal_value is not None
        and misread_key(model, key, goal_value)
        and not any(v in goal and not is_switch(model, v) for v in adjusted_by(model, key))
    ]


def opposite_key(key: str, offered: Sequence[str]) -> str | None:
    """The key among ``offered`` that walks the other way from ``key`` (``turn_x_ccw`` for
    ``turn_x_cw``, ``press_vol_down`` for ``press_vol_up``), however the panel spells its
    names (``press_vol_down_button``); none for a key that is no forward key of a pair."""
    info = action_info(key)
    if info.skill == "turn_cw":
        wanted = ("turn_ccw", info.token)
    else:
        *head, last = info.token.split("_")
        if last not in _PAIRS:
            return None
        wanted = (info.skill, "_".join([*head, _PAIRS[last]]))
    found = [a for a in offered if (action_info(a).skill, action_info(a).token) == wanted]
    return found[0] if found else None
