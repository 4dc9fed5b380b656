"""The closed loop's vocabulary: its switches and limits, how a run ends, one action as done.

:class:`Executed` is what :meth:`apbot.agent.session.Session.press` returns and every
collaborator reasons about: where the belief was, what it predicted, what the display showed.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from apbot.agent.environment import Feedback
from apbot.agent.perception import MISSING, Seen
from apbot.plan.plan import PlannedAction
from apbot.sim.compiled import State

__all__ = ["EXPLORE_LIMIT", "PLAN_BUDGET", "PLAN_WORK", "AgentConfig", "Executed", "GiveUp", "Stop"]

EXPLORE_LIMIT = 400  # presses per direction (a 1-minute clock over 6 hours; most domains < 100)
# Search per plan. On the true models every plan of the bundled suite (750 tasks, stored or
# read goals, from every state the loop plans from) needs at most 14,149 expanded states (and
# keeps up to twice the budget in memory) and 730,469 successors generated; on a model read
# from a manual a search past that much work is almost always one that cannot succeed (the
# goal is out of the belief's reach and the search would walk its whole space, 2,000,000
# successors at 20 per state), so it gives up at the work limit instead.
PLAN_BUDGET = 100_000  # expanded states
PLAN_WORK = 1_000_000  # successors generated


@dataclass(frozen=True)
class AgentConfig:
    """Which parts of ApBot are switched on (the ablations switch them off)."""

    closed_loop: bool = True
    button_policy: bool = True
    explore_limit: int = EXPLORE_LIMIT
    plan_budget: int = PLAN_BUDGET
    plan_work: int = PLAN_WORK


class Stop(Exception):
    """The run ends: ``success`` claimed, or a declared failure with its reason."""

    def __init__(self, reason: str, success: bool = False) -> None:
        super().__init__(reason)
        self.reason = reason
        self.success = success


class GiveUp(Stop):
    """A goal setting that keeps going wrong however it is repaired. Only that setting is
    lost: the loop may set the rest of the goal without it (and then never claims), so that
    what gets set does not depend on whether the stuck setting came first or last in the plan."""

    def __init__(self, reason: str, names: frozenset[str]) -> None:
        super().__init__(reason)
        self.names = names


@dataclass
class Executed:
    """One action as performed: where the belief was, what it predicted, what was shown.

    ``surprises`` maps each variable the feedback contradicted to (predicted, observed); an
    observed None means the display was dark where the belief expected the value, and
    ``UNREADABLE`` that it showed text the belief's display rules cannot print. ``unchanged``:
    the display stayed exactly as it was although the belief predicted a change (a key
    ignored without a sign looks like this).
    """

    action: PlannedAction
    pointer: tuple[str, int] | None  # the belief's feature step after the action
    variable: str | None  # the variable that step adjusts
    feedback: Feedback
    believed_accepted: bool
    before: tuple[str, int] | None = None  # the belief's feature step before the action
    predicted: Any = None  # the belief's value of ``variable`` after the action
    seen: Seen | None = None
    surprises: dict[str, tuple[Any, Any]] = field(default_factory=dict)
    unchanged: bool = False
    buffer: str = ""  # the keypad digits the belief had typed into the step after the action
    state_before: State | None = None  # the belief's state before the action
    unseen_before: frozenset[str] = frozenset()  # changed unseen (or guessed) before the action
    shown_before: dict[str, Any] = field(default_factory=dict)  # last shown, before the action
    typed: bool = False  # the display showed the keypad entry as typed, not the value
    text_before: str = ""  # what the display showed before the action

    def observed(self, name: str) -> Any:
        """The value of ``name`` the display showed after this action (MISSING if none)."""
        return MISSING if self.seen is None else self.seen.observed(name)

    def start_shown(self, name: str) -> bool:
        """Whether the display had shown ``name``'s value and nothing changed it unseen since:
        the value the action moved from was read, not the belief's guess."""
        shown = self.shown_before.get(name, MISSING)
        return name not in self.unseen_before and shown is not MISSING and shown is not None

    @property
    def refused(self) -> bool:
        """The appliance refused what the belief expected to work."""
        return self.believed_accepted and not self.feedback.accepted

    @property
    def surprising(self) -> bool:
        return self.refused or bool(self.surprises)
