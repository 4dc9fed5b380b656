"""Fault injection: valid, deterministic, coherent across rates, and each kind does what it says."""

from __future__ import annotations

import random

import pytest

from apbot.bench.faults import (
    FAULT_KINDS,
    Fault,
    describe,
    effect_direction,
    fault_sites,
    first_valid,
    inject_faults,
    missing_step,
    step_size,
)
from apbot.bench.suite import Suite, load_suite
from apbot.model.schema import ApplianceModel
from apbot.model.validate import check_model
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Simulator
from tests.helpers import model_from

RATES = (0.1, 0.3, 1.0)
SEEDS = ("0", "1", 7)

Sweep = dict[tuple[str, float], tuple[ApplianceModel, list[Fault]]]


@pytest.fixture(scope="module")
def suite() -> Suite:
    return load_suite("bundled")


@pytest.fixture(scope="module")
def sweep(suite: Suite) -> Sweep:
    """Every bundled model at every rate; the seed cycles over the models (seeds matter per
    model, and a full cross product would take minutes of model checking)."""
    results: Sweep = {}
    for i, appliance in enumerate(suite.appliances):
        seed = SEEDS[i % len(SEEDS)]
        for rate in RATES:
            results[appliance.id, rate] = inject_faults(appliance.model, rate, seed)
    return results


def _errors(model: ApplianceModel) -> list[str]:
    return [p.render() for p in check_model(model) if p.severity == "error"]


def test_every_faulty_model_passes_the_model_checks(sweep: Sweep) -> None:
    for (appliance, rate), (model, _) in sweep.items():
        assert _errors(model) == [], (appliance, rate)


def test_lower_rates_give_a_subset_of_the_faults(sweep: Sweep, suite: Suite) -> None:
    for appliance in suite.appliances:
        found = [set(sweep[appliance.id, rate][1]) for rate in RATES]
        assert found[0] <= found[1] <= found[2], appliance.id


def test_rate_one_faults_each_site_at_most_once_and_every_kind_occurs(
    sweep: Sweep, suite: Suite
) -> None:
    kinds = set()
    for appliance in suite.appliances:
        faults = sweep[appliance.id, 1.0][1]
        sites = {name for _, name in fault_sites(appliance.model)}
        targets = [(f.kind == "missing_step", f.target) for f in faults]
        assert len(targets) == len(set(targets)), appliance.id
        assert {f.target for f in faults} <= sites
        if sites:
            assert faults, appliance.id
        kinds |= {f.kind for f in faults}
    assert kinds == set(FAULT_KINDS)


def test_faults_keep_initial_values_and_leave_power_locks_and_run_state_alone(
    sweep: Sweep, suite: Suite
) -> None:
    for appliance in suite.appliances:
        model, faults = sweep[appliance.id, 1.0]
        truth, faulty = compiled_model(appliance.model), compiled_model(model)
        assert faulty.assignment(faulty.initial_state()) == truth.assignment(
            truth.initial_state()
        ), appliance.id
        for name, var in appliance.model.variables.items():
            if name in ("power", "running") or "lock" in name:
                assert model.variables[name] == var
                assert name not in {f.target for f in faults}


def test_rate_zero_returns_the_model_unchanged(suite: Suite) -> None:
    for appliance in suite.appliances:
        model, faults = inject_faults(appliance.model, 0.0, "0")
        assert faults == []
        assert model.model_dump() == appliance.model.model_dump()


def test_same_seed_same_faults_and_seeds_differ(suite: Suite) -> None:
    chosen = ["kettle_3", "washing_machine_2", "rice_cooker_1", "dehumidifier_5"]
    outcomes = []
    for name in chosen:
        truth = suite.get(name).model
        first, again = inject_faults(truth, 0.5, "run/3"), inject_faults(truth, 0.5, "run/3")
        assert first[1] == again[1]
        assert first[0].model_dump() == again[0].model_dump()
        outcomes.append(first[1] != inject_faults(truth, 0.5, "run/4")[1])
    assert any(outcomes)


def test_a_rate_outside_zero_to_one_is_refused(suite: Suite) -> None:
    with pytest.raises(ValueError, match=r"outside 0\.\.1"):
        inject_faults(suite.get("kettle_1").model, 1.5, 0)


def test_describe_gives_one_line_per_fault() -> None:
    faults = [
        Fault("wrap", "delay", "stops at its ends instead of wrapping"),
        Fault("missing_step", "set_delay", "step 1 of 2 (press_timer) is missing"),
    ]
    assert describe([]) == "no faults"
    text = describe(faults)
    assert text.splitlines()[0] == "2 faults:"
    assert "wrap delay: stops at its ends" in text.splitlines()[1]
    assert str(faults[1]) == "missing_step set_delay: step 1 of 2 (press_timer) is missing"


# --- what single kinds do, on a small timer ---------------------------------------------------

TIMER = """
controls:
  - {id: timer_button, label: TIMER}
  - {id: up_button, label: "▲"}
  - {id: down_button, label: "▼"}
variables:
  delay: {type: numeric, unit: h, ranges: [[0, 12, 2]], initial: 4}
actions:
  press_timer: {control: timer_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  set_delay:
    - {actions: [press_timer]}
    - actions: [press_up, press_down]
      variable: delay
      effect: {press_up: next, press_down: prev}
"""


def _first(candidates: object) -> tuple[ApplianceModel, Fault]:
    found = first_valid(candidates)  # type: ignore[arg-type]
    assert found is not None
    return found


def _delay_after(model: ApplianceModel, actions: list[str]) -> object:
    sim = Simulator(model)
    for action in actions:
        sim.step(action)
    return sim.compiled.value(sim.state, "delay")


def test_missing_entry_step_makes_the_belief_adjust_without_the_entry_key() -> None:
    truth = model_from(TIMER)
    assert _delay_after(truth, ["press_up"]) == 4  # ▲ does nothing before TIMER
    faulty, fault = _first(missing_step(truth, "set_delay", random.Random(0)))
    assert fault.kind == "missing_step" and "press_timer" in fault.detail
    assert _delay_after(faulty, ["press_up"]) == 6
    assert _delay_after(faulty, ["press_timer", "press_up"]) == 6  # TIMER kept, as a no-op


def test_effect_direction_makes_up_go_down() -> None:
    faulty, fault = _first(effect_direction(model_from(TIMER), "delay", random.Random(0)))
    assert "press_up next → prev" in fault.detail
    assert _delay_after(faulty, ["press_timer", "press_up"]) == 2


def test_step_size_keeps_the_range_aligned_and_the_initial_value() -> None:
    for seed in range(6):
        faulty, fault = _first(step_size(model_from(TIMER), "delay", random.Random(seed)))
        ((start, end, step),) = faulty.variables["delay"].ranges  # type: ignore[union-attr]
        assert step in (1, 4) and (end - start) % step == 0 and end <= 12
        assert f"step 2 h → {step} h" in fault.detail
        assert _delay_after(faulty, []) == 4
        assert _errors(faulty) == []
