"""The paper's coverage and duplicate-sequence checks, and guards, controls and cycles."""

from __future__ import annotations

import itertools
from collections import Counter
from collections.abc import Iterator

from apbot.model.checks.common import unknown_name
from apbot.model.checks.steps import condition_problems
from apbot.model.domain import (
    ValueProblem,
    build_domain,
    normalise,
)
from apbot.model.effects import (
    condition_values,
    value_index,
)
from apbot.model.problems import PathPart, Problem
from apbot.model.schema import (
    AnywhereStep,
    ApplianceModel,
    Step,
)
from apbot.model.values import preview


def check_coverage(model: ApplianceModel) -> Iterator[Problem]:
    used_actions = {a for steps in model.features.values() for s in steps for a in s.actions}
    used_actions |= {a for entry in model.anywhere for a in entry.actions}
    used_actions |= {n for n, a in model.actions.items() if a.skill == "wait"}  # see timeouts
    for name in model.actions:
        if name not in used_actions:
            yield Problem(
                ("actions", name),
                f"action {name!r} appears in no feature; add it "
                "to the step it belongs to or remove it",
                "action-coverage",
            )
    changed = {s.variable for steps in model.features.values() for s in steps if s.variable}
    changed |= {v for steps in model.features.values() for s in steps for v in [*s.set, *s.reset]}
    changed |= {v for e in model.anywhere for v in [e.variable, *e.set, *e.reset] if v}
    changed |= {v for cycle in model.cycles for v in [*cycle.set, *cycle.reset]}
    for name in model.variables:
        if name not in changed:
            yield Problem(
                ("variables", name),
                f"no feature changes {name!r}; name it as the "
                "`variable` of the step that adjusts it",
                "variable-coverage",
            )


def check_duplicates(model: ApplianceModel) -> Iterator[Problem]:
    signatures: dict[str, str] = {}
    for feature, steps in model.features.items():
        signature = repr([s.model_dump() for s in steps])
        if signature in signatures:
            yield Problem(
                ("features", feature),
                f"same steps as feature {signatures[signature]!r}; keep one",
                "duplicate-sequence",
            )
        signatures.setdefault(signature, feature)
        for s, step in enumerate(steps):
            repeated = sorted(a for a, n in Counter(step.actions).items() if n > 1)
            if repeated:
                yield Problem(
                    ("features", feature, s, "actions"),
                    f"{repeated[0]!r} is listed twice in one step",
                    "duplicate-sequence",
                )
        for s, (a, b) in enumerate(itertools.pairwise(steps)):
            if a.variable and a.variable == b.variable and set(a.actions) & set(b.actions):
                yield Problem(
                    ("features", feature, s + 1),
                    f"steps {s} and {s + 1} adjust {a.variable!r} with the same "
                    "actions; merge them into one step",
                    "duplicate-sequence",
                    severity="warning",
                )
    claimed: dict[str, str] = {}
    for feature, steps in model.features.items():
        if not steps:
            continue
        first = [a for a in steps[0].actions if a in model.actions]
        if first and all(a in claimed for a in first):
            owners = sorted({claimed[a] for a in first})
            yield Problem(
                ("features", feature, 0, "actions"),
                f"feature {feature!r} can never start: every action of its first step "
                f"already starts {owners}; give it a distinct first action or merge "
                "the features",
                "duplicate-sequence",
            )
        for action in first:
            claimed.setdefault(action, feature)


def check_guards(model: ApplianceModel) -> Iterator[Problem]:
    for g, guard in enumerate(model.guards):
        for name, wanted in guard.when.items():
            var = model.variables[name]
            if var.depends_on is not None:
                yield Problem(
                    ("guards", g, "when", name),
                    "guard conditions use independent variables (power, child lock, running)",
                    "guard",
                )
                continue
            domain = build_domain(var)
            for value in condition_values(wanted):
                if value_index(domain, value) is None:
                    yield Problem(
                        ("guards", g, "when", name),
                        f"{value!r} is not a value of {name!r} ({preview(domain.values)})",
                        "guard",
                    )
        allowed = set(guard.only)
        everywhere: list[Step | AnywhereStep] = [s for f in model.features.values() for s in f]
        releasing = [
            s
            for s in [*everywhere, *model.anywhere]
            if any(a in allowed for a in s.actions)
            and (s.variable in guard.when or any(v in guard.when for v in [*s.set, *s.reset]))
        ]
        if not releasing:
            yield Problem(
                ("guards", g, "only"),
                "no allowed action changes "
                f"{sorted(guard.when)}, so once the guard holds nothing can lift it; "
                "allow the action that releases it",
                "guard",
            )


CYCLE_UNITS = {"s": 1, "sec": 1, "min": 60, "h": 3600}  # a numeric cycle length's unit


def check_cycles(model: ApplianceModel) -> Iterator[Problem]:
    """A cycle's conditions, its length variable and its end's side effects make sense."""
    variables = list(model.variables)
    for c, cycle in enumerate(model.cycles):
        path: tuple[PathPart, ...] = ("cycles", c)
        yield from condition_problems(model, (*path, "when"), cycle.when)
        lasts = model.variables.get(cycle.lasts)
        if lasts is None:
            yield Problem(
                (*path, "lasts"), unknown_name("variable", cycle.lasts, variables), "reference"
            )
        elif lasts.depends_on is not None or not (
            lasts.type == "time" or (lasts.type == "numeric" and lasts.unit in CYCLE_UNITS)
        ):
            yield Problem(
                (*path, "lasts"),
                f"{cycle.lasts!r} cannot say how long the cycle lasts: give an independent "
                "time variable, or a numeric one in s, min or h",
                "cycle",
            )
        for target, value in cycle.set.items():
            target_var = model.variables.get(target)
            if target_var is None:
                yield Problem(
                    (*path, "set", target), unknown_name("variable", target, variables), "reference"
                )
                continue
            try:
                normalise(target_var, value)
            except ValueProblem as exc:
                yield Problem((*path, "set", target), str(exc), "cycle")
        for target in cycle.reset:
            if target not in model.variables:
                yield Problem(
                    (*path, "reset"), unknown_name("variable", target, variables), "reference"
                )
        if not cycle.set and not cycle.reset:
            yield Problem(path, "a cycle's end changes nothing; give `set` or `reset`", "cycle")


def check_controls(model: ApplianceModel) -> Iterator[Problem]:
    used = {cid for action in model.actions.values() for cid in action.control_ids}
    for i, control in enumerate(model.controls):
        if control.box is not None:
            x0, y0, x1, y1 = control.box
            if x1 <= x0 or y1 <= y0:
                yield Problem(
                    ("controls", i, "box"),
                    f"box {list(control.box)} is empty; write "
                    "[left, top, right, bottom] with right > left and bottom > top",
                    "control",
                )
        if control.id not in used:
            yield Problem(
                ("controls", i),
                f"control {control.id!r} is used by no action",
                "control",
                severity="warning",
            )
