"""One-touch positions: a key that sets several settings at once is named for all of them.

A bed's TV key puts the head to 45° and the foot to 15°, a crêpe maker's memory key the plate
to 220 °C and the time to one minute. When a user names such a key ("the TV position", "the
stored P setting"), they ask for the whole stored combination, not only the one setting the
key's label was matched to: the settings the key's step sets beside its own go into the goal
too, unless the sentence gives them a value of its own ("TV position, feet flat"). Only for a
key that goes to a quantity (an angle, a temperature): a programme key (SMOOTHIE, with its
speed and time) is asked for by its name, and the settings it brings are its defaults.
"""

from __future__ import annotations

from typing import Any

from apbot.model.schema import DiscreteVariable, GoTo
from apbot.read.goal_roles import control_labels, step_effects, steps_of
from apbot.read.goal_text import Text
from apbot.read.goal_values import name_words
from apbot.read.goal_view import Goal, Model, own_stems
from apbot.read.goal_vocab import STOP_WORDS, stem
from apbot.read.numbers import find_mentions


def _presets(view: Model) -> list[tuple[str, Any, tuple[str, ...], dict[str, Any]]]:
    """(setting, value, label stems, the other settings the key sets) for every key that goes
    straight to one value and sets other settings with it."""
    found: list[tuple[str, Any, tuple[str, ...], dict[str, Any]]] = []
    for _feature, _index, step in steps_of(view.model):
        companions = {
            name: value
            for name, value in (getattr(step, "set", None) or {}).items()
            if name in view.infos and view.infos[name].role == "setting"
        }
        own = view.infos.get(step.variable or "")
        if own is None or not companions or isinstance(own.var, DiscreteVariable):
            continue  # a programme key's companions are its defaults, not what is asked
        for action, effect in step_effects(step):
            if not isinstance(effect, GoTo):
                continue
            for label in control_labels(view.model, [action]):
                words = name_words(label)
                if words and not any(w in STOP_WORDS for w in words):
                    stems = tuple(stem(w) for w in words)
                    found.append((own.name, effect.to, stems, companions))
    return found


Lifted = dict[str, tuple[Any, int]]
"""A one-touch key's own setting -> (the value its name gave, where it was said)."""


def lift_presets(view: Model, text: Text, goal: Goal, where: dict[str, int]) -> Lifted:
    """Take a one-touch key's own quantity out of the goal while the said quantities are
    placed: "Movie scene, but a bit brighter — thirty percent" asks for MOVIE's colour at 30 %,
    not its 20 % (:func:`restore_presets` puts it back when nothing else was said of it)."""
    lifted: Lifted = {}
    kinds = {m.dimension for m in find_mentions(text.tokens) if m.kind != "number"}
    for var, value, stems, companions in _presets(view):
        if view.infos[var].dimension not in kinds - {None}:
            continue  # no quantity of its kind said ("the TV position, massage 3" keeps 45°)
        if _another_home(view, goal, var, companions) and not own_stems(view.infos[var]) & set(
            text.stems
        ):
            continue  # "TV position and warm it to 40 degrees": the HEAT's, the head stays 45
        if var in goal and str(goal[var]) == str(value) and var in where:
            start = where[var]
            if text.stems[start : start + 1] == [stems[0]]:
                lifted[var] = (value, start)
                del goal[var], where[var]
    return lifted


def _another_home(view: Model, goal: Goal, var: str, companions: dict[str, Any]) -> bool:
    """Another open setting (not one the key sets too) takes quantities of the key's kind: a
    quantity said is not the key's own unless its setting is named."""
    kind = view.infos[var].dimension
    return any(
        info.role == "setting" and info.dimension == kind
        for name, info in view.infos.items()
        if name != var and name not in goal and name not in companions
    )


def restore_presets(goal: Goal, where: dict[str, int], lifted: Lifted) -> None:
    """A lifted key's quantity back where no other value was said for its setting."""
    for var, (value, start) in lifted.items():
        if var not in goal:
            goal[var] = value
            where[var] = start


def preset_companions(
    view: Model, text: Text, goal: Goal, where: dict[str, int], lifted: Lifted | None = None
) -> None:
    """Add what a named one-touch key sets beside its own setting (see the module doc)."""
    for var, value, stems, companions in _presets(view):
        if lifted and var in lifted and str(lifted[var][0]) == str(value):
            start = lifted[var][1]  # the key was named; its own setting was said otherwise
        elif var not in goal or str(goal[var]) != str(value) or var not in where:
            continue
        else:
            start = where[var]
        if text.stems[start : start + 1] != [stems[0]]:
            continue  # the value was said another way ("head at 10"), not by the key's name
        for name, companion in companions.items():
            goal.setdefault(name, companion)
