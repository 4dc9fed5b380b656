"""Fault injection: deterministic, coherent across rates, restricted to chosen kinds, and every
fault changes what the appliance does."""

from __future__ import annotations

import random

import pytest

from apbot.bench.faults import (
    FAULT_KINDS,
    SITE_KINDS,
    VARIABLE_KINDS,
    Fault,
    describe,
    fault_kind,
    fault_sites,
    first_valid,
    inject_faults,
)
from apbot.bench.faults.common import protected
from apbot.bench.faults.evidence import first_difference
from apbot.bench.suite import Suite, load_suite
from apbot.model.schema import ApplianceModel
from apbot.sim.compiled import compiled_model

RATES = (0.2, 0.5)
SEEDS = ("0", "1", 7)
HITS_PER_KIND = 2  # single faults per kind checked against the truth, first in suite order
EVIDENCE_STATES = 16_000  # joint states first_difference may explore for one of them

Sweep = dict[tuple[str, float], tuple[ApplianceModel, list[Fault]]]


@pytest.fixture(scope="module")
def suite() -> Suite:
    return load_suite("bundled")


@pytest.fixture(scope="module")
def sample(suite: Suite) -> list[str]:
    """Every fifth bundled appliance, from the second: one of each category (a full sweep
    takes minutes of model checking)."""
    return [appliance.id for appliance in suite.appliances[1::5]]


@pytest.fixture(scope="module")
def sweep(suite: Suite, sample: list[str]) -> Sweep:
    """The sample at every rate; the seed cycles over the models (seeds matter per model)."""
    results: Sweep = {}
    for i, name in enumerate(sample):
        for rate in RATES:
            results[name, rate] = inject_faults(suite.get(name).model, rate, SEEDS[i % 3])
    return results


def test_lower_rates_give_a_subset_of_the_faults(sweep: Sweep, sample: list[str]) -> None:
    grew = False
    for name in sample:
        low, high = (set(sweep[name, rate][1]) for rate in RATES)
        assert low <= high, name
        grew |= len(high) > len(low)
    assert grew


def test_each_kind_applies_on_the_suite_and_every_fault_changes_behaviour(suite: Suite) -> None:
    """For every kind, its first single faults in suite order (on the true model, one site at
    a time) each make some sequence of presses show, accept or set something else."""
    for kind in FAULT_KINDS:
        hits: list[Fault] = []
        for appliance in suite.appliances:
            for section, site in fault_sites(appliance.model):
                table = SITE_KINDS[section]
                if kind not in table or len(hits) >= HITS_PER_KIND:
                    continue
                rng = random.Random(f"test|{appliance.id}|{site}|{kind}")
                found = first_valid(table[kind](appliance.model, site, rng))
                if found is None:
                    continue
                faulty, fault = found
                # models with hold-to-scroll keys and per-mode memory branch more: a fault seven
                # presses deep (air_conditioner_1's FAN mode) needs more than the default budget
                found_at = first_difference(appliance.model, faulty, max_states=EVIDENCE_STATES)
                assert found_at is not None, str(fault)
                hits.append(fault)
        assert len(hits) == HITS_PER_KIND, kind


def test_faults_keep_initial_values_and_leave_power_locks_and_run_state_alone(
    sweep: Sweep, sample: list[str], suite: Suite
) -> None:
    for name in sample:
        truth = suite.get(name).model
        model, faults = sweep[name, RATES[-1]]
        assert faults, name
        before = compiled_model(truth).assignment(compiled_model(truth).initial_state())
        after = compiled_model(model).assignment(compiled_model(model).initial_state())
        assert {k: v for k, v in after.items() if k in before} == {
            k: v for k, v in before.items() if k in after
        }, name
        for variable, spec in truth.variables.items():
            if protected(variable):  # its domain and keys; a missing variable leaves its show
                kept = model.variables[variable].model_dump(exclude={"show"})
                assert kept == spec.model_dump(exclude={"show"}), (name, variable)
        targets = {f.target for f in faults if f.kind in VARIABLE_KINDS}
        assert not any(protected(t) for t in targets), name


def test_rate_zero_returns_the_model_unchanged(suite: Suite) -> None:
    for appliance in suite.appliances:
        model, faults = inject_faults(appliance.model, 0.0, "0")
        assert faults == []
        assert model.model_dump() == appliance.model.model_dump()


def test_same_seed_same_faults_and_seeds_differ(suite: Suite) -> None:
    outcomes = []
    for name in ["kettle_3", "washing_machine_2"]:
        truth = suite.get(name).model
        first, again = inject_faults(truth, 0.5, "run/3"), inject_faults(truth, 0.5, "run/3")
        assert first[1] == again[1]
        assert first[0].model_dump() == again[0].model_dump()
        outcomes.append(first[1] != inject_faults(truth, 0.5, "run/4")[1])
    assert any(outcomes)


def test_kinds_restrict_the_injection_to_those_kinds(suite: Suite) -> None:
    truth = suite.get("bread_maker_4").model
    everything = inject_faults(truth, 1.0, "k")[1]
    assert inject_faults(truth, 1.0, "k", kinds=FAULT_KINDS)[1] == everything
    chosen = {"guard", "display", "side_effect"}
    faults = inject_faults(truth, 1.0, "k", kinds=chosen)[1]
    assert faults and {f.kind for f in faults} <= chosen
    assert {f.kind for f in everything} - chosen  # the restriction removed something
    assert all(f.kind == "guard" for f in inject_faults(truth, 1.0, "k", kinds="guard")[1])


@pytest.mark.parametrize(
    ("kinds", "message"),
    [(["guard", "gaurd"], "unknown fault kind.*gaurd"), ([], "at least one fault kind")],
)
def test_unknown_or_no_kinds_are_refused(suite: Suite, kinds: list[str], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        inject_faults(suite.get("kettle_1").model, 0.3, 0, kinds=kinds)


def test_a_rate_outside_zero_to_one_is_refused(suite: Suite) -> None:
    with pytest.raises(ValueError, match=r"outside 0\.\.1"):
        inject_faults(suite.get("kettle_1").model, 1.5, 0)


def test_describe_gives_one_line_per_fault_and_the_kind_reads_back() -> None:
    faults = [
        Fault("wrap", "delay", "stops at its ends instead of wrapping"),
        Fault("missing_step", "set_delay", "step 1 of 2 (press_timer) is missing"),
    ]
    assert describe([]) == "no faults"
    text = describe(faults)
    assert text.splitlines()[0] == "2 faults:"
    assert "wrap delay: stops at its ends" in text.splitlines()[1]
    assert str(faults[1]) == "missing_step set_delay: step 1 of 2 (press_timer) is missing"
    assert [fault_kind(str(f)) for f in faults] == ["wrap", "missing_step"]
