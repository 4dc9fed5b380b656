"""The checks that run the model: a guard that some reachable state holds for good is an error
naming the guard and how it got stuck; a search cut short never claims one."""

from __future__ import annotations

import random

import pytest

from apbot.examples import example_names, load_example
from apbot.sim.checks import check_model, guard_problems
from apbot.testing.generate import random_model
from tests.helpers import model_from

LOCK = """
controls: [{id: b1, label: A}, {id: b2, label: LOCK}]
variables:
  mode: {type: discrete, values: [a, b, c]}
  lock: {type: discrete, values: ["off", "on"]}
actions:
  press_a: {control: b1}
  hold_lock: {control: b2, skill: hold, seconds: 3}
features:
  mode: [{actions: [press_a], variable: mode, effect: next}]
  lock: [{actions: [hold_lock], variable: lock, effect: RELEASE}]
guards:
  - {name: child lock, when: {lock: "on"}, only: [hold_lock], display: LOCKED}
"""


def test_a_lock_whose_release_locks_again_is_an_error() -> None:
    model = model_from(LOCK.replace("RELEASE", '{to: "on"}'))
    [problem] = [p for p in check_model(model) if p.severity == "error"]
    assert (problem.check, problem.where) == ("guard", "guards[0]")
    assert problem.message.startswith(
        "guard 'child lock' holds for good: after hold_lock (lock is on) no sequence of "
        "actions lifts it (allowed: hold_lock;"
    )


def test_a_lock_that_releases_is_clean() -> None:
    assert guard_problems(model_from(LOCK.replace("RELEASE", "toggle"))) == []


def test_a_release_behind_a_step_the_guard_refuses_is_caught() -> None:
    # the release key is allowed, but only reached through press_a, which the lock refuses
    text = LOCK.replace(
        "lock: [{actions: [hold_lock], variable: lock, effect: RELEASE}]",
        "lock: [{actions: [press_a]}, {actions: [hold_lock], variable: lock, effect: toggle}]\n"
        '  lock_on: [{actions: [hold_lock], variable: lock, effect: {to: "on"}}]',
    ).replace("mode: [{actions: [press_a], variable: mode, effect: next}]", "")
    text = text.replace("mode: {type: discrete, values: [a, b, c]}\n", "")
    problems = guard_problems(model_from(text, check=False))
    assert [p.where for p in problems] == ["guards[0]"]


def test_a_search_cut_short_claims_nothing() -> None:
    model = model_from(LOCK.replace("RELEASE", '{to: "on"}'))
    assert guard_problems(model, max_states=1) == []  # the locked state was never expanded


@pytest.mark.parametrize("name", example_names())
def test_examples_pass(name: str) -> None:
    assert guard_problems(load_example(name)) == []


def test_generated_models_are_checked_without_error_from_the_search() -> None:
    # generated guards always allow their own release: none may be reported stuck
    for seed in range(40):
        model = random_model(random.Random(seed), max_states=5_000)
        assert guard_problems(model) == [], seed
