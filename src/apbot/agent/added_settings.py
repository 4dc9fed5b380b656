"""Repairs that add a setting the belief lacked: its variable, its keys, the step that adjusts it.

The discovery of a missing setting (:mod:`apbot.agent.discovery`) ends here: a setting walked
by a key (and the key back), typed on the keypad after an entry key, or chosen by one key per
value, written as a new procedure, as the next step of one, or into the plain step where the
reader kept its keys. Split from :mod:`apbot.agent.repair` (which re-exports these) because
adding a whole setting is one job of its own, next to the small edits there.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

from apbot.agent.model_edits import _dump, _rebuild
from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, DiscreteVariable
from apbot.read.actions import action_info


def add_setting(
    model: ApplianceModel,
    name: str,
    variable: dict[str, Any],
    key: str,
    effect: str,
    opposite: str | None = None,
    entry: str | None = None,
    after: tuple[str, int] | None = None,
) -> ApplianceModel:
    """A setting the model lacked: its variable, its key (and the key walking the other way),
    and a one-step procedure ``set_NAME`` that adjusts it. Where other settings depend on a
    programme, this one is taken to depend on it too (each programme starting from what was
    seen): a programme change then resets it in the belief as it may on the appliance, and the
    planner sets it after the programme. With ``after`` (a procedure and the index of the step
    whose key ``entry`` is), it is that procedure's next step instead, depending on the choice
    made there when that is a list of values (a weight per automatic menu)."""
    effects: dict[str, Any] = {key: effect}
    if opposite:
        effects[opposite] = "prev" if effect == "next" else "next"
    if after is not None:
        return _after_step(model, name, variable, effects, after)
    return _with_setting(model, name, variable, effects, entry)


def _after_step(
    model: ApplianceModel,
    name: str,
    variable: dict[str, Any],
    effects: dict[str, Any],
    after: tuple[str, int],
) -> ApplianceModel:
    feature, index = after
    data = _dump(model)
    chosen = model.features[feature][index].variable
    parent = model.variables.get(chosen) if chosen else None
    if isinstance(parent, DiscreteVariable) and parent.depends_on is None:
        own = {k: variable.pop(k) for k in ("values", "ranges", "initial") if k in variable}
        variable["depends_on"] = chosen
        variable["cases"] = {str(value): dict(own) for value in all_values(parent)}
    data["variables"][name] = variable
    for action in effects:
        if action not in data["actions"]:
            _add_action(data, action)
    data["features"][feature].insert(
        index + 1,
        {
            "actions": list(effects),
            "variable": name,
            "effect": effects,
            "note": "learnt from feedback",
        },
    )
    return _rebuild(data)


def add_keypad_setting(
    model: ApplianceModel,
    name: str,
    variable: dict[str, Any],
    entry: str | None,
    digits: list[str],
) -> ApplianceModel:
    """A setting the model lacked that is typed on the keypad after ``entry`` (POWER, then
    the digits), or without one: its variable (with its ``entry`` format) and a procedure
    ``set_NAME`` — or the plain steps of digits the model had (see :func:`add_setting`)."""
    return _with_setting(model, name, variable, {d: "digit" for d in digits}, entry)


def add_keypad_step(
    model: ApplianceModel,
    name: str,
    variable: dict[str, Any],
    digits: list[str],
    after: tuple[str, int],
) -> ApplianceModel:
    """A setting the model lacked that is typed on the keypad as the next step of a procedure
    (``after``: the procedure and its step's index): AUTO DEFROST chooses the food, then the
    digits give its weight, one range per food."""
    return _after_step(model, name, variable, {d: "digit" for d in digits}, after)


def add_choice_setting(
    model: ApplianceModel, name: str, variable: dict[str, Any], keys: dict[str, Any]
) -> ApplianceModel:
    """A setting the model lacked whose keys each select one value (WHITE RICE, BROWN RICE…):
    its variable, the keys, and a one-step procedure ``set_NAME`` where each key sets its value
    (a programme of its own: nothing is taken to depend on it, nor it on another)."""
    return _with_setting(
        model,
        name,
        variable,
        {action: {"to": value} for action, value in keys.items()},
        None,
        programme=True,
    )


def _with_setting(
    model: ApplianceModel,
    name: str,
    variable: dict[str, Any],
    effects: dict[str, Any],
    entry: str | None,
    programme: bool = False,
) -> ApplianceModel:
    data = _dump(model)
    parents = [v.depends_on for v in model.variables.values() if v.depends_on is not None]
    # keys that each select a value, or that reset other settings, choose a programme rather
    # than adjust a setting of one
    programme = programme or any(
        model.features[feature][index].reset or model.features[feature][index].set
        for feature, index in plain_steps(model, effects)
        if effects and not all(e == "digit" for e in effects.values())
    )
    if parents and not programme:  # the programme other settings depend on resets it too
        parent = max(dict.fromkeys(parents), key=parents.count)  # ties: the first, not the hash's
        own = {k: variable.pop(k) for k in ("values", "ranges", "initial") if k in variable}
        variable["depends_on"] = parent
        variable["cases"] = {str(value): dict(own) for value in all_values(model.variables[parent])}
    data["variables"][name] = variable
    known = set(data["actions"])
    for action in [*effects, *([entry] if entry else [])]:
        if action not in known:
            _add_action(data, action)
    plain = plain_steps(model, effects)
    used = {a for steps in model.features.values() for step in steps for a in step.actions}
    if plain and entry is None:  # the reader kept the keys as a plain step: it adjusts this
        for feature, index in plain:
            step = data["features"][feature][index]
            # the step's own keys, and those the model has nowhere (the way back)
            keys = list(dict.fromkeys([*step["actions"], *(a for a in effects if a not in used)]))
            step["variable"] = name
            step["effect"] = {a: effects.get(a, "none") for a in keys}
            step["actions"] = keys
        return _rebuild(data)
    adjusting = {
        "actions": list(effects),
        "variable": name,
        "effect": effects,
        "note": "learnt from feedback",
    }
    after = plain_steps(model, [entry]) if entry else []
    if after:  # the entry key is a plain step already ("press POWER, then …"): it goes on there
        feature, index = after[0]
        data["features"][feature].insert(index + 1, adjusting)
        return _rebuild(data)
    steps: list[dict[str, Any]] = (
        [{"actions": [entry], "note": "learnt from feedback"}] if entry else []
    )
    steps.append(adjusting)
    title = f"set_{name}"
    while title in data["features"]:
        title += "_learnt"
    data["features"][title] = steps
    return _rebuild(data)


def plain_keys(model: ApplianceModel) -> set[str]:
    """Keys every step of which adjusts nothing ("press TIMER", then the digits): a key the
    reader knew without knowing what it sets."""
    steps = [step for feature in model.features.values() for step in feature]
    used = {a for step in steps for a in step.actions}
    adjusting = {a for step in steps if step.variable is not None for a in step.actions}
    return used - adjusting


def plain_steps(model: ApplianceModel, keys: Collection[str]) -> list[tuple[str, int]]:
    """The steps that adjust nothing and have some of ``keys``: where a reader kept a
    setting's keys ("press TIMER", the digits, the programme keys) without the setting."""
    return [
        (feature, index)
        for feature, steps in model.features.items()
        for index, step in enumerate(steps)
        if step.variable is None and set(step.actions) & set(keys)
    ]


def setting_step(model: ApplianceModel, name: str) -> tuple[str, int] | None:
    """The first step that adjusts ``name`` (where a new setting was written)."""
    for feature, steps in model.features.items():
        for index, step in enumerate(steps):
            if step.variable == name:
                return feature, index
    return None


def _add_action(data: dict[str, Any], action: str) -> None:
    """An action the model did not know, on a control named after it."""
    info = action_info(action)
    control = f"{info.token}_control" if not info.token.startswith("key_") else info.token
    if not any(c["id"] == control for c in data["controls"]):
        turning = info.skill.startswith("turn")
        kind = "key" if info.digit is not None else "dial" if turning else "button"
        data["controls"].append({"id": control, "kind": kind})
    spec: dict[str, Any] = {"control": control}
    if info.digit is not None:
        spec["digit"] = info.digit
    if info.skill == "hold":
        spec.update(skill="hold", seconds=3)
    elif info.skill != "press":
        spec["skill"] = info.skill
    data["actions"][action] = spec


def unrole(model: ApplianceModel, key: str) -> ApplianceModel:
    """The model with ``key``'s steps adjusting nothing: the walk of the key showed a setting
    of another kind than the one the reader gave it (grams on a key read as a switch), so
    those steps are plain steps, which the setting found is then written into."""
    data = _dump(model)
    dropped: set[str] = set()
    for steps in data["features"].values():
        for step in steps:
            if key in step["actions"] and step.get("variable") is not None:
                dropped.add(step.pop("variable"))
                step.pop("effect", None)
    still = {step.get("variable") for steps in data["features"].values() for step in steps}
    for name in dropped - still:  # a setting the key alone was read to adjust: none at all
        data["variables"].pop(name, None)
    return ApplianceModel.model_validate(data)  # checked once the setting is written in
