"""Fuzz goals through the Python API: any value for any variable name is a normalised goal or
a GoalError / ValueProblem naming it; plan ends in a Plan, GoalError or Unreachable."""

from __future__ import annotations

import contextlib
from typing import Any

from hypothesis import event, given
from hypothesis import strategies as st

from apbot.bench.suite import load_suite
from apbot.examples import example_names, load_example
from apbot.model.domain import ValueProblem
from apbot.model.goal import GoalError, parse_goal
from apbot.model.schema import ApplianceModel
from apbot.plan.plan import Unreachable, plan
from apbot.sim.simulator import Simulator, UnknownVariable
from tests.fuzz import HOSTILE_TOKENS, fuzz_settings, json_values, no_hang

MODELS = [load_example(n) for n in example_names()] + [
    a.model for a in load_suite().appliances[::9]
]
WRITTEN = ["30 min", "2 h", "half an hour", "1:30", "00:99:00", "fifty percent", "On", "1e400"]
values = st.one_of(
    json_values,
    st.sampled_from(HOSTILE_TOKENS + WRITTEN),
    st.floats(),
    st.integers(),
    st.just("9" * 400),
)


@fuzz_settings(150)
@given(st.sampled_from(MODELS), st.data())
def test_any_goal_is_normalised_or_named_as_wrong(model: ApplianceModel, data: Any) -> None:
    names = [*model.variables, "nosuch"]
    goal = data.draw(st.dictionaries(st.sampled_from(names), values, max_size=3))
    with no_hang("a goal"):
        try:
            parse_goal(model, goal)
            event("valid goal")
        except GoalError as exc:
            assert all("\n" not in p.message and len(p.message) < 1_000 for p in exc.problems)
            event("GoalError")
        try:
            Simulator(model).satisfies(goal)
        except (ValueProblem, UnknownVariable):
            pass
        except TypeError as exc:  # an unhashable value: a list or a dict is not one value
            assert "a goal value is one value" in str(exc)
        with contextlib.suppress(GoalError, Unreachable):
            plan(model, None, goal, budget=2_000)
