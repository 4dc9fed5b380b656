"""Two procedures the reader read as one: a key starts what the belief has as a later step.

A manual that lists "express cook" right under "time defrost" is easily read as one procedure
(press DEFROST, type the time, press START, then 1–6 for minutes of express cooking). On the
appliance the later step is a procedure of its own: pressed from no procedure at all, its key
does at once what that step says — sets the setting and its side effects. When the display
shows exactly that, the belief splits the procedure there (a data edit), and the new procedure
comes before any other the key was believed to start, for it is the one the key did start.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.repair import RepairError, split_feature
from apbot.agent.session import MISSING, Executed, Session
from apbot.model.schema import ApplianceModel
from apbot.sim.compiled import CompiledModel


class ProcedureSplitter:
    """Split a procedure where a key started what the belief has as one of its later steps."""

    def __init__(self, session: Session) -> None:
        self.session = session

    def split(self, done: Executed) -> bool:
        """The press did just what a later step with its key does, from no procedure: split
        that procedure there (once per step)."""
        session = self.session
        seen = done.seen
        if seen is None or done.state_before is None or done.refused or done.unchanged:
            return False
        shown = {**seen.values, **seen.outside}
        if not shown:
            return False
        model = session.belief.model
        for feature, steps in model.features.items():
            for index, step in enumerate(steps[1:], start=1):
                if done.action.name not in step.actions or step.variable not in shown:
                    continue
                if not session.budget.once("entry", f"split:{feature}:{index}"):
                    continue
                for first in (False, True):
                    try:
                        variant, name = split_feature(model, feature, index, first)
                    except RepairError:  # (another procedure would hide it: put it first)
                        continue
                    if self._explains(variant, done, shown):
                        session.adopt(
                            variant,
                            f"{done.action.name} starts a procedure of its own: {feature} ends "
                            f"before step {index + 1} ({name})",
                            (name, 0),
                        )
                        session.reread()
                        return True
        return False

    def misentered(self, done: Executed) -> str | None:
        """The press did what the belief says it does from no procedure at all, while the belief
        had the appliance inside one (entered by an earlier key that did nothing): the name of
        the procedure that key did not start."""
        seen = done.seen
        if seen is None or done.before is None or done.refused or done.state_before is None:
            return None
        shown = {**seen.values, **seen.outside}
        if not shown or not self._explains(self.session.belief.model, done, shown):
            return None
        compiled = self.session.belief.compiled
        before = compiled.assignment(done.state_before)
        if not any(before.get(name) != value for name, value in shown.items()):
            return None  # nothing changed that the display showed: no evidence either way
        return done.before[0]

    def _explains(self, variant: ApplianceModel, done: Executed, shown: dict[str, Any]) -> bool:
        """Whether, from no procedure, the key does on ``variant`` what the display showed."""
        assert done.state_before is not None
        compiled = CompiledModel(variant)
        start = done.state_before._replace(step=-1, buffer="")
        after = compiled.apply(start, compiled.action_index[done.action.name], done.action.seconds)
        if after is None:
            return False
        values = compiled.assignment(after)
        return all(
            values.get(name, MISSING) == value for name, value in shown.items() if name in values
        )
