"""apbot.operate: manual text, action names, a sentence and an environment, in one call."""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.bench.runner import cached_suite
from apbot.operate import OFFLINE_NOTE, operate, read_goal, read_model


def test_one_call_reads_the_manual_and_the_sentence_and_runs_the_loop() -> None:
    appliance = cached_suite("bundled").get("kettle_1")
    env = SimulatorEnvironment(appliance.model)
    done = operate(appliance.manual, env.actions, "Heat the water to 80 degrees.", env)
    assert done.model.actions.keys() == appliance.model.actions.keys()
    assert 80 in done.goal.values() and done.trace and done.notes == [OFFLINE_NOTE]
    assert done.outcome.startswith(("done", "failed"))
    assert done.episode.execution_steps == env.steps


def test_the_readings_are_available_on_their_own() -> None:
    appliance = cached_suite("bundled").get("bread_maker_1")
    reading = read_model(appliance.manual, list(appliance.model.actions))
    assert reading.model.variables and reading.report.notes
    goal = read_goal(appliance.model, "A French loaf, 750 g, dark crust", appliance.manual)
    assert goal == {"menu": "2", "loaf_size": 750, "crust": "dark"}


def test_an_instruction_the_model_cannot_satisfy_is_not_attempted() -> None:
    appliance = cached_suite("bundled").get("kettle_1")
    env = SimulatorEnvironment(appliance.model)
    done = operate(
        appliance.manual, env.actions, "Heat it to 120 degrees", env, model=appliance.model
    )
    assert not done.success and env.steps == 0
    assert done.goal_error.startswith("'120 degrees': ") and "not attempted" in done.outcome
    nothing = operate(appliance.manual, env.actions, "Hello there", env, model=appliance.model)
    assert nothing.goal_error and not nothing.trace
