"""Faults in what the model contains: a setting the reader did not see, one that does not
exist, and guards (what is refused while the appliance is off, locked or running).
"""

from __future__ import annotations

import random
import re
from collections.abc import Iterator
from typing import Any

from apbot.bench.faults.common import (
    Candidates,
    Data,
    Fault,
    actions_text,
    by_mode,
    copied,
    dump,
    protected,
)
from apbot.model.schema import ApplianceModel

# --- a setting the reader did not see ----------------------------------------------------------


def _changes(step: Data) -> bool:
    return bool(step.get("variable") or step.get("set") or step.get("reset"))


def _drop_field(template: str, name: str) -> str:
    return re.sub(r"\s{2,}", "  ", template.replace("{" + name + "}", "")).strip()


def _forget(data: Data, name: str) -> None:
    """Remove every reference to variable ``name`` except the steps that adjust it."""
    for steps in data["features"].values():
        for step in steps:
            step.get("set", {}).pop(name, None)
            if name in step.get("reset", []):
                step["reset"] = [r for r in step["reset"] if r != name]
    display = data.setdefault("display", {})
    if "idle" in display:
        display["idle"] = _drop_field(display["idle"], name)
    if name in display.get("indicators", []):
        display["indicators"] = [v for v in display["indicators"] if v != name]
    for var in data["variables"].values():
        show = var.get("show")
        if isinstance(show, str):
            var["show"] = _drop_field(show, name)
        elif isinstance(show, dict):
            var["show"] = {k: _drop_field(text, name) for k, text in show.items()}


def _drop_unused_keys(data: Data) -> list[str]:
    """Actions no feature uses any more (and controls no action uses) leave the model, and the
    guards' lists of allowed actions: the reader never learnt what those keys do."""
    used = {a for steps in data["features"].values() for step in steps for a in step["actions"]}
    gone = [a for a in data["actions"] if a not in used]
    for action in gone:
        del data["actions"][action]
    for guard in data.get("guards", []):
        guard["only"] = [a for a in guard["only"] if a in used]
    touched = {c for action in data["actions"].values() for c in [action.get("control")] if c} | {
        c for action in data["actions"].values() for c in action.get("controls", [])
    }
    data["controls"] = [c for c in data["controls"] if c["id"] in touched]
    return gone


def missing_variable(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A setting the reader did not see at all: ``delay`` is gone, with the steps that adjust
    it. A step in the middle of a procedure (or one with side effects) stays as a plain key
    press ("press TIMER, then the digits, then START"); a last step goes; a procedure left
    changing nothing goes; keys then used nowhere are unknown to the belief. Not power, locks
    or run state, nor a programme other settings depend on or a guard tests."""
    del rng  # one way to forget a variable
    if protected(name) or name not in model.variables:
        return
    if any(v.depends_on == name for v in model.variables.values()):
        return
    if any(name in g.when for g in model.guards):
        return
    data = dump(model)
    changed: list[str] = []
    for feature, steps in list(data["features"].items()):
        if not any(step.get("variable") == name for step in steps):
            continue
        kept = []
        for i, step in enumerate(steps):
            if step.get("variable") != name:
                kept.append(step)
                continue
            plain = {k: v for k, v in step.items() if k not in ("variable", "effect", "on_entry")}
            if plain.get("set") or plain.get("reset") or i < len(steps) - 1:
                kept.append(plain)
        data["features"][feature] = kept
        changed.append(feature)
    _forget(data, name)
    removed = [f for f, steps in data["features"].items() if not any(map(_changes, steps))]
    for feature in removed:
        del data["features"][feature]
    del data["variables"][name]
    gone = _drop_unused_keys(data)
    parts = []
    if removed:
        parts.append(f"{', '.join(removed)} removed")
    if kept_features := [f for f in changed if f not in removed]:
        parts.append(
            f"{', '.join(kept_features)} no longer set{'s' * (len(kept_features) == 1)} it"
        )
    if gone:
        parts.append(f"{actions_text(gone)} unknown")
    detail = "the setting is missing" + (f" ({'; '.join(parts)})" if parts else "")
    yield data, Fault("missing_variable", name, detail)


# --- a setting that does not exist -------------------------------------------------------------

INVENTED: tuple[tuple[str, list[str]], ...] = (
    ("memory", ["off", "on"]),
    ("eco", ["off", "on"]),
    ("level", ["1", "2", "3"]),
    ("mode", ["standard", "intensive"]),
)


def _run_state(name: str | None) -> bool:
    return name is not None and protected(name) and name != "power" and "lock" not in name


def _starts(steps: list[Any]) -> bool:
    """Whether a feature's first step starts the appliance (steps or sets a run state)."""
    return _run_state(steps[0].variable) or any(map(_run_state, steps[0].set))


def spurious_variable(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A setting that does not exist, with a step the reader invented for it: after setting the
    temperature, "press START to choose the temperature memory" — ``press_start`` right after
    ``set_temperature`` is believed to step ``temperature_memory`` (off/on) instead of starting.
    The key is the first key of another procedure: the one that starts the appliance first
    (nearly every plan presses it last, so the planner must work round the invented step),
    then those later in the manual; the belief mispredicts what it does right after this
    procedure."""
    steps = model.features.get(name, [])
    settings = [s.variable for s in steps if s.variable and not protected(s.variable)]
    guarded = {v for g in model.guards for v in g.when}
    if not settings or any(s.variable in guarded or guarded & set(s.set) for s in steps):
        return  # after starting or locking, a guard would refuse the key in both models
    names = list(model.features)
    after = names[names.index(name) + 1 :] + names[: names.index(name)]
    starting = [f for f in after if _starts(model.features[f])]
    after = starting + [f for f in after if f not in starting]
    last = set(steps[-1].actions)
    keys = list(
        dict.fromkeys(
            a
            for feature in after
            for a in model.features[feature][0].actions
            if a not in last and model.actions[a].digit is None
        )
    )
    for key in keys[:2] + rng.sample(keys[2:], min(2, len(keys[2:]))):
        word, values = rng.choice(INVENTED)
        invented = f"{settings[-1]}_{word}"
        if invented in model.variables:
            continue
        data = dump(model)
        data["variables"][invented] = {"type": "discrete", "values": list(values)}
        data["features"][name].append({"actions": [key], "variable": invented, "effect": "next"})
        detail = (
            f"invented {invented} ({'/'.join(values)}): {key} right after {name} is believed "
            "to step it"
        )
        yield data, Fault("spurious_variable", name, detail)


# --- guards -------------------------------------------------------------------------------------


def guard_names(model: ApplianceModel) -> list[str]:
    """Each guard's site name: its name as an identifier (``child_lock``), made unique."""
    names: list[str] = []
    for i, guard in enumerate(model.guards):
        base = re.sub(r"[^a-z0-9]+", "_", guard.name.casefold()).strip("_") or f"guard_{i}"
        text, n = base, 2
        while text in names:
            text, n = f"{base}_{n}", n + 1
        names.append(text)
    return names


def _condition(when: dict[str, Any]) -> str:
    return ", ".join(
        f"{k} is {'/'.join(map(str, v)) if isinstance(v, list) else v}" for k, v in when.items()
    )


def _wrong_conditions(when: dict[str, Any]) -> Iterator[tuple[str, list[str]]]:
    """Plausible misread conditions: one value of a list left out ("while cooking" for "while
    cooking or keeping warm"). A single value is not misread: another programme or state in
    its place would be a different guard, not a misreading."""
    for variable, wanted in when.items():
        if isinstance(wanted, list) and len(wanted) >= 2:
            options = [str(w) for w in wanted]
            for value in options:
                yield variable, [w for w in options if w != value]


def guard(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A guard missing or wrong: the belief lets keys work while the appliance runs (missing),
    refuses a key the guard allows, allows a key it refuses, or tests too few values
    (``when: {status: [cooking]}`` for ``[cooking, keep warm]``). The guard stays liftable,
    or the model would not be valid."""
    names = guard_names(model)
    if name not in names:
        return
    index = names.index(name)
    truth = model.guards[index]
    original = dump(model)
    label = f"{truth.name or name!r} (while {_condition(original['guards'][index]['when'])})"

    def edited(change: Any, detail: str) -> tuple[Data, Fault]:
        data = copied(original)
        change(data["guards"])
        return data, Fault("guard", name, f"{label} {detail}")

    missing = [edited(lambda g: g.pop(index), "is missing")]
    narrower = [
        edited(
            lambda g, a=a: g[index].update(only=[x for x in truth.only if x != a]),
            f"no longer allows {a}",
        )
        for a in truth.only
    ]
    starts = {a for steps in model.features.values() for a in steps[0].actions}
    refused = [a for a in model.actions if a not in truth.only and a in starts]
    wider = [
        edited(lambda g, a=a: g[index].update(only=[*truth.only, a]), f"also allows {a}")
        for a in rng.sample(refused, min(4, len(refused)))
    ]
    wrong = [
        edited(
            lambda g, v=variable, w=value: g[index]["when"].update({v: w}),
            f"tests {variable} is {'/'.join(value)}",
        )
        for variable, value in _wrong_conditions(original["guards"][index]["when"])
    ]
    yield from by_mode([missing, narrower, wider, wrong], rng)
