"""Helpers for tests: small models written inline."""

from __future__ import annotations

import textwrap
from importlib.resources import files
from typing import Any

from apbot.agent.environment import FeedbackMode, SimulatorEnvironment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel


def model_from(yaml_text: str, check: bool = True) -> ApplianceModel:
    """A model from an indented YAML snippet (the appliance header is added if missing)."""
    text = textwrap.dedent(yaml_text)
    if "appliance:" not in text:
        text = "appliance: {id: test_unit, category: test}\n" + text
    return loads_model(text, check=check)


def suite_model(appliance: str, *replacements: tuple[str, str]) -> ApplianceModel:
    """A bundled appliance's true model with each ``(old, new)`` text replaced once: a belief
    that is wrong in exactly the way a test describes."""
    text = (files("apbot") / f"data/suite/{appliance}/model.yaml").read_text()
    for old, new in replacements:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    return loads_model(text)


def run_checked(
    truth: ApplianceModel,
    belief: ApplianceModel,
    goal: dict[str, Any],
    feedback: FeedbackMode = "display",
) -> tuple[Episode, bool]:
    """Run ``apbot`` from ``belief`` on a simulator of ``truth``; the episode and whether the
    goal was really reached. Fails the test on any false claim of success."""
    env = SimulatorEnvironment(truth, feedback)
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    reached = env.simulator.satisfies(parse_goal(truth, goal))
    assert not (episode.claimed_success and not reached), "a false claim of success"
    return episode, reached
