"""A held stepping key is a bigger step of the same setting, not a setting of its own.

Panels move one value per press of ▲ / ▼, + / −, HOUR / MIN and several while the key is
held ("hold ▲ for 2 s: ten steps at once", "held: the time jumps by 2 hours", "MIN held =
+10 minutes"). Read as a key of its own, such a hold becomes a guessed on/off switch no
manual line supports: a phantom setting for the goal parser and the agent. Here the hold
joins every step its press takes part in, with the step the manual gives for holding it,
else as a plain repeat of the press's own step; the planner may use it or keep to presses.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import NUMBER_WORDS
from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_holdcell import own_hold_cells

_NUMBER_WORDS = {
    w: NUMBER_WORDS[w] for w in ("two", "three", "four", "five", "six", "ten", "twenty")
}
_N = r"(\d+|" + "|".join(_NUMBER_WORDS) + r")"
# "ten steps at once", "moves 5 values", "in steps of 10", "10 steps"
_STEPS_RE = re.compile(rf"\b{_N}\s+(?:steps?|values?|positions?)\b|\bsteps?\s+of\s+{_N}\b", re.I)
# "jumps by 2 hours", "+ 10 minutes", "in 10-minute steps", "moves the minutes by 10"
_TIME_RE = re.compile(
    r"(?:\bby\s+|\+\s*|\bof\s+)(\d+)\s*-?\s*(hours?|hrs?|h|minutes?|mins?)\b"
    r"|\b(\d+)\s*-\s*(hour|minute|min)\s+(?:steps?|jumps?|increments?)\b"
    r"|\b(hours?|minutes?)\s+by\s+(\d+)\b"
    r"|\b(\d+)\s+(hours?|minutes?)\s+at\s+a\s+time\b",  # "to move 10 minutes at a time"
    re.I,
)
_HOLD_RE = re.compile(r"\b(?:hold|held|holding|long[- ]press)", re.I)
# "hold to change it faster", "2 s: large steps", "by a whole hour": a hold that steps
_FASTER_RE = re.compile(
    r"\b(?:fast|quick|rapid|scroll|continu|repeat|speed|large|big|whole|jump|keeps?\s+\w+ing)"
    r"|\bat\s+(?:once|a\s+time)\b",
    re.I,
)
# where the hold's clause ends: another gesture, a new clause
_CLAUSE_END_RE = re.compile(
    r";|\b(?:press|presses|pressing|touch|turn)\b|,\s*(?:and|but|while|whereas)\b", re.I
)
# "hold + for 3 s to switch the unit": what the hold is for
_PURPOSE_RE = re.compile(r"\bto\s+([a-z]+)", re.I)
_STEP_VERBS = frozenset(
    [
        "change",
        "move",
        "set",
        "adjust",
        "raise",
        "lower",
        "increase",
        "decrease",
        "step",
        "advance",
        "go",
        "reach",
        "count",
    ]
)
# "hold ▲ and ▼ together": a hold of two keys, a gesture of its own (not this key's hold)
_BOTH_RE = re.compile(r"\b(?:together|both|same\s+time|simultaneous)", re.I)


def fold_fast_holds(b: Builder) -> None:
    """Fold each hold read as a setting of its own that the manual never names (its name
    is the gesture's, ``up_hold``: a guess) into the stepping steps of its key's press."""
    holds = []
    for hold in b.infos:
        if hold.skill != "hold" or len(hold.controls) != 1:
            continue
        var = f"{hold.token}_hold"
        own = [
            f for f, steps in b.features.items() if any(hold.name in s["actions"] for s in steps)
        ]
        if var not in b.variables or any(
            [s.get("actions") for s in b.features[f]] != [[hold.name]]
            or b.features[f][0].get("variable") != var
            for f in own
        ):
            continue
        used = [s for f, steps in b.features.items() if f not in own for s in steps]
        if any(s.get("variable") == var for s in used) or any(var in g["when"] for g in b.guards):
            continue
        if not any(i.skill == "press" and i.controls == hold.controls for i in b.infos):
            continue
        if (_said_step(b, hold) is None and _hold_has_own_job(b, hold)) or _cell_job(b, hold):
            continue  # "hold + for 3 s to switch to °F": a job of its own, not a faster step
        holds.append((hold, var, own))
    attached = attach_fast_holds(b, [h for h, _, _ in holds])
    for hold, var, own in holds:
        if hold.name not in attached:
            continue
        for f in own:
            del b.features[f]
        del b.variables[var]
        for steps in b.features.values():
            for step in steps:
                if var in step.get("reset", []):
                    step["reset"] = [v for v in step["reset"] if v != var]
                    if not step["reset"]:
                        del step["reset"]
        b.indicators = [v for v in b.indicators if v != var]
        gone = {f"variables.{var}", *(f"features.{f}" for f in own)}
        b.notes = [n for n in b.notes if not _about(n.subject, gone)]


def _about(subject: str, gone: set[str]) -> bool:
    return any(subject == g or subject.startswith(g + ".") for g in gone)


def attach_fast_holds(b: Builder, holds: list[ActionInfo]) -> set[str]:
    """Add each hold to every stepping step its press is in (a step with two or more
    actions each moving the setting: a ▲ / ▼ pair, HOUR / MIN); return the holds placed."""
    placed: set[str] = set()
    presses = {
        h.name: next(i.name for i in b.infos if i.skill == "press" and i.controls == h.controls)
        for h in holds
    }
    sizes = {h.name: _said_step(b, h) for h in holds}
    for hold in holds:
        press = presses[hold.name]
        for fname, steps in b.features.items():
            for step in steps:
                effect = _press_effect(step, press)
                if effect is None or step.get("variable") not in b.variables:
                    continue
                # "hold + or – for 2 s": the pair's sentence, under either key's name
                said = sizes[hold.name] or next(
                    (
                        sizes[h.name]
                        for h in holds
                        if sizes[h.name] and presses[h.name] in step["actions"]
                    ),
                    None,
                )
                fast = _fast_effect(b.variables[step["variable"]], effect, said)
                if fast is None:
                    continue  # "the time jumps by 2 hours": not the temperature's step
                step["actions"] = [*step["actions"], hold.name]
                step["effect"] = {**step["effect"], hold.name: fast}
                b.note(
                    f"features.{fname}",
                    f"{hold.name} steps {step['variable']} faster than {press}",
                    said[1] if said else None,
                )
                placed.add(hold.name)
    return placed


def _press_effect(step: dict[str, Any], press: str) -> Any:
    """The press's effect in a stepping step of two or more keys (next, prev, an add)."""
    effect = step.get("effect")
    if press not in step.get("actions", []) or not isinstance(effect, dict):
        return None
    if len(step["actions"]) < 2:
        return None
    own = effect.get(press)
    if own in ("next", "prev") or (isinstance(own, dict) and set(own) == {"add"}):
        return own
    return None


def _said_step(b: Builder, hold: ActionInfo) -> tuple[str, int] | None:
    """The sentence about holding this key that gives a size ("hold ▲: ten steps at
    once"): its text and unit index; None when the manual gives none."""
    label = b.labels.get(hold.controls[0])
    if label is None:
        return None
    for i in label.mentions:
        held = _HOLD_RE.search(b.manual.units[i].text)
        text = _hold_clause(b.manual.units[i].text[held.start() :]) if held else ""
        if held and (_STEPS_RE.search(text) or _TIME_RE.search(text)):
            return text, i  # (what follows the hold: not the press's own step before it)
    return None


def held_time_step(text: str) -> int | None:
    """The seconds a hold moves a time by, from the hold's own clause in ``text`` ("Holding ▲
    or ▼ for 2 seconds moves the minutes by 10": 600); None when no hold gives a time."""
    held = _HOLD_RE.search(text)
    m = _TIME_RE.search(_hold_clause(text[held.start() :])) if held else None
    return _seconds(m) if m else None


def _seconds(m: re.Match[str]) -> int:
    """The seconds a match of ``_TIME_RE`` gives."""
    amount = int(m.group(1) or m.group(3) or m.group(6) or m.group(7))
    unit = (m.group(2) or m.group(4) or m.group(5) or m.group(8)).lower()
    return amount * (3600 if unit.startswith("h") else 60)


def _hold_clause(text: str) -> str:
    """The hold's own clause: up to another gesture or clause ("hold + to set the clock
    faster, and press START to add a delay of 2 hours": the 2 hours are START's)."""
    return _CLAUSE_END_RE.split(text, maxsplit=1)[0]


def _cell_job(b: Builder, hold: ActionInfo) -> bool:
    """The key's row in a key table gives holding a job in its column for holding ("| ▲ |
    warmer | release / restore the 40 °C stop |"), and it is no faster step."""
    return any(
        re.search(r"[a-z]{3}", cell, re.I)
        and not (_FASTER_RE.search(cell) or _STEPS_RE.search(cell) or _TIME_RE.search(cell))
        for cell in own_hold_cells(b, hold)
    )


def _hold_has_own_job(b: Builder, hold: ActionInfo) -> bool:
    """The manual tells what holding this key alone is for, and it is not a step ("hold −
    for 5 s to reset", "hold ▼ to switch the display off"): folding it into the press's step
    would have the planner reach a value with a key that does something else."""
    label = b.labels.get(hold.controls[0])
    if label is None or not label.text.strip():
        return False
    key = re.escape(label.text.strip())
    own = re.compile(
        rf"\b(?:hold|holding|long[- ]press)\s+(?:down\s+)?(?:the\s+)?{key}(?![\w/])"
        r"(?P<rest>[^.;]*)",
        re.I,
    )
    for i in label.mentions:
        text = b.manual.units[i].text
        if _BOTH_RE.search(text):
            continue
        for m in own.finditer(text):
            rest = m.group("rest")
            if _FASTER_RE.search(rest) or _STEPS_RE.search(rest) or _TIME_RE.search(rest):
                continue
            purpose = _PURPOSE_RE.search(rest)
            if purpose and purpose.group(1).lower() not in _STEP_VERBS:
                return True
    return False


def _count(word: str) -> int:
    return int(word) if word.isdigit() else _NUMBER_WORDS[word.lower()]


def _fast_effect(spec: dict[str, Any], effect: Any, said: tuple[str, int] | None) -> Any:
    """The hold's effect: the press's direction with the manual's size (a count of steps,
    or a time for a time setting), else the press's own effect repeated; None when the size
    is a time and the setting is none (the hold is said of another setting the pair steps)."""
    sign = -1 if effect == "prev" or (isinstance(effect, dict) and _negative(effect["add"])) else 1
    if said is None:
        return effect
    text = said[0]
    m = _TIME_RE.search(text)
    if m and spec.get("type") == "time":
        return {"add": sign * _seconds(m)}
    if m and not _STEPS_RE.search(text):
        return None
    m = _STEPS_RE.search(text)
    if m:
        n = _count(m.group(1) or m.group(2))
        if n >= 2:
            return {"skip": sign * n}
    return effect


def _negative(amount: Any) -> bool:
    return (isinstance(amount, str) and amount.startswith("-")) or (
        isinstance(amount, (int, float)) and amount < 0
    )
