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
    belief: str = Field(description="'true', 'faulty:RATE' (seeded) or 'read'")
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


def spl(success: bool, optimal: int, taken: int) -> float:
    """Success weighted by path length: optimal / max(optimal, taken) when successful.

    >>> spl(True, 4, 8), spl(True, 4, 4), spl(False, 4, 4), spl(True, 0, 0)
    (0.5, 1.0, 0.0, 1.0)
    """
    if not success:
        return 0.0
    return 1.0 if max(optimal, taken) == 0 else optimal / max(optimal, taken)
