"""Repairs to a belief model, as data edits: each returns a new validated model.

The closed loop learns facts from feedback (the values a variable really takes, which way a
key moves it, a step the procedure needs); these functions write such facts into a copy of
the model. A repair that would make the model invalid raises :class:`RepairError` and the
agent keeps its old model.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from typing import Any

from pydantic import ValidationError

from apbot.model.domain import all_values
from apbot.model.effects import default_effect
from apbot.model.schema import ApplianceModel, DiscreteVariable, TimeVariable
from apbot.model.validate import check_model
from apbot.model.values import expand_ranges, format_hms, parse_hms


class RepairError(ValueError):
    """The repaired model would not be valid; the message says why."""


def _rebuild(data: dict[str, Any]) -> ApplianceModel:
    try:
        model = ApplianceModel.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        raise RepairError(f"{'.'.join(str(p) for p in first['loc'])}: {first['msg']}") from None
    errors = [p for p in check_model(model) if p.severity == "error"]
    if errors:
        raise RepairError(str(errors[0]))
    return model


def _dump(model: ApplianceModel) -> dict[str, Any]:
    return model.model_dump(mode="json", exclude_none=True)


def redefine_domain(
    model: ApplianceModel,
    name: str,
    case: str | None,
    *,
    values: Sequence[Any] | None = None,
    ranges: Sequence[tuple[float, float, float]] | None = None,
    wrap: bool | None = None,
    current: Any = None,
    initial: Any = None,
) -> ApplianceModel:
    """A new domain for ``name`` (for the parent's ``case`` when it depends on one).

    Discrete variables take ``values`` in order; numeric and time variables take ``ranges`` of
    magnitudes (seconds for times). The initial value is ``initial`` when given and it fits,
    else kept when it still fits, else the observed ``current`` value (or the first value).
    """
    data = _dump(model)
    spec = model.variables[name]
    var = data["variables"][name]
    target = var if case is None else var["cases"].setdefault(case, {})
    if isinstance(spec, DiscreteVariable):
        assert values is not None
        new_values = [str(v) for v in values]
        if case is not None and isinstance(target, list):
            target = var["cases"][case] = {"values": target}
        old_values = target.get("values") or []
        # no initial written: the first of the old list was (a new order must not move it)
        start = target.get("initial", old_values[0] if old_values else None)
        target["values"] = new_values
        fits = start in new_values
        if initial is not None and str(initial) in new_values:
            target["initial"] = str(initial)
        elif fits and start != new_values[0]:
            target["initial"] = start
        elif not fits and ("initial" in target or case is None):
            target["initial"] = str(current) if str(current) in new_values else new_values[0]
    else:
        assert ranges is not None
        allowed = set(expand_ranges([list(r) for r in ranges]))
        if isinstance(spec, TimeVariable):
            target["ranges"] = [
                [format_hms(int(a)), format_hms(int(b)), int(s)] for a, b, s in ranges
            ]
        else:
            target["ranges"] = [list(r) for r in ranges]
        if initial is not None and _magnitude(spec, initial) in allowed:
            target["initial"] = initial
        initial = target.get("initial")
        if (initial is not None or case is None) and (
            initial is None or _magnitude(spec, initial) not in allowed
        ):
            fallback = (
                current
                if current is not None and _magnitude(spec, current) in allowed
                else min(allowed)
            )
            target["initial"] = (
                format_hms(int(_magnitude(spec, fallback)))
                if isinstance(spec, TimeVariable)
                else fallback
            )
    if wrap is not None:
        var["wrap"] = wrap
    return _rebuild(data)


def set_case_start(model: ApplianceModel, name: str, case: str, value: Any) -> ApplianceModel:
    """The model with the parent's ``case`` starting ``name`` at ``value``."""
    data = _dump(model)
    cases = data["variables"][name]["cases"]
    if isinstance(cases[case], list):  # a discrete case written as its bare list of values
        cases[case] = {"values": cases[case]}
    spec = model.variables[name]
    cases[case]["initial"] = (
        format_hms(parse_hms(str(value))) if isinstance(spec, TimeVariable) else value
    )
    return _rebuild(data)


def _magnitude(spec: Any, value: Any) -> float:
    if isinstance(spec, TimeVariable) and isinstance(value, str):
        return float(parse_hms(value))
    return float(value)


def set_effects(
    model: ApplianceModel, feature: str, step: int, effects: dict[str, Any]
) -> ApplianceModel:
    """Give actions of one step new effects (e.g. ``next`` ↔ ``prev``, ``{add: -5}``)."""
    data = _dump(model)
    entry = data["features"][feature][step]
    spec = model.features[feature][step]
    if isinstance(spec.effect, dict):  # already one effect per action
        current = entry["effect"]
    else:
        current = {a: _plain(default_effect(spec, a, model)) for a in spec.actions}
    entry["effect"] = {**current, **effects}
    return _rebuild(data)


def _plain(effect: Any) -> Any:
    return effect.model_dump(mode="json") if hasattr(effect, "model_dump") else effect


def insert_step(
    model: ApplianceModel,
    feature: str,
    before: int,
    actions: Sequence[str],
    move: bool = False,
) -> ApplianceModel:
    """Insert a step that only moves the procedure on (an entry key the model missed);
    ``move``: the keys leave the steps they were filed under (where not their only key)."""
    data = _dump(model)
    if move:
        for action in actions:
            _take_out(data, action, keep=(feature, -1))
    data["features"][feature].insert(
        before, {"actions": list(actions), "note": "learnt from feedback"}
    )
    return _rebuild(data)


def entry_then_keys(
    model: ApplianceModel, feature: str, index: int, effects: dict[str, str]
) -> ApplianceModel:
    """The step's key only brings its setting up; ``effects``' keys adjust it, in a step of
    their own after it (POWER, then + and −)."""
    data = _dump(model)
    steps = data["features"][feature]
    old = steps[index]
    entry = {"actions": list(old["actions"]), "note": "learnt from feedback"}
    adjust = {k: v for k, v in old.items() if k not in ("actions", "effect", "note", "on_entry")}
    adjust.update(actions=list(effects), effect=dict(effects), note="learnt from feedback")
    steps[index : index + 1] = [entry, adjust]
    return _rebuild(data)


def set_entry_format(model: ApplianceModel, name: str, fmt: str) -> ApplianceModel:
    """Read a keypad variable's typed digits in another format (``mm:ss`` for ``minutes``)."""
    data = _dump(model)
    data["variables"][name].setdefault("entry", {})["format"] = fmt
    return _rebuild(data)


def set_display(
    model: ApplianceModel,
    name: str,
    template: str | dict[str, str],
    time_format: str | None = None,
    drop_unit: bool = False,
) -> ApplianceModel:
    """Print a variable through another template: as its label when the template is the usual
    "LABEL {value}", else as its ``show`` template (``"PL{value}"``, or a word per value);
    ``time_format``: a time variable's new display style too ("min" for "30 min");
    ``drop_unit``: a number the display prints without the unit the model gives it."""
    data = _dump(model)
    var = data["variables"][name]
    if time_format is not None:
        var["format"] = time_format
    if drop_unit:
        var.pop("unit", None)
    if isinstance(template, dict):
        var["show"] = template
        return _rebuild(data)
    label, _, rest = template.partition(" ")
    if rest == "{value}" and "{" not in label and not isinstance(var.get("show"), dict):
        var["label"] = label
        var.pop("show", None)
    else:
        var["show"] = template
    return _rebuild(data)


def set_on_entry(model: ApplianceModel, feature: str, step: int, on_entry: str) -> ApplianceModel:
    """Say whether the press that enters a step applies its effect or only shows the value."""
    data = _dump(model)
    data["features"][feature][step]["on_entry"] = on_entry
    return _rebuild(data)


def split_feature(
    model: ApplianceModel, feature: str, index: int, first: bool = False
) -> tuple[ApplianceModel, str]:
    """``feature`` ends before step ``index``; its steps from there are a procedure of their own
    (named after the first one's setting), right after it — or before every other (``first``).
    """
    data = _dump(model)
    steps = data["features"][feature]
    if not 0 < index < len(steps):
        raise RepairError(f"{feature} has no step {index} to split at")
    head, tail = steps[:index], steps[index:]
    base = f"{tail[0].get('variable') or feature}_procedure"
    name = base
    while name in data["features"]:
        name += "_learnt"
    features: dict[str, Any] = {} if not first else {name: tail}
    for title, body in data["features"].items():
        features[title] = head if title == feature else body
        if title == feature and not first:
            features[name] = tail
    data["features"] = features
    return _rebuild(data), name


def drop_dependence(model: ApplianceModel, name: str, case: str) -> ApplianceModel:
    """``name`` does not depend on a programme after all: it keeps its values in ``case``
    (the programme it was seen in) whatever the programme."""
    data = _dump(model)
    var = data["variables"][name]
    cases = var.pop("cases", {})
    var.pop("depends_on", None)
    own: Any = cases.get(case) or next((c for c in cases.values() if c), {})
    if isinstance(own, list):
        own = {"values": own}
    var.update({k: v for k, v in own.items() if k in ("values", "ranges", "initial")})
    return _rebuild(data)


def set_start(model: ApplianceModel, name: str, case: str, value: Any) -> ApplianceModel:
    """Choosing the programme ``case`` starts ``name`` at ``value`` (its case's initial)."""
    data = _dump(model)
    cases = data["variables"][name].get("cases", {})
    own = cases.get(case)
    if own is None:
        raise RepairError(f"{name} has no case {case!r}")
    if isinstance(own, list):
        own = cases[case] = {"values": own}
    own["initial"] = value
    return _rebuild(data)


def set_side_effect(
    model: ApplianceModel,
    feature: str,
    step: int,
    name: str,
    value: Any = None,
    reset: bool = False,
) -> ApplianceModel:
    """What one step does to ``name`` besides its own setting: sets it to ``value``, resets it
    (``reset``), or — with neither — leaves it alone."""
    data = _dump(model)
    entry = data["features"][feature][step]
    entry.get("set", {}).pop(name, None)
    entry["reset"] = [r for r in entry.get("reset", []) if r != name]
    if value is not None:
        entry.setdefault("set", {})[name] = value
    elif reset:
        entry["reset"].append(name)
    for key in ("set", "reset"):
        if not entry.get(key):
            entry.pop(key, None)
    return _rebuild(data)


def allow(model: ApplianceModel, guard: int, action: str) -> ApplianceModel:
    """A guard lets ``action`` through after all."""
    data = _dump(model)
    data["guards"][guard]["only"] = [*data["guards"][guard]["only"], action]
    return _rebuild(data)


def allow_all(model: ApplianceModel, pairs: Sequence[tuple[int, str]]) -> ApplianceModel:
    """Every guard ``index`` lets its ``action`` through: the union of :func:`allow`'s
    variants, which can do everything any one of them can."""
    data = _dump(model)
    for index, action in pairs:
        only = data["guards"][index]["only"]
        if action not in only:
            data["guards"][index]["only"] = [*only, action]
    return _rebuild(data)


def disallow(model: ApplianceModel, guard: int, action: str) -> ApplianceModel:
    """A guard does not let ``action`` through after all."""
    data = _dump(model)
    data["guards"][guard]["only"] = [a for a in data["guards"][guard]["only"] if a != action]
    return _rebuild(data)


def add_guard(
    model: ApplianceModel,
    when: dict[str, Any],
    only: Sequence[str],
    display: str = "",
    hide: bool = False,
) -> ApplianceModel:
    """A guard the model lacked: while ``when`` holds, only ``only`` works."""
    data = _dump(model)
    guard: dict[str, Any] = {"name": "learnt", "when": when, "only": list(only), "display": display}
    if hide:
        guard["hide"] = True
    data.setdefault("guards", []).append(guard)
    return _rebuild(data)


def move_action(
    model: ApplianceModel, action: str, where: tuple[str, int], effect: Any = None
) -> ApplianceModel:
    """File ``action`` under the step ``where`` (with ``effect`` on its setting) and take it
    out of every other step, except one it is the only key of."""
    data = _dump(model)
    feature, index = where
    _take_out(data, action, keep=where)
    step = data["features"][feature][index]
    spec = model.features[feature][index]
    step["actions"] = [*step["actions"], action]
    if spec.variable is not None:
        current = (
            dict(step["effect"])
            if isinstance(step.get("effect"), dict)
            else {a: _plain(default_effect(spec, a, model)) for a in spec.actions}
        )
        step["effect"] = {**current, action: effect if effect is not None else "none"}
    return _rebuild(data)


def _take_out(data: dict[str, Any], action: str, keep: tuple[str, int]) -> None:
    """Remove ``action`` from every step but ``keep`` (index -1: none of that procedure's
    steps is kept, but the procedure stays). A step it was the only key of goes too — and with
    a first step, its whole procedure: the key was shown to do something else, so nothing could
    ever start it."""
    features = data["features"]
    for name in list(features):
        steps = features[name]
        for i in reversed(range(len(steps))):
            step = steps[i]
            if (name, i) == keep or action not in step["actions"]:
                continue
            if len(step["actions"]) > 1:
                step["actions"] = [a for a in step["actions"] if a != action]
                if isinstance(step.get("effect"), dict):
                    step["effect"].pop(action, None)
            elif name == keep[0]:
                continue  # the procedure the key goes to keeps its own steps
            elif i == 0:
                del features[name]
                break
            else:
                del steps[i]


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
    control = _control_id(action)
    digit = action.rsplit("_", 1)[-1]
    keypad = len(digit) == 1 and digit.isdigit()  # press_7: a keypad key
    if not any(c["id"] == control for c in data["controls"]):
        turning = action.endswith(("_cw", "_ccw"))
        kind = "key" if keypad else "dial" if turning else "button"
        data["controls"].append({"id": control, "kind": kind})
    spec: dict[str, Any] = {"control": control}
    if keypad:
        spec["digit"] = int(digit)
    if action.startswith("hold"):
        spec.update(skill="hold", seconds=3)
    elif action.endswith("_ccw"):
        spec["skill"] = "turn_ccw"
    elif action.endswith("_cw"):
        spec["skill"] = "turn_cw"
    data["actions"][action] = spec


def _control_id(action: str) -> str:
    """A control id for an action the model did not know: its name without the skill."""
    name = action
    for prefix in ("press_", "hold_", "turn_"):
        if name.startswith(prefix):
            name = name[len(prefix) :]
    for suffix in ("_cw", "_ccw"):
        if name.endswith(suffix):
            name = name[: -len(suffix)]
    if name[:1].isdigit():  # press_7: keypad key 7
        return f"key_{name}"
    return f"{name}_control" if name else "learnt_control"


def add_indicator(model: ApplianceModel, name: str) -> ApplianceModel:
    """The display shows this setting as a lamp too, whatever screen is up."""
    data = _dump(model)
    indicators = data.setdefault("display", {}).setdefault("indicators", [])
    if name not in indicators:
        indicators.append(name)
    return _rebuild(data)


def drop_indicator(model: ApplianceModel, name: str) -> ApplianceModel:
    """The display has no lamp for this setting: it shows it only on its own screen."""
    data = _dump(model)
    display = data.get("display") or {}
    display["indicators"] = [n for n in display.get("indicators", []) if n != name]
    return _rebuild(data)


def drop_action(model: ApplianceModel, action: str, where: tuple[str, int]) -> ApplianceModel:
    """Take ``action`` out of one step (it keeps its other keys)."""
    data = _dump(model)
    step = data["features"][where[0]][where[1]]
    step["actions"] = [a for a in step["actions"] if a != action]
    if isinstance(step.get("effect"), dict):
        step["effect"].pop(action, None)
    return _rebuild(data)
