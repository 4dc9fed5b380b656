"""The built-in methods: ApBot, its ablations, and the oracle."""

from __future__ import annotations

from apbot.agent.environment import Environment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.loop import AgentConfig, run_agent
from apbot.agent.registry import Method, RunFunction, register
from apbot.model.goal import GoalError, parse_goal
from apbot.plan.plan import Unreachable, plan


def run_oracle(context: TaskContext, env: Environment) -> Episode:
    """Plan once on the (true) model and press every action: the upper bound SPL measures by."""
    episode = context.episode()
    env.reset()
    try:
        goal = parse_goal(context.belief, context.goal)
        found = plan(context.belief, None, goal)
    except (GoalError, Unreachable) as exc:
        episode.failure = str(exc)
        episode.log("stop", episode.failure)
        return episode
    for macro in found.macro_actions:
        episode.reasoning_steps += 1
        episode.log("macro", macro.feature, expected=dict(macro.expect))
        for action in macro.actions:
            feedback = env.step(action.name, action.seconds)
            episode.execution_steps += 1
            episode.log(
                "action",
                action=action.name,
                display=feedback.text,
                values=feedback.values,
                accepted=feedback.accepted,
            )
    episode.claimed_success = True
    episode.log("stop", "plan executed")
    return episode


register(
    Method(
        "oracle",
        run_oracle,
        "the planner on the ground-truth model, executed open loop",
        uses_truth=True,
    )
)


def _agent(config: AgentConfig) -> RunFunction:
    def run(context: TaskContext, env: Environment) -> Episode:
        return run_agent(config, context, env)

    return run


register(
    Method(
        "apbot",
        _agent(AgentConfig()),
        "ApBot: plan on the belief model, check after every macro action, explore and "
        "repair on a mismatch, re-plan",
    )
)
register(
    Method(
        "apbot-open-loop",
        _agent(AgentConfig(closed_loop=False)),
        "ApBot without model updates: the belief's plan, executed without checking",
    )
)
register(
    Method(
        "apbot-no-button-policy",
        _agent(AgentConfig(button_policy=False)),
        "ApBot with the macro-action order from the model, but every press within a "
        "macro action chosen greedily from the feedback (one reasoning step each)",
    )
)
