"""Repairs to a belief model, as data edits: each returns a new validated model.

The closed loop learns facts from feedback (the values a variable really takes, which way a
key moves it, a step the procedure needs); these functions write such facts into a copy of
the model. A repair that would make the model invalid raises :class:`RepairError` and the
agent keeps its old model.

Adding a whole setting the model lacked is in :mod:`apbot.agent.added_settings`, the shared
core (:class:`RepairError`, model ↔ data) in :mod:`apbot.agent.model_edits`; both are
re-exported here.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from apbot.agent.added_settings import (
    add_choice_setting,
    add_keypad_setting,
    add_keypad_step,
    add_setting,
    plain_keys,
    plain_steps,
    setting_step,
)
from apbot.agent.model_edits import RepairError, _dump, _rebuild
from apbot.model.domain import all_values
from apbot.model.effects import default_effect
from apbot.model.schema import ApplianceModel, DiscreteVariable, TimeVariable
from apbot.model.values import expand_ranges, format_hms, parse_hms

__all__ = [
    "RepairError",
    "add_choice_setting",
    "add_guard",
    "add_indicator",
    "add_keypad_setting",
    "add_keypad_step",
    "add_setting",
    "allow",
    "allow_all",
    "disallow",
    "drop_action",
    "drop_dependence",
    "drop_indicator",
    "entry_then_keys",
    "insert_step",
    "move_action",
    "name_values",
    "plain_keys",
    "plain_steps",
    "redefine_domain",
    "set_display",
    "set_effects",
    "set_entry_format",
    "set_on_entry",
    "set_side_effect",
    "set_start",
    "setting_step",
    "split_feature",
]


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
    checked: bool = True,
) -> ApplianceModel:
    """A new domain for ``name`` (for the parent's ``case`` when it depends on one).

    Discrete variables take ``values`` in order; numeric and time variables take ``ranges`` of
    magnitudes (seconds for times). The initial value is ``initial`` when given and it fits,
    else kept when it still fits, else the observed ``current`` value (or the first value).
    ``checked=False``: see :func:`set_effects`.
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
        if case is None:
            _rekey_dependents(data, name, new_values)
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
    return _rebuild(data, checked)


def _rekey_dependents(data: dict[str, Any], name: str, values: list[str]) -> None:
    """The settings that depend on ``name`` follow its new values: a case named in other
    words of a value the display showed ("bread and cakes" where the panel shows "bread":
    the same first word, no other value so named) takes that value's name; a case for a
    value the panel never shows is dropped. A dependent left with no case stays as it was
    (the repair then fails as before rather than lose the setting)."""
    for var in data["variables"].values():
        if not isinstance(var, dict) or var.get("depends_on") != name:
            continue
        cases = var.get("cases") or {}
        kept: dict[str, Any] = {}
        for key, spec in cases.items():
            if key in values:
                kept.setdefault(key, spec)
                continue
            first = key.split()[:1]
            named = [v for v in values if v.split()[:1] == first and v not in cases]
            if len(named) == 1:
                kept.setdefault(named[0], spec)
        if kept:
            var["cases"] = kept


def _magnitude(spec: Any, value: Any) -> float:
    if isinstance(spec, TimeVariable) and isinstance(value, str):
        return float(parse_hms(value))
    return float(value)


def set_effects(
    model: ApplianceModel,
    feature: str,
    step: int,
    effects: dict[str, Any],
    checked: bool = True,
) -> ApplianceModel:
    """Give actions of one step new effects (e.g. ``next`` ↔ ``prev``, ``{add: -5}``).

    ``checked=False`` only validates the schema: for a first edit the caller completes (a
    domain fitted to the new effect) before the whole model is checked."""
    data = _dump(model)
    entry = data["features"][feature][step]
    spec = model.features[feature][step]
    if isinstance(spec.effect, dict):  # already one effect per action
        current = entry["effect"]
    else:
        current = {a: _plain(default_effect(spec, a, model)) for a in spec.actions}
    entry["effect"] = {**current, **effects}
    return _rebuild(data, checked)


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


def set_entry_format(
    model: ApplianceModel,
    name: str,
    fmt: str,
    max_digits: int | None = None,
    overflow: str | None = None,
) -> ApplianceModel:
    """Read a keypad variable's typed digits in another format (``mm:ss`` for ``minutes``);
    ``max_digits`` / ``overflow``: how many digits it keeps, and what a digit past them does."""
    data = _dump(model)
    entry = data["variables"][name].setdefault("entry", {})
    entry["format"] = fmt
    if max_digits is not None:
        entry["max_digits"] = max_digits
    if overflow is not None:
        entry["overflow"] = overflow
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


def set_start(model: ApplianceModel, name: str, case: str | None, value: Any) -> ApplianceModel:
    """Choosing the programme ``case`` starts ``name`` at ``value`` (its case's initial): learnt
    from the display after the choice (``side_effects``) or from a look (``case_starts``). With
    no case, ``name`` itself starts there (where a reset brings it back)."""
    data = _dump(model)
    if case is None:
        data["variables"][name]["initial"] = value
        return _rebuild(data)
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


def name_values(model: ApplianceModel, name: str, shown: dict[str, str]) -> ApplianceModel:
    """A list setting's values as the display named them: each of ``shown`` (value → the text
    printed for it) joins the values the belief had, printed as shown; a key read as flipping
    a switch (``toggle``) steps through the list instead, round."""
    data = _dump(model)
    var = data["variables"][name]
    known = [str(v) for v in all_values(model.variables[name])]
    show = dict(var.get("show") or {})
    for value, text in shown.items():
        show.setdefault(value, text)
    var["values"] = known + [v for v in shown if v not in known]
    var["show"] = show
    for steps in data["features"].values():
        for step in steps:
            if step.get("variable") == name and step.get("effect") == "toggle":
                step["effect"] = "next"
                var["wrap"] = True
    return _rebuild(data)
