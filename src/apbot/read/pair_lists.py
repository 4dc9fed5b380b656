"""A second function reached by two keys together, its name and its list in its own paragraph:
"Click sound  (SHIFT + KIT)" then "VOICE CLICK … / VOICE BEEP … / VOICE CLAVE …", or "Beat
(SHIFT + TEMPO)" then "1/4   2/4   3/4   4/4   6/8".

Keyboards, drum modules, calculators and radios print a second function under a key and
reach it with SHIFT (FUNCTION, 2ND) held; the manual gives each second function a small
heading naming it with the keys in brackets, and the list the stepping keys move through. Read
key by key, the two-key action had no sentence of its own (a guessed on/off, or the range of
the plain key's section); here the action takes the heading's name, the list as its values
(a run of lines sharing a display word: the rest of each line's first cell, shown whole; or
one line of fractions or figures), and the pair of stepping keys its other features use.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import Label

# "Click sound  (SHIFT + KIT)": a short name, then the two keys in brackets
_HEAD_RE = re.compile(
    r"^\s*([A-Za-z][A-Za-z -]{1,30}?)\s*\(\s*([A-Z0-9]+)\s*\+\s*([A-Z0-9]+)\s*\)\s*$"
)
# a line of a display list: a display word, one more word or figure, then a gap and a gloss
_SHOWN_RE = re.compile(r"^([A-Z]{2,10})\s([A-Z0-9][A-Z0-9-]{0,12})(?:\s{2,}\S.*)?$")
# a line of fractions or figures and nothing else ("1/4   2/4   3/4")
_FIGURES_RE = re.compile(r"^\s*\d{1,3}(?:/\d{1,2})?(?:\s{2,}\d{1,3}(?:/\d{1,2})?){2,}\s*$")
_LOOK = 14
_NONE = Label("", "", None)  # how far after its heading a second function's list may stand


def read_pair_lists(b: Builder) -> None:
    """Give each two-key action's guessed setting the name and list its paragraph prints."""
    pairs = [i for i in b.infos if len(b.labels.get(i.controls[0], _NONE).text.split("+")) == 2]
    steppers = _stepping_steps(b) if pairs else None
    if steppers is None:
        return
    units = b.manual.units
    for info in pairs:
        label = b.labels[info.controls[0]].text
        keys = [k.strip() for k in label.split("+")]  # ("SHIFT+KIT", "SHIFT + KIT")
        if len(info.controls) != 1 or len(keys) != 2 or info.skill != "press":
            continue
        for i, unit in enumerate(units):
            head = _HEAD_RE.match(unit.text)
            if head is None or [head[2], head[3]] != keys:
                continue
            found = _list_after(b, i)
            if found is None:
                continue
            values, shows = found
            _rebuild(b, info, head[1].strip().lower(), values, shows, steppers, i)
            break


def _list_after(b: Builder, i: int) -> tuple[list[str], dict[str, str]] | None:
    """The values (and what the display shows of each) listed after the heading at ``i``,
    before the next such heading."""
    units = b.manual.units
    for k in range(i + 1, min(i + _LOOK, len(units))):
        text = units[k].text
        if _HEAD_RE.match(text) or units[k].heading != units[i].heading:
            return None
        if _FIGURES_RE.match(text):
            values = text.split()
            return (values, {}) if len(set(values)) == len(values) else None
        run = _shown_run(units, k)
        if run is not None:
            return run
    return None


def _shown_run(units: Any, k: int) -> tuple[list[str], dict[str, str]] | None:
    """Three or more lines from ``k`` on that start with the same display word."""
    lines: list[re.Match[str]] = []
    for unit in units[k:]:
        m = _SHOWN_RE.match(unit.text)
        if m is None or (lines and m[1] != lines[0][1]):
            break
        lines.append(m)
    if len(lines) < 3:
        return None
    values = [m[2].lower() for m in lines]
    if len(set(values)) != len(values):
        return None
    return values, {m[2].lower(): f"{m[1]} {m[2]}" for m in lines}


def _stepping_steps(b: Builder) -> dict[str, Any] | None:
    """The one stepping step (its actions and effects) the read features share, else None."""
    seen: dict[str, dict[str, Any]] = {}
    for steps in b.features.values():
        for step in steps[1:]:
            effect = step.get("effect")
            if isinstance(effect, dict) and all(e in ("next", "prev") for e in effect.values()):
                seen[",".join(step["actions"])] = step
    if len(seen) != 1:
        return None
    return next(iter(seen.values()))


def _rebuild(
    b: Builder,
    info: ActionInfo,
    name: str,
    values: list[str],
    shows: dict[str, str],
    stepper: dict[str, Any],
    at: int,
) -> None:
    """Replace the action's read setting by a list stepped by the shared stepping keys."""
    for feature, steps in list(b.features.items()):
        if steps and steps[0].get("actions") == [info.name]:
            old = steps[0].get("variable") or (steps[1].get("variable") if len(steps) > 1 else None)
            del b.features[feature]
            if old and not any(s.get("variable") == old for st in b.features.values() for s in st):
                b.variables.pop(old, None)
                b.unread.discard(old)
                b.notes = [n for n in b.notes if not n.subject.startswith(f"variables.{old}")]
    var = b.unique("_".join(re.findall(r"[a-z0-9]+", name)), b.variables)
    spec: dict[str, Any] = {"type": "discrete", "values": values, "label": name.upper()}
    if shows:
        spec["show"] = shows
    b.variables[var] = spec
    effect = {a: e for a, e in stepper["effect"].items() if a in stepper["actions"]}
    b.feature(
        var,
        [{"actions": [info.name]}, {"actions": list(effect), "variable": var, "effect": effect}],
    )
    b.note(f"variables.{var}", f"a second function's list ({', '.join(values)})", at)
