"""Any appliance, from Python, in one call: manual text, action names, a sentence, an environment.

Someone with their own appliance — a simulator of theirs, or a robot in front of a real panel —
has its manual, the names of the actions it accepts, and what the user said. :func:`operate`
takes exactly those four things and returns the whole episode: the model read from the manual,
the goal read from the sentence, the trace and the outcome. Both readings use the LLM configured
in the environment (``APBOT_LLM``; see ``docs/llm.md``) and are offline otherwise; each is also
available on its own (:func:`read_model`, :func:`read_goal`).

Nothing here sees a ground truth: the outcome is the agent's own verdict, checked against what
the appliance displayed. See ``docs/environments.md`` for a worked example.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

from apbot.agent.environment import Environment
from apbot.agent.episode import Episode, TaskContext, TraceEvent
from apbot.agent.registry import get_method
from apbot.model.schema import ApplianceModel
from apbot.read import Reading, Report, read_manual
from apbot.read.goal import GoalParseError, parse_instruction

OFFLINE_NOTE = (
    "reading with the offline reader and goal parser: no LLM is configured "
    "(give --llm openai:MODEL with the key in OPENAI_API_KEY, --llm http://HOST:PORT/v1:MODEL, "
    "or --llm local after `apbot llm serve`; or set APBOT_LLM)"
)
"""What a user is told about how the manual and the sentence are read."""


@dataclass
class Operation:
    """One episode on an appliance known only from its manual.

    ``reading``: the read model and its report; ``goal``: what the sentence asks for, in the
    model's names (empty when it could not be read: ``goal_error`` says why); ``episode``: the
    trace, steps and repairs; ``success``: the agent's verdict (it sees no ground truth).
    """

    reading: Reading
    goal: dict[str, Any]
    episode: Episode
    goal_error: str = ""
    notes: list[str] = field(default_factory=list)

    @property
    def model(self) -> ApplianceModel:
        return self.reading.model

    @property
    def trace(self) -> list[TraceEvent]:
        return self.episode.trace

    @property
    def success(self) -> bool:
        return self.episode.claimed_success

    @property
    def outcome(self) -> str:
        """One line: the verdict, and the reason when the agent stopped short."""
        if self.goal_error:
            return f"not attempted: {self.goal_error}"
        if self.success:
            return (
                f"done: {self.episode.reasoning_steps} reasoning steps, "
                f"{self.episode.execution_steps} actions"
            )
        return f"failed: {self.episode.failure or 'the goal was not reached'}"


def read_model(
    manual: str,
    actions: Sequence[str],
    appliance_id: str = "appliance",
    category: str = "appliance",
) -> Reading:
    """The model (and reading report) read from a manual's text and the panel's action names:
    by the configured LLM (seeded by the offline reading), else by the offline reader.
    Raises :class:`apbot.read.ReaderError` for text that is no manual."""
    from apbot.llm.client import configured_client

    client = configured_client()
    if client is None:
        return read_manual(manual, list(actions), appliance_id, category)
    from apbot.read.llm_reader import llm_read_manual

    return llm_read_manual(manual, list(actions), client, appliance_id, category).as_reading()


def read_goal(model: ApplianceModel, instruction: str, manual: str = "") -> dict[str, Any]:
    """The goal a sentence asks for, over ``model``'s settings: by the configured LLM, else (or
    when it gives no valid answer) by the offline goal parser.

    Raises :class:`apbot.read.goal.GoalParseError` (a ``ValueError``) naming the words the
    model cannot satisfy and why.
    """
    from apbot.llm.client import configured_client

    client = configured_client()
    if client is not None:
        from apbot.llm.structured import StructuredError
        from apbot.read.llm_goal import llm_parse_instruction

        try:
            return dict(llm_parse_instruction(model, instruction, client, manual=manual).goal)
        except StructuredError:
            pass  # the offline parser's answer stands
    return dict(parse_instruction(model, instruction, manual))


def operate(
    manual: str,
    actions: Sequence[str],
    instruction: str,
    env: Environment,
    *,
    method: str = "apbot",
    observer: Callable[[TraceEvent], None] | None = None,
    model: ApplianceModel | None = None,
) -> Operation:
    """Read the manual and the instruction, then operate ``env`` until the goal shows.

    ``actions`` are the environment's action names (``env.actions`` usually). An instruction
    the read model cannot satisfy is not guessed at: the operation comes back unattempted,
    with the parser's message in ``goal_error``. ``observer`` sees every trace event live;
    ``model`` replaces the reading of the manual (a model written or read before).
    """
    reading = read_model(manual, actions) if model is None else Reading(model, Report([]))
    try:
        goal = read_goal(reading.model, instruction, manual)
    except GoalParseError as exc:
        return Operation(reading, {}, Episode(failure=str(exc)), goal_error=str(exc))
    if not goal:
        why = "the instruction names no setting of the model read from the manual"
        return Operation(reading, {}, Episode(failure=why), goal_error=why)
    context = TaskContext(
        reading.model.appliance.id,
        reading.model.appliance.category,
        "live",
        instruction,
        goal,
        reading.model,
        manual,
        tuple(actions),
        observer=observer,
    )
    episode = get_method(method).run(context, env)
    return Operation(reading, goal, episode, notes=[reading_note()] if model is None else [])


def reading_note() -> str:
    """How the manual and the sentence are read: by which LLM, or offline and how to set one."""
    from apbot.llm.client import configured_client

    client = configured_client()
    if client is None:
        return OFFLINE_NOTE
    return f"reading with the LLM {client.config.describe()}"
