"""Random small appliance models and goals, for checking the planner against brute force.

The models use every part of the format — discrete, numeric and time variables, piecewise
ranges, wrap and clamp, keypad entry, programme-dependent settings, go-to and add effects, side
effects, entry steps, ``on_entry: show``, holds, two-control holds, power and lock guards — but
stay small enough (a few thousand states) for breadth-first search over the whole simulator.
Generation is driven by a ``random.Random`` so a failing case is reproducible from its seed.
"""

from __future__ import annotations

import random
from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import ApplianceModel


def random_model(rng: random.Random) -> ApplianceModel:
    """A schema-valid model with all references resolved (semantic checks may still warn)."""
    variables: dict[str, Any] = {}
    controls: list[dict[str, Any]] = []
    actions: dict[str, Any] = {}
    features: dict[str, list[dict[str, Any]]] = {}
    guards: list[dict[str, Any]] = []

    def new_action(kind: str = "button", **extra: Any) -> str:
        index = len(actions)
        control = f"c{index}"
        controls.append({"id": control, "kind": kind, "label": control.upper()})
        name = f"a{index}"
        actions[name] = {"control": control, **extra}
        return name

    if rng.random() < 0.5:  # a power switch guarding everything else
        variables["power"] = {"type": "discrete", "values": ["off", "on"]}
        press = new_action()
        features["power"] = [{"actions": [press], "variable": "power", "effect": "toggle"}]
        guards.append({"when": {"power": "off"}, "only": [press], "hide": rng.random() < 0.5})

    count = rng.randint(1, 4)
    parent: str | None = None
    for i in range(count):
        name = f"v{i}"
        kind = rng.choice(
            ["discrete", "discrete", "numeric", "time", "keypad", "dependent", "large"]
        )
        if kind == "dependent" and parent is None:
            kind = "discrete"
        variables[name] = _variable(rng, kind, parent, variables)
        if (
            variables[name]["type"] == "discrete"
            and "depends_on" not in variables[name]
            and parent is None
        ):
            parent = name
    pool = _ActionPool(rng, new_action)
    for name in [v for v in variables if v.startswith("v")]:
        for _ in range(rng.randint(1, 2)):
            features[f"f{len(features)}"] = _feature(rng, name, variables, pool)

    numeric = [
        v for v, spec in variables.items() if spec["type"] == "numeric" and "depends_on" not in spec
    ]
    if numeric and rng.random() < 0.25:  # a guard on a number: "set a time before starting"
        guarded = rng.choice(numeric)
        low = (
            _ranges(rng)[0][0]
            if "ranges" not in variables[guarded]
            else variables[guarded]["ranges"][0][0]
        )
        adjusting = [
            a
            for steps in features.values()
            for step in steps
            if step.get("variable") == guarded
            for a in step["actions"]
        ]
        entering = [
            a
            for steps in features.values()
            if any(st.get("variable") == guarded for st in steps)
            for a in steps[0]["actions"]
        ]
        guards.append(
            {"when": {guarded: [low, low + 1, low + 2]}, "only": sorted(set(adjusting + entering))}
        )

    if rng.random() < 0.3:  # a child lock on a hold, possibly of two controls
        variables["lock"] = {"type": "discrete", "values": ["off", "on"]}
        if rng.random() < 0.5 and len(controls) >= 2:
            a, b = rng.sample([c["id"] for c in controls], 2)
            name = f"a{len(actions)}"
            actions[name] = {"controls": [a, b], "skill": "hold", "seconds": 3}
        else:
            name = new_action(skill="hold", seconds=2)
        features["lock"] = [{"actions": [name], "variable": "lock", "effect": "toggle"}]
        guards.append({"when": {"lock": "on"}, "only": [name]})

    if rng.random() < 0.3 and len(variables) > 1:  # a step with side effects
        target = rng.choice([v for v in variables if "depends_on" not in variables[v]])
        domain = build_domain(
            ApplianceModel.model_validate(
                _wrap(variables, controls, actions, features, guards)
            ).variables[target]
        )
        press = new_action()
        step: dict[str, Any] = {"actions": [press]}
        if rng.random() < 0.5:
            step["set"] = {target: domain.values[rng.randrange(len(domain))]}
        else:
            step["reset"] = [target]
        features[f"f{len(features)}"] = [step]

    return ApplianceModel.model_validate(_wrap(variables, controls, actions, features, guards))


def _wrap(
    variables: dict[str, Any],
    controls: list[dict[str, Any]],
    actions: dict[str, Any],
    features: dict[str, Any],
    guards: list[dict[str, Any]],
) -> dict[str, Any]:
    return {
        "appliance": {"id": "generated", "category": "generated"},
        "controls": controls,
        "variables": variables,
        "actions": actions,
        "features": features,
        "guards": guards,
    }


def _ranges(rng: random.Random) -> list[list[int]]:
    start = rng.choice([0, 1, 5, 10])
    step = rng.choice([1, 2, 5])
    first = [start, start + step * rng.randint(1, 3), step]
    if rng.random() < 0.5:
        return [first]
    step2 = step * rng.choice([2, 3])
    return [first, [first[1], first[1] + step2 * rng.randint(1, 3), step2]]


def _variable(
    rng: random.Random, kind: str, parent: str | None, variables: dict[str, Any]
) -> dict[str, Any]:
    wrap = rng.random() < 0.5
    if kind == "discrete":
        values = [f"x{j}" for j in range(rng.randint(2, 4))]
        return {"type": "discrete", "values": values, "wrap": wrap, "initial": rng.choice(values)}
    if kind == "numeric":
        return {"type": "numeric", "ranges": _ranges(rng), "wrap": wrap, "unit": "min"}
    if kind == "large":  # more values than the planner enumerates cheaply (> 64)
        return {"type": "numeric", "ranges": [[0, rng.choice([70, 100]), 1]], "wrap": wrap}
    if kind == "time":
        return {
            "type": "time",
            "wrap": wrap,
            "ranges": [["00:00:00", "00:02:00", 30], ["00:02:00", "00:04:00", 60]],
        }
    if kind == "keypad":
        top, step = rng.choice([(9, 1), (12, 3), (20, 5), (120, 30)])
        return {
            "type": "numeric",
            "ranges": [[0, top, step]],
            "entry": {
                "format": "number",
                "max_digits": rng.choice([2, 3]),
                "overflow": rng.choice(["shift", "ignore"]),
            },
        }
    assert parent is not None
    parent_values = variables[parent]["values"]
    cases = {}
    for value in parent_values:
        if rng.random() < 0.8:
            size = rng.randint(1, 3)
            cases[value] = {
                "values": [f"y{j}" for j in range(size)],
                "initial": f"y{rng.randrange(size)}",
            }
    if not cases:
        cases[parent_values[0]] = {"values": ["y0", "y1"]}
    return {"type": "discrete", "depends_on": parent, "cases": cases, "wrap": wrap}


class _ActionPool:
    """Actions shared the way real panels share them: one ▲/▼ pair and one keypad."""

    def __init__(self, rng: random.Random, new_action: Any) -> None:
        self.rng = rng
        self.new_action = new_action
        self.arrows: tuple[str, str] | None = None
        self.digits: list[str] | None = None

    def arrows_pair(self) -> tuple[str, str]:
        if self.arrows is None or self.rng.random() < 0.3:
            self.arrows = (self.new_action(), self.new_action())
        return self.arrows

    def keypad(self) -> list[str]:
        if self.digits is None:
            self.digits = [self.new_action("key", digit=d) for d in range(10)]
        return self.digits


def _adjusting_step(
    rng: random.Random, name: str, var: dict[str, Any], pool: _ActionPool
) -> dict[str, Any]:
    if "entry" in var:
        step = {"actions": pool.keypad(), "variable": name}
        if rng.random() < 0.2:
            step["on_entry"] = "show"
        return step
    effects: dict[str, Any] = {}
    if rng.random() < 0.5:
        up, down = pool.arrows_pair()
        effects = {up: "next", down: "prev"}
    else:
        hold = {"skill": "hold", "seconds": 1} if rng.random() < 0.15 else {}
        effects[pool.new_action(**hold)] = rng.choice(["next", "next", "prev", "reset"])
    if var["type"] != "discrete" and rng.random() < 0.3:
        effects[pool.new_action()] = {"add": rng.choice([1, 2, 5, 10, 30, 60, -30])}
    if var.get("values") and rng.random() < 0.2:
        effects[pool.new_action()] = {"to": rng.choice(var["values"])}
    step: dict[str, Any] = {"actions": list(effects), "variable": name, "effect": effects}
    if rng.random() < 0.2:
        step["on_entry"] = "show"
    return step


def _feature(
    rng: random.Random, name: str, variables: dict[str, Any], pool: _ActionPool
) -> list[dict[str, Any]]:
    """A procedure adjusting ``name`` (and sometimes a second variable after it), with an
    entry key sometimes and a confirm key sometimes."""
    steps: list[dict[str, Any]] = []
    if rng.random() < 0.5:
        steps.append({"actions": [pool.new_action()]})
    steps.append(_adjusting_step(rng, name, variables[name], pool))
    others = [v for v in variables if v.startswith("v") and v != name]
    if others and rng.random() < 0.3:
        if rng.random() < 0.5:
            steps.append({"actions": [pool.new_action()]})
        second = rng.choice(others)
        steps.append(_adjusting_step(rng, second, variables[second], pool))
    if rng.random() < 0.2:
        steps.append({"actions": [pool.new_action()]})
    return steps


def random_goal(rng: random.Random, model: ApplianceModel) -> dict[str, Any]:
    """A goal over one to three variables: values drawn from their domains, or (half the
    time) read off a state reached by a random walk, so that it is usually reachable."""
    names = rng.sample(list(model.variables), rng.randint(1, min(3, len(model.variables))))
    if rng.random() < 0.5:
        from apbot.plan.bfs import random_walk
        from apbot.sim.compiled import compiled_model

        compiled = compiled_model(model)
        state = random_walk(compiled, rng, rng.randint(3, 30))
        goal = {n: compiled.value(state, n) for n in names}
        if all(v is not None for v in goal.values()):
            return goal
    names.sort(key=lambda n: model.variables[n].depends_on is not None)  # parents first
    goal: dict[str, Any] = {}
    for name in names:
        var = model.variables[name]
        if var.depends_on is not None:
            parent = var.depends_on
            parent_domain = build_domain(model.variables[parent])
            options = [v for v in parent_domain.values if v in (var.cases or {})]
            chosen = goal.get(parent) or rng.choice(options)
            if chosen not in (var.cases or {}):
                continue
            if parent in goal or rng.random() < 0.5:  # else: any programme offering it will do
                goal.setdefault(parent, chosen)
            domain = build_domain(var, (var.cases or {})[chosen])
        else:
            domain = build_domain(var)
        goal[name] = domain.values[rng.randrange(len(domain))]
    return goal
