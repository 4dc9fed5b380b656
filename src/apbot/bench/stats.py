"""What a suite contains: per category counts and which model features the appliances use."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from apbot.bench.suite import CATEGORIES, Suite, load_suite
from apbot.model.schema import ApplianceModel, Conditional, OtherThan, Skip
from apbot.sim.compiled import compiled_model

FEATURES = (
    "keypad",
    "dial",
    "hold",
    "two_control_hold",
    "dependent_settings",
    "piecewise",
    "time_variables",
    "guards",
)


def appliance_features(model: ApplianceModel) -> dict[str, bool]:
    """Which parts of the model format an appliance uses.

    ``guards`` counts child-lock and running guards: guards that do not already hold in the
    initial state (a power-off guard does; a lock or a running cycle is switched on later).
    """
    ranges: list[Any] = []
    for var in model.variables.values():
        specs = [var, *list((var.cases or {}).values())]
        ranges.extend(getattr(s, "ranges", None) or [] for s in specs if not isinstance(s, list))
    compiled = compiled_model(model)
    start = compiled.initial_state()
    later_guards = [
        g for g in compiled.guards if not all(start.values[v] in ok for v, ok in g.conditions)
    ]
    return {
        "keypad": any(c.kind == "key" for c in model.controls),
        "dial": any(c.kind in ("dial", "knob") for c in model.controls),
        "hold": any(a.skill == "hold" for a in model.actions.values()),
        "two_control_hold": any(a.controls for a in model.actions.values()),
        "dependent_settings": any(v.depends_on for v in model.variables.values()),
        "piecewise": any(len(r) > 1 for r in ranges),
        "time_variables": any(v.type == "time" for v in model.variables.values()),
        "guards": bool(later_guards),
    }


def _steps(model: ApplianceModel) -> list[Any]:
    return [step for steps in model.features.values() for step in steps]


def _entries(model: ApplianceModel) -> list[Any]:
    return [e for v in model.variables.values() if (e := getattr(v, "entry", None)) is not None]


def _unreachable_values(model: ApplianceModel) -> bool:
    return any(v.unreachable for v in model.variables.values())


def _effects(model: ApplianceModel) -> list[Any]:
    """Every effect a step writes, conditionals opened up (theirs and their branches)."""
    found: list[Any] = []
    for steps in model.features.values():
        for step in steps:
            pending = list(step.effect.values()) if isinstance(step.effect, dict) else [step.effect]
            while pending:
                effect = pending.pop()
                found.append(effect)
                if isinstance(effect, Conditional):
                    pending += [effect.then, effect.otherwise]
    return found


def _skip(model: ApplianceModel) -> bool:
    return any(isinstance(e, Skip) for e in _effects(model))


def _conditional(model: ApplianceModel) -> bool:
    return any(isinstance(e, Conditional) for e in _effects(model))


def _other_than(model: ApplianceModel) -> bool:
    return any(isinstance(w, OtherThan) for g in model.guards for w in g.when.values()) or any(
        isinstance(w, OtherThan)
        for e in _effects(model)
        if isinstance(e, Conditional)
        for w in e.when.values()
    )


# Constructs of the format added for behaviours real manuals describe (docs/model-format.md):
# one row each in ``apbot suite stats``, counting the appliances whose model uses it.
CONSTRUCTS: dict[str, Callable[[ApplianceModel], bool]] = {
    "optional steps (optional)": lambda m: any(s.optional for s in _steps(m)),
    "keys acting from anywhere (anywhere)": lambda m: bool(m.anywhere),
    "keys that leave the procedure (leave)": lambda m: any(e.leave for e in m.anywhere),
    "holds entering when released early (too_short)": lambda m: any(
        a.too_short == "enters" for a in m.actions.values()
    ),
    "step timeouts let expire by a wait (timeout, wait)": lambda m: any(
        s.timeout is not None for s in _steps(m)
    ),
    "keypads whose other keys clear (other_keys)": lambda m: any(
        e.other_keys == "clear" for e in _entries(m)
    ),
    "keypads showing digits as typed (shows: typed)": lambda m: any(
        e.shows == "typed" for e in _entries(m)
    ),
    "values declared unreachable": _unreachable_values,
    "settings remembered per programme or zone": lambda m: any(
        v.remember for v in m.variables.values()
    ),
    "skip effects (hold to scroll)": _skip,
    "cycles that end by themselves": lambda m: bool(m.cycles),
    "conditional effects": _conditional,
    "other_than conditions (one dial position)": _other_than,
}


# the procedure-structure ones, listed first above (docs/model-format.md, "The feature pointer")
PROCEDURE_CONSTRUCTS = tuple(CONSTRUCTS)[:7]


def appliance_constructs(model: ApplianceModel) -> dict[str, bool]:
    """Which constructs of :data:`CONSTRUCTS` one model uses."""
    return {name: uses(model) for name, uses in CONSTRUCTS.items()}


def construct_counts(models: list[ApplianceModel]) -> dict[str, int]:
    """Per construct of :data:`CONSTRUCTS`, how many of ``models`` use it."""
    return {name: sum(uses(m) for m in models) for name, uses in CONSTRUCTS.items()}


def suite_statistics(suite: Suite | None = None) -> dict[str, Any]:
    """Counts for ``apbot suite stats`` (and its ``--json``)."""
    suite = suite or load_suite()
    categories: dict[str, dict[str, Any]] = {}
    totals = dict.fromkeys(FEATURES, 0)
    order = [c for c in CATEGORIES if any(a.category == c for a in suite.appliances)]
    order += sorted({a.category for a in suite.appliances} - set(order))
    for name in order:
        members = [a for a in suite.appliances if a.category == name]
        tasks = [t for a in members for t in a.tasks]
        features = dict.fromkeys(FEATURES, 0)
        for appliance in members:
            for key, used in appliance_features(appliance.model).items():
                features[key] += used
                totals[key] += used
        categories[name] = {
            "appliances": len(members),
            "tasks": len(tasks),
            "goal_vars_per_task": round(sum(len(t.goal) for t in tasks) / len(tasks), 2)
            if tasks
            else 0,
            "features": features,
        }
    return {
        "appliances": len(suite.appliances),
        "tasks": len(suite.tasks),
        "categories": categories,
        "features": totals,
        "constructs": construct_counts([a.model for a in suite.appliances]),
    }
