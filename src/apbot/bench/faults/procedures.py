"""Faults in procedures (features): a step skipped, and what a step's keys are believed to do.

A reader skips "press TIMER before ▲/▼", misses that the first press only shows the setting,
gets a side effect wrong, files a key under the wrong procedure, or reads two procedures as one.
"""

from __future__ import annotations

import random
from typing import Any

from apbot.bench.faults.common import (
    Candidates,
    Data,
    Fault,
    actions_text,
    by_mode,
    copied,
    directional,
    dump,
    plain,
    protected,
)
from apbot.model.domain import ValueProblem, build_domain, normalise
from apbot.model.effects import default_effect
from apbot.model.schema import ApplianceModel, GoTo, Step


def missing_step(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A feature with two or more steps loses one (e.g. "press TIMER before ▲/▼").

    Steps that only press a key (entry, confirm) are tried first: that is what a reader skips.
    When the step's actions are used nowhere else they stay in the model (so it remains valid)
    as no-op actions of the neighbouring step: the belief then thinks ▲ works without TIMER,
    and that TIMER does nothing.
    """
    steps = model.features.get(name, [])
    if len(steps) < 2:
        return
    keys = [i for i, s in enumerate(steps) if s.variable is None]  # entry or confirm steps
    others = [i for i, s in enumerate(steps) if s.variable is not None]
    for i in rng.sample(keys, len(keys)) + rng.sample(others, len(others)):
        step = steps[i]
        data = dump(model)
        del data["features"][name][i]
        used = {a for feature in data["features"].values() for s in feature for a in s["actions"]}
        orphans = [a for a in step.actions if a not in used]
        label = f"step {i + 1} of {len(steps)} ({actions_text(step.actions)}) is missing"
        if not orphans:
            if i < len(steps) - 1 or not _taken_over(model, name, step):
                yield data, Fault("missing_step", name, label)
            continue
        if step.variable is not None or step.set or step.reset:
            continue  # a step that changes values cannot become a no-op
        j = i if i < len(steps) - 1 else i - 1  # the neighbour, indexed after the removal
        neighbour = steps[j + 1 if j >= i else j]
        if i == 0 and _claimed_before(model, name, neighbour.actions):
            continue  # ▲ pressed first still enters the earlier feature: nothing would change
        target = data["features"][name][j]
        target["actions"] = [*orphans, *target["actions"]]
        if neighbour.variable is not None or neighbour.effect is not None:
            target["effect"] = {
                **{a: "none" for a in orphans},
                **{a: plain(default_effect(neighbour, a, model)) for a in neighbour.actions},
            }
        side = "next" if j >= i else "previous"
        yield (
            data,
            Fault(
                "missing_step",
                name,
                f"{label}; {', '.join(orphans)} kept as a no-op of the {side} step",
            ),
        )


def _same_step(a: Step, b: Step) -> bool:
    return a.model_copy(update={"note": ""}) == b.model_copy(update={"note": ""})


def _taken_over(model: ApplianceModel, name: str, last: Step) -> bool:
    """Whether, without this last step, its first key would enter a one-step feature that does
    the same (a closing START that the ``start`` feature does anyway): nothing would change."""
    for feature, steps in model.features.items():
        if feature != name and last.actions[0] in steps[0].actions:
            return len(steps) == 1 and _same_step(steps[0], last)
    return False


def _claimed_before(model: ApplianceModel, name: str, actions: list[str]) -> bool:
    """Whether every action starts a feature listed before ``name`` (so none can start it)."""
    earlier = list(model.features)[: list(model.features).index(name)]
    starts = {a for feature in earlier for a in model.features[feature][0].actions}
    return all(a in starts for a in actions)


def _settings_steps(model: ApplianceModel, name: str) -> list[int]:
    """Steps of feature ``name`` that step a setting (not power, locks or run state) up, down
    or over: where "the first press only shows it" is a plausible reading."""
    places = []
    for i, step in enumerate(model.features.get(name, [])):
        if step.variable is None or protected(step.variable):
            continue
        effects = [default_effect(step, a, model) for a in step.actions]
        stepping = [e for e in effects if directional(e) or e == "toggle"]
        if stepping and all(e in stepping or e == "none" for e in effects):
            places.append(i)
    return places


def on_entry(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """``on_entry`` read the other way: the belief has the first press of TEMP only show the
    setting where it already changes it (``on_entry: show`` for ``apply``), or the reverse."""
    places = _settings_steps(model, name)
    for index in rng.sample(places, len(places)):
        step = model.features[name][index]
        data = dump(model)
        keys = actions_text(step.actions)
        if step.on_entry == "show":
            data["features"][name][index].pop("on_entry", None)
            detail = f"features.{name}[{index}]: the first press of {keys} changes {step.variable}"
            detail += " (it only shows it)"
        else:
            data["features"][name][index]["on_entry"] = "show"
            detail = f"features.{name}[{index}]: the first press of {keys} only shows "
            detail += f"{step.variable} (it changes it)"
        yield data, Fault("on_entry", name, detail)


def _other_value(model: ApplianceModel, target: str, value: Any, rng: random.Random) -> Any:
    """A value of ``target`` next to ``value`` (a ``set`` misread), or None when the variable
    has only two values (an on/off a reader does not confuse) or ``value`` is not plain."""
    var = model.variables[target]
    if var.depends_on is not None:
        return None
    domain = build_domain(var)
    values = list(domain.values)
    try:
        i = values.index(normalise(var, value))
    except (ValueProblem, ValueError):
        return None
    if len(values) < 3:
        return None
    return rng.choice([values[j] for j in (i - 1, i + 1) if 0 <= j < len(values)])


def _settings(model: ApplianceModel) -> list[str]:
    """Variables a step adjusts that a reader could believe reset (not power, locks, run)."""
    return [
        n
        for n in model.variables
        if not protected(n)
        and any(s.variable == n for steps in model.features.values() for s in steps)
    ]


def side_effect(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A side effect of a step wrong: a ``set`` to a wrong value, a ``set`` or ``reset``
    missing ("+30 SEC does not start the oven"), or one invented ("STOP also clears the
    timer", "choosing a programme clears the delay", "the POPCORN key starts at once")."""
    steps = model.features.get(name, [])
    original = dump(model)
    groups: dict[str, list[tuple[Data, Fault]]] = {
        "no set": [],
        "wrong set": [],
        "no reset": [],
        "extra reset": [],
        "starts": [],
    }

    def add(group: str, data: Data, detail: str) -> None:
        groups[group].append((data, Fault("side_effect", name, detail)))

    for index, step in enumerate(steps):
        where = f"features.{name}[{index}]"
        for target, value in step.set.items():
            data = copied(original)
            del data["features"][name][index]["set"][target]
            add("no set", data, f"{where} no longer sets {target} to {value!r}")
            wrong = _other_value(model, target, value, rng)
            if wrong is not None:
                data = copied(original)
                data["features"][name][index]["set"][target] = wrong
                add("wrong set", data, f"{where} sets {target} to {wrong!r} instead of {value!r}")
        for target in step.reset:
            if model.variables[target].depends_on in {step.variable, *step.reset, *step.set}:
                continue  # reset with its programme anyway
            data = copied(original)
            data["features"][name][index]["reset"] = [r for r in step.reset if r != target]
            add("no reset", data, f"{where} no longer resets {target}")
        chooses = step.variable is not None and any(
            v.depends_on == step.variable for v in model.variables.values()
        )
        if step.reset or step.set or chooses:  # "STOP also clears the timer", "MENU the delay"
            chosen = {step.variable, *step.reset, *step.set}  # a programme resets its settings
            others = [
                v
                for v in _settings(model)
                if v not in chosen and model.variables[v].depends_on not in chosen
            ]
            for target in rng.sample(others, min(3, len(others))):
                data = copied(original)
                data["features"][name][index]["reset"] = [*step.reset, target]
                add("extra reset", data, f"{where} also resets {target} (it does not)")
        started = _started_value(model)
        one_touch = any(isinstance(default_effect(step, a, model), GoTo) for a in step.actions)
        if (
            one_touch  # a one-touch key (POPCORN, EXPRESS 1) believed to start at once
            and started is not None
            and "running" not in step.set
            and step.variable is not None
            and not protected(step.variable)
        ):
            data = copied(original)
            data["features"][name][index].setdefault("set", {})["running"] = started
            add("starts", data, f"{where} also sets running to {started!r} (it does not start)")
    yield from by_mode(list(groups.values()), rng)


def _started_value(model: ApplianceModel) -> str | None:
    """The value that means "running" (``on``), if the run state is a plain on/off."""
    var = model.variables.get("running")
    if var is None:
        return None
    values = getattr(var, "values", None) or []
    return "on" if var.depends_on is None and "on" in values else None


def misplaced_action(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A key filed under the wrong procedure: ``press_down`` moved from its step of
    ``set_temperature`` into a step of ``set_timer`` (the belief thinks ▼ sets the timer and
    that ``set_temperature`` has only ▲), or the entry key of a procedure ("press TEMP, then
    ▲/▼") filed under another one, its step gone. Keys that share a step move alone, so every
    step keeps a key; a moved key steps the value it lands on as it stepped its own."""
    original = dump(model)
    steps = model.features.get(name, [])
    moves: list[tuple[int, str, bool]] = [
        (i, a, False)
        for i, step in enumerate(steps)
        if len(step.actions) >= 2
        for a in step.actions
        if model.actions[a].digit is None
    ]
    moves += [
        (i, step.actions[0], True)
        for i, step in enumerate(steps)
        if len(steps) >= 2
        and len(step.actions) == 1
        and step.variable is None
        and not step.set
        and not step.reset
    ]
    destinations = [
        (feature, j)
        for feature, other in model.features.items()
        if feature != name
        for j, step in enumerate(other)
        if (step.variable is None or not protected(step.variable))
        and all(model.actions[a].digit is None for a in step.actions)
    ]
    for i, action, whole in rng.sample(moves, len(moves)):
        places = [(f, j) for f, j in destinations if action not in model.features[f][j].actions]
        for feature, j in rng.sample(places, min(3, len(places))):
            target = model.features[feature][j]
            step = steps[i]
            effect = default_effect(step, action, model)
            data = copied(original)
            if whole:
                del data["features"][name][i]
            else:
                source = data["features"][name][i]
                source["actions"] = [a for a in step.actions if a != action]
                if isinstance(step.effect, dict):
                    source["effect"] = {a: e for a, e in source["effect"].items() if a != action}
            moved = data["features"][feature][j]
            moved["actions"] = [*target.actions, action]
            if target.variable is not None:
                carried = plain(effect) if effect in ("next", "prev") else "next"
                moved["effect"] = {
                    **{a: plain(default_effect(target, a, model)) for a in target.actions},
                    action: carried,
                }
            detail = f"{action} moved from features.{name}[{i}] to features.{feature}[{j}]"
            if whole:
                detail += f" (step {i + 1} of {name} gone)"
            yield data, Fault("misplaced_action", name, detail)


def _adjusts(steps: list[Any], test: Any) -> bool:
    return any(s.variable is not None and test(s.variable) for s in steps)


def merged_features(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """Two procedures read as one: ``set_time`` and the ``start`` that follows it in the manual
    merged into ``set_time`` (its steps, then start's), so the belief thinks START only works
    after setting the time. The feature merges with the next one in the model's order; power
    and locks are left apart."""
    del rng  # one candidate: the next feature
    names = list(model.features)
    if name not in names or names.index(name) + 1 >= len(names):
        return
    following = names[names.index(name) + 1]
    first, second = model.features[name], model.features[following]
    if not _adjusts(first, lambda v: not protected(v)):
        return
    if _adjusts(second, lambda v: v == "power" or "lock" in v):
        return
    data = dump(model)
    data["features"][name] = [*data["features"][name], *data["features"][following]]
    del data["features"][following]
    detail = f"{name} and {following} read as one procedure ({following}'s steps follow)"
    yield data, Fault("merged_features", name, detail)
