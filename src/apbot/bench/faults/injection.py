"""Where faults can go (the sites), which kinds each site takes, and the seeded injection."""

from __future__ import annotations

import random
from collections.abc import Callable, Collection

from apbot.bench.faults.common import Candidates, Fault, protected, valid
from apbot.bench.faults.display import display, entry_format
from apbot.bench.faults.procedures import (
    merged_features,
    misplaced_action,
    missing_step,
    on_entry,
    side_effect,
)
from apbot.bench.faults.structure import guard, guard_names, missing_variable, spurious_variable
from apbot.bench.faults.values import (
    effect_direction,
    extra_value,
    missing_case,
    missing_value,
    range_end,
    step_size,
    value_order,
    wrap,
)
from apbot.model.schema import ApplianceModel

Kind = Callable[[ApplianceModel, str, random.Random], Candidates]
VARIABLE_KINDS: dict[str, Kind] = {
    "step_size": step_size,
    "range_end": range_end,
    "missing_value": missing_value,
    "extra_value": extra_value,
    "value_order": value_order,
    "wrap": wrap,
    "effect_direction": effect_direction,
    "missing_case": missing_case,
    "entry_format": entry_format,
    "display": display,
    "missing_variable": missing_variable,
}
FEATURE_KINDS: dict[str, Kind] = {
    "missing_step": missing_step,
    "on_entry": on_entry,
    "side_effect": side_effect,
    "misplaced_action": misplaced_action,
    "merged_features": merged_features,
    "spurious_variable": spurious_variable,
}
GUARD_KINDS: dict[str, Kind] = {"guard": guard}
SITE_KINDS: dict[str, dict[str, Kind]] = {
    "variables": VARIABLE_KINDS,
    "features": FEATURE_KINDS,
    "guards": GUARD_KINDS,
}
FAULT_KINDS: tuple[str, ...] = (*VARIABLE_KINDS, *FEATURE_KINDS, *GUARD_KINDS)
ORIGINAL_KINDS: tuple[str, ...] = (  # the eight kinds the first study injected
    "step_size",
    "range_end",
    "missing_value",
    "extra_value",
    "value_order",
    "wrap",
    "effect_direction",
    "missing_step",
)
MAX_TRIES_PER_KIND = 6  # candidates tried before a kind counts as not applicable here


def fault_sites(model: ApplianceModel) -> list[tuple[str, str]]:
    """The places a fault can hit, in a fixed order.

    ``("variables", name)`` for each setting a step adjusts (not power, locks or run state),
    then ``("features", name)`` for each procedure with two or more steps, one that adjusts a
    setting or one with side effects (a plain on/off key is not a site), then
    ``("guards", name)`` for each guard (:func:`~apbot.bench.faults.structure.guard_names`).
    """
    stepped = {s.variable for steps in model.features.values() for s in steps if s.variable}
    variables = [("variables", n) for n in model.variables if n in stepped and not protected(n)]
    features = [
        ("features", n)
        for n, steps in model.features.items()
        if len(steps) >= 2
        or any(s.set or s.reset or (s.variable and not protected(s.variable)) for s in steps)
    ]
    guards = [("guards", n) for n in guard_names(model)]
    return variables + features + guards


def _chosen_kinds(kinds: Collection[str] | None) -> frozenset[str]:
    if kinds is None:
        return frozenset(FAULT_KINDS)
    if isinstance(kinds, str):
        kinds = [kinds]
    unknown = [k for k in kinds if k not in FAULT_KINDS]
    if unknown:
        raise ValueError(
            f"unknown fault kind(s) {', '.join(unknown)}; known: {', '.join(FAULT_KINDS)}"
        )
    if not kinds:
        raise ValueError("give at least one fault kind (or None for every kind)")
    return frozenset(kinds)


def _present(model: ApplianceModel, section: str, name: str) -> bool:
    """Whether a site of the true model is still there (an earlier fault may have removed a
    variable, merged a feature away or dropped a guard)."""
    if section == "variables":
        return name in model.variables
    if section == "features":
        return name in model.features
    return name in guard_names(model)


def inject_faults(
    model: ApplianceModel,
    rate: float,
    seed: str | int,
    kinds: Collection[str] | None = None,
) -> tuple[ApplianceModel, list[Fault]]:
    """A valid faulty copy of ``model`` and the faults in it, in site order (see the package
    doc for ``rate``). ``kinds`` restricts the faults to those kinds (None: every kind).

    The same (model, rate, seed, kinds) always gives the same faults; string seeds are
    deterministic across processes. Raises ValueError for a rate outside 0..1 or an unknown
    kind.
    """
    if not 0.0 <= rate <= 1.0:
        raise ValueError(f"fault rate {rate} is outside 0..1")
    chosen = _chosen_kinds(kinds)
    drawn = []
    for position, (section, name) in enumerate(fault_sites(model)):
        base = f"{seed}|{model.appliance.id}|{section}.{name}"
        site_rng = random.Random(base)
        draw = site_rng.random()
        if draw < rate:
            drawn.append((draw, position, section, name, base, site_rng))
    drawn.sort(key=lambda site: (site[0], site[1]))  # a lower rate's sites are a prefix
    current, found = model, []
    for _, position, section, name, base, site_rng in drawn:
        if not _present(current, section, name):
            continue
        table = SITE_KINDS[section]
        for kind in site_rng.sample(list(table), len(table)):
            if kind not in chosen:
                continue
            hit = first_valid(table[kind](current, name, random.Random(f"{base}|{kind}")))
            if hit is not None:
                current = hit[0]
                found.append((position, hit[1]))
                break
    return current, [fault for _, fault in sorted(found, key=lambda item: item[0])]


def first_valid(candidates: Candidates) -> tuple[ApplianceModel, Fault] | None:
    """The first candidate (of at most ``MAX_TRIES_PER_KIND``) that is a valid model."""
    for _, (data, fault) in zip(range(MAX_TRIES_PER_KIND), candidates, strict=False):
        faulty = valid(data)
        if faulty is not None:
            return faulty, fault
    return None


def candidate_sites(
    model: ApplianceModel, rate: float, seed: str | int, kinds: Collection[str]
) -> list[tuple[str, str]]:
    """The sites drawn below ``rate`` where one of ``kinds`` offers a candidate on the true
    model, unchecked: a cheap test of whether :func:`inject_faults` with these kinds can fault
    the model at all (a study skips appliances it cannot hit). It checks no validity, so it
    may name a site the injection then leaves alone."""
    chosen = _chosen_kinds(kinds)
    found = []
    for section, name in fault_sites(model):
        base = f"{seed}|{model.appliance.id}|{section}.{name}"
        if random.Random(base).random() >= rate:
            continue
        table = SITE_KINDS[section]
        for kind in chosen & set(table):
            rng = random.Random(f"{base}|{kind}")
            if next(iter(table[kind](model, name, rng)), None) is not None:
                found.append((section, name))
                break
    return found
