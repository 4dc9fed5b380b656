"""A setting's own on/off switch, said as the setting switched: "switch on the second meal",
"turn off meal 3", "meal four at midnight, and switch it on".

A feeder keeps per meal slot whether it feeds (MEAL ON beside MEAL); a timer keeps per
programme whether it runs. The switch's name is the setting's and a state word, so the rest of
the parser reads "the second meal" as the setting and leaves the switch. Here a verb of
switching said of the setting's word, or of "it" when the setting was named, sets the switch.
"""

from __future__ import annotations

from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model
from apbot.read.goal_vocab import stem

_STATE_SUFFIXES = ("_on", "_enabled", "_active")
_VERBS = frozenset({"switch", "turn", "switched", "turned", "put", "set"})
_ENABLE = {"enable": "on", "disable": "off", "activate": "on", "deactivate": "off"}
_BREAKS = frozenset({",", ";", ".", "!", "?", "and", "then", "but", "-"})


def _own_switches(view: Model) -> dict[str, str]:
    """switch -> the setting it belongs to (MEAL ON -> MEAL)."""
    found = {}
    for name, info in view.infos.items():
        if info.role != "switch" or info.on is None:
            continue
        for suffix in _STATE_SUFFIXES:
            base = name[: -len(suffix)]
            if name.endswith(suffix) and base in view.infos and base != name:
                found[name] = base
    return found


def own_switch_states(view: Model, text: Text, goal: Goal, where: dict[str, int]) -> None:
    """Set a setting's own switch from a verb of switching said of that setting."""
    for switch, base in _own_switches(view).items():
        if switch in goal or base not in goal:
            continue
        own = stem(base.split("_")[-1])
        for k in range(len(text.tokens)):
            state = _state_at(text, k)
            if state is None:
                continue
            if _object_is(text, k, own):
                info = view.infos[switch]
                goal[switch] = info.on if state == "on" else info.off
                where[switch] = k
                break


def _state_at(text: Text, k: int) -> str | None:
    """ "switch … on", "turn off", "enable" at token k: the state asked."""
    word = text.word(k)
    if word in _ENABLE:
        return _ENABLE[word]
    if word in _VERBS:
        for j in range(k + 1, min(k + 6, len(text.tokens))):
            if text.word(j) in ("on", "off"):
                return text.word(j)
            if text.word(j) in _BREAKS:
                return None
    return None


def _object_is(text: Text, k: int, own: str) -> bool:
    """The verb at k is said of the setting's word (within its clause) or of "it"."""
    for j in range(k + 1, min(k + 6, len(text.tokens))):
        if text.word(j) in _BREAKS:
            return False
        if text.stems[j] == own or text.word(j) == "it":
            return True
    return False
