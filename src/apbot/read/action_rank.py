"""The actions in the manual's order, so that the reading does not depend on the list's order.

A robot's grounding lists the actions in whatever order it finds the controls, an environment's
author in whatever order they like; many of the reader's choices take the first of several
candidates (the first action of a key, the first variable named like a programme, a pad's values
in the order of its keys). Putting the actions in one order that comes from the manual before
anything is read makes every such choice the manual's: a key whose label is found earlier comes
first (the panel legend's order, else the key's first mention), its press before its turns and
its hold; keys the manual never names come after, the digits in a keypad's order (1 to 9,
then 0), the rest by name.
"""

from __future__ import annotations

import math

from apbot.model.schema import ApplianceModel
from apbot.read.actions import ActionInfo
from apbot.read.labels import Label
from apbot.read.text import Manual

# one control's actions: the plain press first (the key itself), then its turns, then its hold
SKILL_ORDER = ("press", "turn_cw", "turn_ccw", "hold")


def _where(token: str, manual: Manual, labels: dict[str, Label]) -> tuple[float, float]:
    """Where the manual names the control: the line where its label was found (the panel's
    legend), else its first mention's, and how far along that line (two keys named on one
    line, "SOUP · CONGEE", keep the line's order); never named: infinity."""
    label = labels.get(token)
    if label is None:
        return (math.inf, math.inf)
    line = label.line
    if line is None:
        lines = [manual.units[m].line for m in label.mentions if 0 <= m < len(manual.units)]
        line = min(lines) if lines else None
    if line is None:
        return (math.inf, math.inf)
    text = manual.lines[line - 1].lower() if 1 <= line <= len(manual.lines) else ""
    column = text.find(label.text.lower())
    return (float(line), float(column) if column >= 0 else math.inf)


def manual_rank(
    info: ActionInfo, manual: Manual, labels: dict[str, Label]
) -> tuple[tuple[float, float], int, int, str]:
    """The action's place: where its control is named (a two-key action once both are named),
    the skill, a digit's value, then the name (what is left is a tie of spelling only)."""
    at = max((_where(t, manual, labels) for t in info.controls), default=(math.inf, math.inf))
    skill = SKILL_ORDER.index(info.skill) if info.skill in SKILL_ORDER else len(SKILL_ORDER)
    digit = (info.digit - 1) % 10 if info.digit is not None else -1  # a keypad's 1…9, 0
    return (at, skill, digit, info.name)


def in_manual_order(
    infos: list[ActionInfo], manual: Manual, labels: dict[str, Label]
) -> list[ActionInfo]:
    """The actions sorted by :func:`manual_rank`: the same list whatever order they came in."""
    return sorted(infos, key=lambda info: manual_rank(info, manual, labels))


def listed_as_given(model: ApplianceModel, names: list[str]) -> ApplianceModel:
    """The read model with its actions, and the controls they use, listed in the order the
    actions were given: that listing is the caller's naming, not something read (the model
    says the same either way; a caller finds its own actions where it put them)."""
    place = {name: k for k, name in enumerate(names)}
    actions = sorted(model.actions, key=lambda a: place.get(a, len(place)))
    first: dict[str, int] = {}
    for k, name in enumerate(actions):
        for control in model.actions[name].control_ids:
            first.setdefault(control, k)
    controls = sorted(model.controls, key=lambda c: first.get(c.id, len(actions)))
    return model.model_copy(
        update={"actions": {a: model.actions[a] for a in actions}, "controls": controls}
    )
