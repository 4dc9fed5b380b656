"""What a suite contains: per category counts and which model features the appliances use."""

from __future__ import annotations

from typing import Any

from apbot.bench.suite import CATEGORIES, Suite, load_suite
from apbot.model.schema import ApplianceModel
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


# Procedure-structure constructs of the format (docs/model-format.md, "The feature pointer"):
# name -> what the row says in `apbot suite stats`.
CONSTRUCTS = {
    "optional_steps": "optional steps (optional)",
    "anywhere_keys": "keys acting from anywhere (anywhere)",
    "leave_keys": "keys that leave the procedure (leave)",
    "early_release_enters": "holds entering when released early (too_short)",
    "timeouts": "step timeouts let expire by a wait (timeout, wait)",
    "keypad_other_keys_clear": "keypads whose other keys clear (other_keys)",
    "keypad_shows_typed": "keypads showing digits as typed (shows: typed)",
}


def appliance_constructs(model: ApplianceModel) -> dict[str, bool]:
    """Which procedure-structure constructs (:data:`CONSTRUCTS`) an appliance uses."""
    steps = [step for steps in model.features.values() for step in steps]
    entries = [e for v in model.variables.values() if (e := getattr(v, "entry", None)) is not None]
    return {
        "optional_steps": any(step.optional for step in steps),
        "anywhere_keys": bool(model.anywhere),
        "leave_keys": any(entry.leave for entry in model.anywhere),
        "early_release_enters": any(a.too_short == "enters" for a in model.actions.values()),
        "timeouts": any(step.timeout is not None for step in steps),
        "keypad_other_keys_clear": any(e.other_keys == "clear" for e in entries),
        "keypad_shows_typed": any(e.shows == "typed" for e in entries),
    }


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
    constructs = dict.fromkeys(CONSTRUCTS, 0)
    for appliance in suite.appliances:
        for key, used in appliance_constructs(appliance.model).items():
            constructs[key] += used
    return {
        "appliances": len(suite.appliances),
        "tasks": len(suite.tasks),
        "categories": categories,
        "features": totals,
        "constructs": constructs,
    }
