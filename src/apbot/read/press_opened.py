"""A setting a key's press opens and the stepping pair then sets, read from its numbered steps:
"1. Press SET. The base time flashes, e.g. TIME 0:05 (hours:minutes). 2. Press + or − to change
it by one minute. Hold + or − for 2 seconds to change it by ten minutes. The range is 0:01 to
9:59."

Read key by key, the press was an entry key for the pair and its setting a guess ("0–10",
named after the key): the range, the step and the name were in the steps after the press, not
in the key's own sentences. Here, when the press's setting is such a guess and the steps read as
a one-field walk (see ``held_walks``), the setting becomes the one the steps give: named by what
flashes, its range and unit, the press's step ("change it by one minute") and the pair's hold
("hold … to change it by ten minutes") as a bigger step.
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

from apbot.model.values import NUMBER_WORDS
from apbot.read.build import Builder
from apbot.read.held_guesses import drop_unused
from apbot.read.held_walks import _one_walk
from apbot.read.walk_keys import controls_of, moves_on, stepping_pairs
from apbot.read.walk_known import flashing_name
from apbot.read.walk_steps import walk_steps

_AMOUNT = r"(\d+|" + "|".join(w for w in NUMBER_WORDS if " " not in w) + r")"
_TIME_UNIT = r"(seconds?|minutes?|hours?)"
_SECONDS = {"second": 1, "minute": 60, "hour": 3600}
# "Press + or − to change it by one minute", "Hold + or − for 2 seconds to change it by ten minutes"
_BY = re.compile(
    rf"^\W*(?P<way>press|touch|tap|hold)\b[^.;]{{0,40}}?\bto\s+(?:change|move|raise|lower|adjust)"
    rf"\s+(?:it|the\s+\w+)\s+by\s+{_AMOUNT}\s+{_TIME_UNIT}\b",
    re.I,
)
_SENTENCES = re.compile(r"(?<=[.;])\s+")


def read_press_opened(b: Builder) -> None:
    """Give a press's guessed setting, stepped by the pair after it, the one its steps read."""
    pairs = stepping_pairs(b)
    if not pairs:
        return
    for fname, steps in list(b.features.items()):
        if len(steps) != 2 or "variable" in steps[0] or len(steps[0].get("actions", [])) != 1:
            continue
        press = steps[0]["actions"][0]
        var = str(steps[1].get("variable"))
        info = next((i for i in b.infos if i.name == press), None)
        if info is None or info.skill != "press" or var not in b.unread or len(info.controls) != 1:
            continue
        if info.controls[0] not in b.labels:
            continue
        label = b.labels[info.controls[0]].text
        walk = _walk(b, label, pairs)
        if walk is None or tuple(walk["pair"][0]) not in _ups(steps[1]):
            continue
        field = walk["fields"][0]
        if "evidence" not in field:
            continue
        _replace(b, fname, steps, var, walk, field, label)


def _ups(step: dict[str, Any]) -> set[tuple[str, ...]]:
    effect = step.get("effect")
    if not isinstance(effect, dict):
        return set()
    return {(a,) for a, e in effect.items() if e == "next"}


def _walk(
    b: Builder, label: str, pairs: list[tuple[list[str], list[str]]]
) -> dict[str, Any] | None:
    units = b.manual.units
    for i, unit in enumerate(units):
        if unit.step is None or not moves_on(unit.text, label):
            continue
        walk = _one_walk(b, walk_steps(units, i), label, pairs, i)
        if walk is not None:
            return walk
    return None


def _replace(
    b: Builder,
    fname: str,
    steps: list[dict[str, Any]],
    old: str,
    walk: dict[str, Any],
    field: dict[str, Any],
    label: str,
) -> None:
    said = str(walk["said"])
    name = flashing_name(said) or field["name"]
    ev = field["evidence"]
    press_by, hold_by = _steps(said)
    if press_by is not None and ev.step is None:
        ev = replace(ev, step=(float(press_by), "s"), step_at=walk["at"])
    del b.features[fname]
    drop_unused(b, old)
    var = b.add_number(name, label, ev, cyclic=False)
    up, down = walk["pair"]
    effect: dict[str, Any] = {**{a: "next" for a in up}, **{a: "prev" for a in down}}
    if hold_by is not None:
        for side, sign in ((up, 1), (down, -1)):
            for action in side:
                held = _hold_of(b, action)
                if held:
                    effect[held] = {"add": sign * hold_by}
    b.feature(
        f"set_{var}", [steps[0], {"actions": list(effect), "variable": var, "effect": effect}]
    )
    b.note(f"features.set_{var}", f"{steps[0]['actions'][0]} opens {var}", walk["at"])


def _hold_of(b: Builder, action: str) -> str:
    controls = controls_of(b, action)
    return next((i.name for i in b.infos if i.skill == "hold" and i.controls == controls), "")


def _steps(said: str) -> tuple[int | None, int | None]:
    """What a press and a hold of the pair change the time by, in seconds, as the steps say."""
    press = hold = None
    for sentence in _SENTENCES.split(said):
        m = _BY.search(sentence)
        if not m:
            continue
        raw = m.group(2).lower()
        amount = int(raw) if raw.isdigit() else int(NUMBER_WORDS[raw])
        seconds = amount * _SECONDS[m.group(3).lower().rstrip("s")]
        if m.group("way").lower() == "hold":
            hold = hold if hold is not None else seconds
        else:
            press = press if press is not None else seconds
    return press, hold
