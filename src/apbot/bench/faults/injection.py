"""Where faults can go (the sites), which kinds each site takes, and the seeded injection."""

from __future__ import annotations

import random
from collections.abc import Callable

from apbot.bench.faults.common import Candidates, Fault, directional, protected, valid
from apbot.bench.faults.procedures import missing_step
from apbot.bench.faults.values import (
    effect_direction,
    extra_value,
    missing_value,
    range_end,
    step_size,
    value_order,
    wrap,
)
from apbot.model.schema import ApplianceModel
from apbot.sim.compiled import default_effect

Kind = Callable[[ApplianceModel, str, random.Random], Candidates]
VARIABLE_KINDS: dict[str, Kind] = {
    "step_size": step_size,
    "range_end": range_end,
    "missing_value": missing_value,
    "extra_value": extra_value,
    "value_order": value_order,
    "wrap": wrap,
    "effect_direction": effect_direction,
}
FEATURE_KINDS: dict[str, Kind] = {"missing_step": missing_step}
FAULT_KINDS: tuple[str, ...] = (*VARIABLE_KINDS, *FEATURE_KINDS)
MAX_TRIES_PER_KIND = 6  # candidates tried before a kind counts as not applicable here


def fault_sites(model: ApplianceModel) -> list[tuple[str, str]]:
    """The places a fault can hit, in a fixed order: ``("variables", name)`` for each adjustable
    variable (stepped, added to or typed by some step), then ``("features", name)`` for each
    feature with two or more steps."""
    adjusted: set[str] = set()
    for steps in model.features.values():
        for step in steps:
            if step.variable is not None and any(
                directional(e) or e == "digit"
                for e in (default_effect(step, a, model) for a in step.actions)
            ):
                adjusted.add(step.variable)
    variables = [("variables", n) for n in model.variables if n in adjusted and not protected(n)]
    features = [("features", n) for n, steps in model.features.items() if len(steps) >= 2]
    return variables + features


def inject_faults(
    model: ApplianceModel, rate: float, seed: str | int
) -> tuple[ApplianceModel, list[Fault]]:
    """A valid faulty copy of ``model`` and the faults in it (see the package doc for ``rate``).

    The same (model, rate, seed) always gives the same faults; string seeds are deterministic
    across processes.
    """
    if not 0.0 <= rate <= 1.0:
        raise ValueError(f"fault rate {rate} is outside 0..1")
    current, faults = model, []
    for section, name in fault_sites(model):
        base = f"{seed}|{model.appliance.id}|{section}.{name}"
        site_rng = random.Random(base)
        if site_rng.random() >= rate:
            continue
        kinds = VARIABLE_KINDS if section == "variables" else FEATURE_KINDS
        for kind in site_rng.sample(list(kinds), len(kinds)):
            found = first_valid(kinds[kind](current, name, random.Random(f"{base}|{kind}")))
            if found is not None:
                current = found[0]
                faults.append(found[1])
                break
    return current, faults


def first_valid(candidates: Candidates) -> tuple[ApplianceModel, Fault] | None:
    """The first candidate (of at most ``MAX_TRIES_PER_KIND``) that is a valid model."""
    for _, (data, fault) in zip(range(MAX_TRIES_PER_KIND), candidates, strict=False):
        faulty = valid(data)
        if faulty is not None:
            return faulty, fault
    return None
