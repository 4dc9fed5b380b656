"""Superlatives a panel's own key names: "the finest setting" where a key turns the dial finer.

A dial or a pair of keys named by what they do (``turn_finer`` / ``turn_coarser``,
``press_faster`` / ``press_slower``) tells which end of its setting a superlative of that word
is: the end the key runs to. "The finest" is where turning finer stops — the lowest position on
a mill whose numbers grow coarser, whatever "fineness" would suggest — and "the second finest"
one step back from it. Only for an open ordered setting the key steps one way (``next`` or
``prev``), and only when one such key is named by the word.
"""

from __future__ import annotations

from apbot.read.goal_ladders import ordered
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_view import Goal, Model

_OFFSETS = {"second": 1, "third": 2}


def keyed_end(view: Model, goal: Goal, word: str) -> tuple[str, int] | None:
    """(setting, end) for a superlative made of a key's own comparative word ("finest" of
    ``turn_finer``): end 0 when that key steps the setting back, -1 when it steps it on."""
    if not word.isalpha() or not word.endswith("est") or len(word) < 6:
        return None
    said = word[:-3] + "er"  # finest → finer, hottest → hotter, dimmest → dimmer
    found: set[tuple[str, int]] = set()
    for steps in view.model.features.values():
        for step in steps:
            name = step.variable
            if name is None or name in goal or not isinstance(step.effect, dict):
                continue
            info = view.infos.get(name)
            if info is None or info.role != "setting" or not ordered(info):
                continue
            for action, effect in step.effect.items():
                if said in action.split("_") and effect in ("next", "prev"):
                    found.add((name, -1 if effect == "next" else 0))
    return found.pop() if len(found) == 1 else None


def at_the_latest(text: Text, k: int) -> bool:
    """ "ready by noon at the latest", "start it at the earliest by six": the idiom of a
    deadline ("no later than"), not the end a LATER / EARLIER key steps to."""
    return (
        text.word(k) in ("latest", "earliest", "soonest")
        and (text.word(k - 2), text.word(k - 1)) == ("at", "the")
        and text.word(k + 1) in CLAUSE_ENDS | {"", ",", "by", "before", "on", "at"}
    )


def keyed_offset(text: Text, k: int) -> int:
    """Steps back from the end: "the second finest" is one."""
    return _OFFSETS.get(text.word(k - 1), 0)
