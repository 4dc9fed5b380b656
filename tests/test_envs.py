"""Every bundled appliance is a working Gymnasium environment."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

from apbot.envs import ENV_IDS, ApplianceEnv
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


def test_the_step_budget_leaves_room_and_the_env_leaves_truncation_to_the_wrapper() -> None:
    """Ours: each id's budget is at least four times its longest optimal plan (and 50), and the
    env itself never truncates (Gymnasium's TimeLimit, tested by Gymnasium, counts the steps)."""
    from apbot.bench.suite import load_suite

    for appliance in load_suite().appliances:
        budget = gym.spec(f"apbot/{appliance.id}-v0").max_episode_steps
        worst = max(t.optimal_steps or 0 for t in appliance.tasks)
        assert budget is not None and budget >= max(50, 4 * worst), appliance.id
    env = ApplianceEnv("kettle_1")
    env.reset(seed=0, options={"task": "t01"})
    for _ in range(3 * (gym.spec(ENV_IDS[0]).max_episode_steps or 0)):
        *_, terminated, truncated, _info = env.step(0)
        assert not truncated
        if terminated:
            env.reset(seed=0, options={"task": "t01"})


def test_actions_outside_the_space_are_refused_not_wrapped_or_truncated() -> None:
    env = ApplianceEnv("kettle_1")
    env.reset(seed=0, options={"task": 0})
    count = env.action_space.n
    with pytest.raises(ValueError, match=f"action -1 is out of range: kettle_1 has {count}"):
        env.step(-1)  # used to press the last action
    with pytest.raises(ValueError, match=f"action {count} is out of range"):
        env.step(count)
    for bad in (1.5, True, "0", None):
        with pytest.raises(TypeError, match="an action is an integer index"):
            env.step(bad)  # type: ignore[arg-type]
    assert env.step(np.int64(1))[4]["accepted"] == ApplianceEnv("kettle_1").step(1)[4]["accepted"]


def test_reset_options_are_checked() -> None:
    env = ApplianceEnv("kettle_1")
    with pytest.raises(ValueError, match="task index 10 is out of range: kettle_1 has 10 tasks"):
        env.reset(options={"task": 10})
    with pytest.raises(ValueError, match="task index -1 is out of range"):
        env.reset(options={"task": -1})
    with pytest.raises(ValueError, match=r"unknown reset option\(s\) \['taks'\]"):
        env.reset(options={"taks": "t03"})
    assert env.reset(options={"task": 2})[1]["task"] == "t03"


def test_the_env_reveals_what_the_benchmark_environment_reveals() -> None:
    """One rule for every adapter: the panel's text, refusals only where they are signalled,
    never the simulator's reason (which names true values)."""
    env = ApplianceEnv("washing_machine_1")
    env.reset(seed=0)
    names = env.action_names
    off = env.step(names.index("press_start"))[4]  # switched off: a dark panel ignores it
    assert off["accepted"] and off["reason"] == ""
