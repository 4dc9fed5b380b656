"""Methods that need an LLM: the LLM as policy, and ApBot without a model.

Both get only honest inputs: the manual, the user's instruction, the action names, and after
each action what the display showed (never the stored goal or the belief model).

- ``llm-policy``: each reasoning step the LLM picks one action by name, or says it is done.
- ``apbot-no-model`` (the paper's "w/o model" ablation): each reasoning step the LLM picks an
  action and how many times to press it; code only expands the repeats.

The prompt puts the manual first and the action names after it — the same for every step of
every task on one appliance — so a server's prompt cache reuses that prefix; the instruction
and the history come last. Actions are chosen from an enum of the environment's names, so an
answer cannot name an action that does not exist; the answer is data, never executed. Hold
actions are held as long as the appliance needs (as a person holds a key until it beeps).
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, Field, create_model

from apbot.agent.environment import Environment, Feedback
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.registry import Method, register
from apbot.llm.client import LLMClient, configured_client
from apbot.llm.structured import StructuredError, ask
from apbot.llm.usage import add_records

DONE = "done"
MAX_REPEAT = 30
MAX_MANUAL_CHARS = 16_000  # a longer manual is cut (the local model's context is 8k tokens)

SYSTEM = (
    "You operate a home appliance for a user by pressing its controls, following its user "
    "manual. You see what the display shows after every action. Choose actions that make the "
    "appliance do exactly what the user asked; when it is done, answer done."
)


class NoLLM(RuntimeError):
    """A method that needs an LLM was run with none configured."""


def _client() -> LLMClient:
    client = configured_client()
    if client is None:
        raise NoLLM(
            "this method needs an LLM: give --llm (openai:MODEL, http://HOST:PORT/v1:MODEL or "
            "local) or set APBOT_LLM"
        )
    return client


def _shown(feedback: Feedback) -> str:
    text = feedback.text.strip() or "(dark)"
    return text if feedback.accepted else f"{text} (refused: {feedback.reason or 'beep'})"


def policy_messages(
    context: TaskContext, actions: list[str], history: list[str], repeats: bool
) -> list[dict[str, Any]]:
    manual = context.manual[:MAX_MANUAL_CHARS]
    listed = ", ".join(actions)
    steps = "\n".join(history) if history else "(nothing yet)"
    ask_for = (
        "Choose the next action and how many times to press it in a row, or done."
        if repeats
        else "Choose the next action, or done."
    )
    return [
        {"role": "system", "content": SYSTEM},
        {
            "role": "user",
            "content": f"User manual:\n{manual}\n\nActions: {listed}\n\n"
            f"User's request: {context.instruction}\n\n"
            f"Actions so far and what the display showed after each:\n{steps}\n\n{ask_for}",
        },
    ]


def choice_schema(actions: list[str], repeats: bool) -> type[BaseModel]:
    names = Literal[tuple([*actions, DONE])]  # type: ignore[valid-type]
    fields: dict[str, Any] = {"action": (names, ...)}
    if repeats:
        fields["times"] = (int, Field(default=1, ge=1, le=MAX_REPEAT))
    return create_model("Choice", **fields)


def run_llm_policy(
    context: TaskContext, env: Environment, repeats: bool = False, client: LLMClient | None = None
) -> Episode:
    """Ask the LLM for the next action each step until it says done or the steps run out."""
    llm = client or _client()
    episode = context.episode()
    actions = list(env.actions)
    schema = choice_schema(actions, repeats)
    history: list[str] = []
    env.reset()
    while episode.reasoning_steps < context.max_reasoning_steps:
        try:
            answer = ask(
                llm,
                policy_messages(context, actions, history, repeats),
                schema,
                max_tokens=40,
            )
        except StructuredError as exc:
            add_records(episode.llm_usage, exc.usage)
            episode.failure = f"no valid choice from the LLM: {exc}"
            episode.log("stop", episode.failure)
            return episode
        add_records(episode.llm_usage, answer.usage)
        action = str(answer.value.action)  # type: ignore[attr-defined]
        if action == DONE:
            episode.claimed_success = True
            episode.log("stop", "the LLM says the request is done")
            return episode
        times = int(getattr(answer.value, "times", 1)) if repeats else 1
        episode.reasoning_steps += 1
        episode.log("macro", f"{action} ×{times}" if times > 1 else action)
        for _ in range(times):
            feedback = env.step(action)
            episode.execution_steps += 1
            episode.log(
                "action",
                action=action,
                display=feedback.text,
                values=feedback.values,
                accepted=feedback.accepted,
            )
            history.append(f"{len(history) + 1}. {action} -> {_shown(feedback)}")
    episode.failure = f"no done after {context.max_reasoning_steps} reasoning steps"
    episode.log("stop", episode.failure)
    return episode


def _run_repeats(context: TaskContext, env: Environment) -> Episode:
    return run_llm_policy(context, env, repeats=True)


register(
    Method(
        "llm-policy",
        run_llm_policy,
        "LLM as policy with grounded actions: manual, instruction, action names and the "
        "display history in, the next action (or done) out, each step",
        needs_llm=True,
    )
)
register(
    Method(
        "apbot-no-model",
        _run_repeats,
        "ApBot without a model (the paper's ablation): the LLM picks the next action and how "
        "many presses; code expands the repeats",
        needs_llm=True,
    )
)
