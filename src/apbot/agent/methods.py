"""The built-in methods: ApBot, its ablations, and the oracle."""

from __future__ import annotations

from apbot.agent.environment import Environment, Feedback
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.loop import AgentConfig, run_agent
from apbot.agent.oracle import run_oracle_plan
from apbot.agent.registry import Method, RunFunction, register
from apbot.model.goal import GoalError
from apbot.plan.plan import MacroAction, PlannedAction, Unreachable


def run_oracle(context: TaskContext, env: Environment) -> Episode:
    """Plan once on the (true) model and press every action: the upper bound SPL measures by.

    The plan and the presses are the benchmark's one oracle (``apbot.agent.oracle``); this
    method only keeps the trace.
    """
    episode = context.episode()

    def on_macro(macro: MacroAction) -> None:
        episode.reasoning_steps += 1
        episode.log("macro", macro.feature, expected=dict(macro.expect))

    def on_action(action: PlannedAction, feedback: Feedback) -> None:
        episode.execution_steps += 1
        episode.log(
            "action",
            action=action.name,
            display=feedback.text,
            values=feedback.values,
            accepted=feedback.accepted,
        )

    try:
        run_oracle_plan(context.belief, context.goal, env, on_macro, on_action)
    except (GoalError, Unreachable) as exc:
        env.reset()
        episode.failure = str(exc)
        episode.log("stop", episode.failure)
        return episode
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
