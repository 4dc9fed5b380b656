"""One finished (method, task) run as stored in a results file: the unit of resumption.

Records are JSON lines. ``key`` identifies the run (method, belief, appliance, task) so an
interrupted benchmark can skip what is done; everything but ``timings`` is deterministic, so
a resumed run ends with the same results as an uninterrupted one.
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field


def record_key(method: str, belief: str, appliance: str, task: str) -> str:
    return f"{method}|{belief}|{appliance}/{task}"


class TaskRecord(BaseModel):
    """The result of one method on one task, judged on the environment's true final state."""

    model_config = ConfigDict(extra="forbid")

    key: str
    method: str
    belief: str = Field(description="'read', 'true' or 'faulty:RATE' (seeded)")
    feedback: str = Field(
        default="values", description="what the agent perceived: 'display' or 'values'"
    )
    appliance: str
    category: str
    task: str
    instruction: str
    goal: dict[str, Any]
    goal_variables: int
    success: bool = Field(
        description="the goal holds in the true final state and the run "
        "stayed within the reasoning-step limit"
    )
    claimed_success: bool
    reasoning_steps: int
    execution_steps: int
    optimal_steps: int
    spl: float
    failure: str = ""
    repairs: list[str] = Field(default_factory=list)
    faults: list[str] = Field(default_factory=list, description="faults injected in the belief")
    final_values: dict[str, Any] = Field(
        default_factory=dict, description="true final values of the goal variables"
    )
    trace: list[dict[str, Any]] = Field(default_factory=list)
    timings: dict[str, float] = Field(default_factory=dict)
    llm_usage: dict[str, int] = Field(default_factory=dict)
    goal_mode: str = Field(
        default="given",
        description="'read': the method got the goal parsed from the instruction; 'given': "
        "the stored goal",
    )
    parsed_goal: dict[str, Any] | None = Field(
        default=None, description="the parser's goal, in the belief's names (read mode)"
    )
    goal_exact: bool | None = Field(
        default=None,
        description="the parsed goal is the stored one under the reader's alignment (judged "
        "with the truth; never shown to the method)",
    )
    goal_outside: list[str] = Field(
        default_factory=list,
        description="parts of the read goal the belief has no value for, handed over as said",
    )
    belief_hash: str = Field(default="", description="sha256 of the model the method started from")
    belief_diff: list[str] = Field(
        default_factory=list, description="a read belief's differences from the truth"
    )
    learnt_from: int = Field(
        default=0, description="with --learn: how many earlier tasks the starting belief saw"
    )


def spl(success: bool, optimal: int, taken: int) -> float:
    """Success weighted by path length: optimal / max(optimal, taken) when successful.

    >>> spl(True, 4, 8), spl(True, 4, 4), spl(False, 4, 4), spl(True, 0, 0)
    (0.5, 1.0, 0.0, 1.0)
    """
    if not success:
        return 0.0
    return 1.0 if max(optimal, taken) == 0 else optimal / max(optimal, taken)
