"""Fuzz the model loader: whatever the text, a model or a ModelError, quickly; never a crash.

A mutant that loads is then simulated and planned on: a model that passed every check must
run without an error the checks should have caught.
"""

from __future__ import annotations

import random

from hypothesis import event, given
from hypothesis import strategies as st

from apbot.bench.suite import bundled_suite_dir
from apbot.examples import example_dir
from apbot.model.domain import all_values
from apbot.model.goal import GoalError
from apbot.model.load import loads_model
from apbot.model.problems import ModelError
from apbot.model.schema import ApplianceModel
from apbot.plan.plan import Unreachable, plan
from apbot.sim.simulator import Simulator
from tests.fuzz import fuzz_settings, mutated_data_text, mutated_text, no_hang

MODEL_FILES = sorted(example_dir().glob("*.yaml")) + sorted(
    bundled_suite_dir().glob("*_1/model.yaml")
)
TEXTS = [path.read_text(encoding="utf-8") for path in MODEL_FILES]

yamlish = st.text(
    alphabet=st.sampled_from([*"{}[]:,-&*!|>'\"#?%@`~ \n\t.0123456789abcxyz_", "\x00", "é"]),
    max_size=200,
)


def load_or_explain(text: str) -> ApplianceModel | None:
    """The model, or None after a ModelError whose every problem renders as one line."""
    try:
        with no_hang("loading a model"):
            model = loads_model(text, source="fuzz.yaml")
    except ModelError as exc:
        assert exc.problems, "a ModelError without problems"
        for problem in exc.problems:
            line = problem.render("fuzz.yaml")
            assert "\n" not in line and len(line) < 2_000, line
        event(f"refused: {exc.problems[0].check}")
        return None
    event("loaded")
    return model


def exercise(model: ApplianceModel, seed: int) -> None:
    """A checked model compiles, steps and plans without any unexpected exception."""
    rng = random.Random(seed)
    with no_hang("simulating and planning a checked model"):
        sim = Simulator(model)
        for _ in range(30):
            sim.step(rng.randrange(len(sim.actions)), rng.choice([None, 0.5, 3.0, 60.0]))
            sim.observe()
        name = rng.choice(list(model.variables))
        values = all_values(model.variables[name])
        goal = {name: values[rng.randrange(len(values))]}
        try:
            found = plan(model, None, goal, budget=3_000)
        except (Unreachable, GoalError):
            return
        sim.reset()
        for action in found.actions:
            assert sim.step(action.name, action.seconds).accepted
        assert sim.satisfies(found.goal)


@fuzz_settings(300)
@given(st.one_of(yamlish, st.text(max_size=200)))
def test_random_text_is_a_model_error_never_a_crash(text: str) -> None:
    assert load_or_explain(text) is None  # no random text is a whole model


@fuzz_settings(100)
@given(st.sampled_from(TEXTS).flatmap(mutated_text), st.integers(0, 2**16))
def test_textually_mutated_models_load_or_explain(text: str, seed: int) -> None:
    model = load_or_explain(text)
    if model is not None:
        exercise(model, seed)


@fuzz_settings(100)
@given(st.sampled_from(TEXTS).flatmap(mutated_data_text), st.integers(0, 2**16))
def test_structurally_mutated_models_load_or_explain(text: str, seed: int) -> None:
    model = load_or_explain(text)
    if model is not None:
        exercise(model, seed)
