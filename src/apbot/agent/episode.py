"""What a method is given for one task, and what it hands back: the episode and its trace.

The counts follow the paper: a *reasoning step* is one macro action decided (exploration
excluded); an *execution step* is one physical action performed (exploration included).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from typing import Any, Literal

from apbot.model.schema import ApplianceModel

MAX_REASONING_STEPS = 25

EventKind = Literal["macro", "action", "check", "explore", "repair", "plan", "stop"]


@dataclass(frozen=True)
class TaskContext:
    """Everything a robot would have for one task — and nothing of the ground truth.

    ``belief`` is the model the method works from (the true model, a faulty copy, or one read
    from the manual); ``goal`` is the target as written (variable name → value in any
    notation), to be normalised against the belief; ``actions`` are the environment's action
    names.
    """

    appliance: str
    category: str
    task: str
    instruction: str
    goal: dict[str, Any]
    belief: ApplianceModel
    manual: str = ""
    actions: tuple[str, ...] = ()
    max_reasoning_steps: int = MAX_REASONING_STEPS
    goal_read: bool = True
    """The goal was read from ``instruction`` (False: handed over, e.g. a benchmark's stored
    goal — then the sentence is not what the goal answers for, and a number it says that the
    goal does not hold is no part left unread)."""
    observer: Callable[[TraceEvent], None] | None = field(default=None, compare=False)
    """Called with every trace event as it happens (``apbot run`` shows them live)."""

    def episode(self) -> Episode:
        """A fresh episode that reports its events to the observer."""
        return Episode(observer=self.observer)


@dataclass
class TraceEvent:
    """One line of an episode's trace.

    ``kind``: ``macro`` (a reasoning step starts: ``text`` names the macro action),
    ``action`` (a physical action and the feedback after it; ``exploring`` marks exploration),
    ``check`` (expected vs observed after a macro action), ``explore`` / ``repair`` (what was
    learnt and how the belief changed), ``plan`` (a (re)plan) and ``stop`` (why the run ended).
    """

    kind: EventKind
    step: int
    text: str = ""
    action: str | None = None
    display: str | None = None
    values: dict[str, Any] = field(default_factory=dict)
    expected: dict[str, Any] = field(default_factory=dict)
    accepted: bool = True
    exploring: bool = False

    def to_dict(self) -> dict[str, Any]:
        """The event without its default fields (traces are stored for every task)."""
        data = {
            k: v
            for k, v in asdict(self).items()
            if v not in (None, {}, "", False) or k in ("kind", "step")
        }
        if self.accepted:
            del data["accepted"]
        else:
            data["accepted"] = False
        return data


@dataclass
class Episode:
    """The outcome of one method on one task, as the method saw it.

    ``claimed_success`` is the method's own verdict; the benchmark judges success on the
    environment's true final state instead. ``failure`` says why the method stopped early.
    """

    claimed_success: bool = False
    reasoning_steps: int = 0
    execution_steps: int = 0
    trace: list[TraceEvent] = field(default_factory=list)
    repairs: list[str] = field(default_factory=list)
    failure: str = ""
    llm_usage: dict[str, int] = field(default_factory=dict)
    observer: Callable[[TraceEvent], None] | None = field(default=None, repr=False)
    belief: ApplianceModel | None = field(default=None, repr=False)
    """The model the method ended with, its repairs kept (None: it keeps none); a household
    robot starts its next task from it (``apbot bench --learn``)."""

    def log(self, kind: EventKind, text: str = "", **fields: Any) -> TraceEvent:
        event = TraceEvent(kind, self.reasoning_steps, text, **fields)
        self.trace.append(event)
        if self.observer is not None:
            self.observer(event)
        return event
