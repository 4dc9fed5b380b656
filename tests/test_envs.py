"""Every bundled appliance is a working Gymnasium environment."""

from __future__ import annotations

import warnings

import gymnasium as gym
import pytest
from gymnasium.utils.env_checker import check_env

from apbot.envs import ENV_IDS
from apbot.plan.plan import plan


def test_every_bundled_appliance_is_registered() -> None:
    from apbot.bench.suite import load_suite

    assert {f"apbot/{a.id}-v0" for a in load_suite().appliances} == set(ENV_IDS)


def test_the_gymnasium_checker_passes_on_every_id() -> None:
    for env_id in ENV_IDS:
        env = gym.make(env_id)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            check_env(env.unwrapped, skip_render_check=False)
        env.close()


@pytest.mark.parametrize("env_id", ENV_IDS[:: max(1, len(ENV_IDS) // 9)])
def test_oracle_actions_terminate_within_the_budget(env_id: str) -> None:
    env = gym.make(env_id)
    _display, info = env.reset(seed=3)
    appliance = env.unwrapped.appliance
    task = next(t for t in appliance.tasks if t.id == info["task"])
    found = plan(appliance.model, None, task.goal)
    terminated = truncated = False
    steps = 0
    for action in found.actions:
        _, reward, terminated, truncated, info = env.step(info["actions"].index(action.name))
        steps += 1
        assert info["accepted"], info["reason"]
    assert terminated and reward == 1.0 and not truncated
    assert steps == task.optimal_steps <= env.spec.max_episode_steps


def test_budget_truncates() -> None:
    env = gym.make(ENV_IDS[0])
    env.reset(seed=0)
    truncated = False
    for _ in range(env.spec.max_episode_steps):
        *_, terminated, truncated, _info = env.step(0)
        if terminated:
            break
    assert truncated or terminated
