"""The goal a method is given in a benchmark run: read from the instruction, or the stored one.

- ``read`` (the default) — the offline goal parser reads the task's instruction against the
  method's own belief (:func:`apbot.read.goal.parse_instruction`, with the manual for coded
  values): what a robot with no LLM would do. A quantity the belief has no value for is still
  handed over as said, to the setting of its kind the words name (a belief read from a manual
  may lack a value the appliance has; the closed loop looks for it), and the parser's reason
  is recorded; an instruction it cannot read at all gives no goal, and the task fails with the
  parser's message.
  With an LLM configured (``--llm``) the LLM reads it instead
  (:func:`apbot.read.llm_goal.llm_parse_instruction`, the offline reading as its hint).
- ``given`` — the task's stored goal, in the truth's names (the figures before reading landed).

Either way success is judged on the true simulator against the stored goal. Whether the parsed
goal *is* the stored one (after translating the stored goal into the belief's names through
the reader's evaluation alignment) is recorded for the report — a judgement that uses the
truth, never shown to a method.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, Literal

from apbot.model.schema import ApplianceModel

GoalMode = Literal["read", "given"]
GOAL_MODES: tuple[GoalMode, ...] = ("read", "given")


class GoalModeError(ValueError):
    """An unknown goal mode."""


def parse_goal_mode(text: str) -> GoalMode:
    """Validate a ``--goal`` value.

    >>> parse_goal_mode(" read ")
    'read'
    >>> parse_goal_mode("parsed")
    Traceback (most recent call last):
    ...
    apbot.bench.goals.GoalModeError: unknown goal mode 'parsed'; accepted: read, given
    """
    cleaned = text.strip()
    if cleaned == "read":
        return "read"
    if cleaned == "given":
        return "given"
    raise GoalModeError(f"unknown goal mode {text!r}; accepted: {', '.join(GOAL_MODES)}")


@dataclass
class MethodGoal:
    """What a method is given, and what the report shows about it.

    ``goal``: the goal handed to the method (None when the instruction could not be read);
    ``parsed``: the parser's goal (read mode), ``error``: its message when it gave none;
    ``exact``: the parsed goal equals the stored one under the alignment (None: not judged).
    """

    goal: dict[str, Any] | None
    parsed: dict[str, Any] | None = None
    error: str = ""
    exact: bool | None = None
    outside: list[str] = field(default_factory=list)  # values kept though the belief lacks them
    usage: dict[str, int] = field(default_factory=dict)  # LLM tokens spent reading it


def method_goal(
    mode: GoalMode,
    belief: ApplianceModel,
    instruction: str,
    manual: str,
    stored: dict[str, Any],
    truth: ApplianceModel,
    offline: bool = False,
) -> MethodGoal:
    """The goal for a method working from ``belief`` on a task whose stored goal is ``stored``:
    read by the configured LLM (unless ``offline``), else by the offline parser."""
    if mode == "given":
        return MethodGoal(dict(stored))
    from apbot.llm.client import configured_client
    from apbot.read.goal import GoalParseError, parse_instruction

    client = None if offline else configured_client()
    if client is not None:  # the LLM reads it; when it gives no valid answer, the offline parser
        from apbot.llm.structured import StructuredError
        from apbot.read.llm_goal import llm_parse_instruction

        try:
            answer = llm_parse_instruction(belief, instruction, client, manual=manual)
        except StructuredError as exc:
            fallback = method_goal(mode, belief, instruction, manual, stored, truth, offline=True)
            fallback.usage = exc.usage.record()
            return fallback
        parsed = dict(answer.goal)
        exact = same_goal(belief, truth, parsed, stored)
        return MethodGoal(parsed, dict(parsed), exact=exact, usage=answer.usage.record())
    key = (id(belief), id(truth), instruction, manual, repr(sorted(stored.items())))
    known = _OFFLINE.get(key)
    if known is None or known[0] is not belief or known[1] is not truth:
        outside: list[str] = []
        try:
            parsed = parse_instruction(belief, instruction, manual, outside=outside)
        except GoalParseError as exc:
            found = MethodGoal(None, None, f"cannot read the instruction: {exc}", exact=False)
        else:
            exact = same_goal(belief, truth, parsed, stored)
            found = MethodGoal(dict(parsed), dict(parsed), exact=exact, outside=outside)
        if len(_OFFLINE) >= OFFLINE_KEPT:
            _OFFLINE.clear()
        known = _OFFLINE[key] = (belief, truth, found)
    found = known[2]
    return replace(
        found,
        goal=None if found.goal is None else dict(found.goal),
        parsed=None if found.parsed is None else dict(found.parsed),
        outside=list(found.outside),
    )


# Offline readings by belief, truth, instruction, manual and stored goal: the parser is
# deterministic and every method of a task asks it the same question on the same (frozen,
# cached) belief; the alignment judging it costs more than the parse. Identity is checked, so
# a model freed and another allocated at its address is never mistaken for it.
OFFLINE_KEPT = 4096
_OFFLINE: dict[tuple[int, int, str, str, str], tuple[ApplianceModel, ApplianceModel, MethodGoal]]
_OFFLINE = {}


def same_goal(
    belief: ApplianceModel, truth: ApplianceModel, parsed: dict[str, Any], stored: dict[str, Any]
) -> bool:
    """The parsed goal (belief names) is the stored goal (truth names), under the alignment."""
    from apbot.model.domain import ValueProblem
    from apbot.model.goal import GoalError, parse_goal
    from apbot.read.evaluate import translate_goal

    try:
        wanted = stored if belief is truth else translate_goal(belief, truth, stored)
        return parse_goal(belief, wanted) == parse_goal(belief, parsed)
    except (GoalError, ValueProblem, KeyError, ValueError):
        return False
