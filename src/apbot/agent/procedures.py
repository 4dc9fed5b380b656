"""The procedure repairer: a step the belief's feature lacks or has in the wrong place.

Values are learnt by walking them; steps are learnt by probing. When the appliance refuses
a key the belief expected to work, or a setting the belief cannot reach at all, the agent
tries the keys the belief gives no clear role (unused keys, keys that do nothing in the step,
the procedure's other keys) and keeps the one after which the setting comes up. Each probe is
an exploration press: it costs execution steps, not reasoning steps.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.guards import GuardLearner
from apbot.agent.repair import RepairError, insert_step
from apbot.agent.session import MISSING, Executed, Session, Stop


class ProcedureRepairer:
    """Find and insert missing steps (a guard that explains the trouble comes first)."""

    def __init__(self, session: Session, guards: GuardLearner) -> None:
        self.session = session
        self.guards = guards

    def repair_procedure(self, executed: list[Executed]) -> None:
        """A key the belief expected to work was refused, or brought up another setting:
        explain it by a guard, or find the step in front of it that the belief misses."""
        refused = [e for e in executed if e.refused]
        if refused and self.guards.explain(refused[0]):
            return
        failing = refused or [e for e in executed if e.variable is not None]
        if failing and self.guards.learn(failing[0]):
            return
        if not failing or failing[0].pointer is None:
            raise Stop(
                "the appliance does not respond as the model predicts, and the "
                "model gives no step to learn from"
            )
        first = failing[0]
        assert first.pointer is not None
        feature, index = first.pointer
        name = first.variable
        self.session.again("procedure", feature, f"{first.action.name} keeps failing in {feature}")
        step = self.session.belief.model.features[feature][index]
        idle = [a for a in step.actions if self.session.effect(first.pointer, a) == "none"]
        others = [
            a
            for s in self.session.belief.model.features[feature]
            for a in s.actions
            if a not in step.actions
        ]
        for candidate in dict.fromkeys(self.orphans() + idle + others):
            if candidate == first.action.name:
                continue
            probe = self.session.press(self.session.planned(candidate), exploring=True)
            if not probe.feedback.accepted:
                continue
            after = self.session.press(first.action, exploring=True)
            if after.feedback.accepted and name is not None and after.observed(name) is not MISSING:
                try:
                    new = insert_step(self.session.belief.model, feature, index, [candidate])
                except RepairError as exc:
                    self.session.episode.log("repair", f"could not add a step: {exc}")
                    continue
                self.session.adopt(
                    new,
                    f"{feature} starts with {candidate} before {first.action.name}",
                    (feature, index + 1),
                )
                return
        self.session.forget_pointer()

    def recover_unreachable(self, blocked: dict[str, Any]) -> bool:
        """The belief cannot bring these goal variables up: probe for the key that does."""
        for name in blocked:
            if not self.session.budget.once("unreachable", name):
                continue
            features = [
                f
                for f, steps in self.session.belief.model.features.items()
                if any(s.variable == name for s in steps)
            ]
            if self._first_step_from_orphans(name, features):
                return True
            if any(self.find_separator(feature, name) for feature in features):
                return True
        return False

    def _first_step_from_orphans(self, name: str, features: list[str]) -> bool:
        for candidate in self.orphans():
            self.guards.lift(candidate)
            probe = self.session.press(self.session.planned(candidate), exploring=True)
            if not probe.feedback.accepted or probe.observed(name) is MISSING:
                continue
            for feature in features:
                try:
                    new = insert_step(self.session.belief.model, feature, 0, [candidate])
                except RepairError:
                    continue
                self.session.adopt(new, f"{feature} starts with {candidate}", (feature, 0))
                return True
        return False

    def find_separator(self, feature: str, name: str) -> bool:
        """A step of ``feature`` that can never be entered because it shares its keys with
        the step before it: walk the procedure up to that step, then try the procedure's other
        keys for the one that brings ``name`` up (a SET press between hours and minutes)."""
        steps = self.session.belief.model.features[feature]
        index = next((i for i, s in enumerate(steps) if s.variable == name), None)
        if (
            index is None
            or index == 0
            or not set(steps[index].actions) & set(steps[index - 1].actions)
        ):
            return False
        inside = {a for i in (index - 1, index) for a in steps[i].actions}
        others = [a for s in steps for a in s.actions if a not in inside]
        for candidate in dict.fromkeys(others):
            # from the step before (where the plan left off), else through the procedure
            if self.session.belief.pointer() != (feature, index - 1):
                self.enter_step(feature, index)
            probe = self.session.press(self.session.planned(candidate), exploring=True)
            shown = probe.observed(name)
            if probe.feedback.accepted and shown is not MISSING:
                # confirm: the setting's own key must now change it
                turn = self.session.press(
                    self.session.planned(steps[index].actions[0]), exploring=True
                )
                if turn.observed(name) not in (MISSING, shown):
                    try:
                        new = insert_step(self.session.belief.model, feature, index, [candidate])
                    except RepairError:
                        continue
                    self.session.adopt(
                        new, f"{feature} needs {candidate} before {name}", (feature, index + 1)
                    )
                    self.session.reread()
                    return True
            self.session.forget_pointer()
        return False

    def absorbed(self, entering: Executed) -> bool:
        """A key meant to start a new procedure changed nothing, and the display does not
        show that procedure's setting: perhaps the procedure in progress takes the key as one
        more step (a START that confirms a timer). Add it there, once; the next check judges."""
        before, after = entering.before, entering.pointer
        if before is None or after is None or before[0] == after[0]:
            return False
        shown = set(entering.seen.values if entering.seen else ()) - set(
            self.session.belief.model.display.indicators
        )
        staying = {s.variable for s in self.session.belief.model.features[before[0]]} - {None}
        if entering.variable in staying | shown:
            return False  # the display shows the new setting: the key did start it
        if not self.session.budget.once("absorbed", f"{before[0]}:{entering.action.name}"):
            return False
        feature, index = before
        try:
            new = insert_step(self.session.belief.model, feature, index + 1, [entering.action.name])
        except RepairError as exc:
            self.session.episode.log("repair", f"could not add a step to {feature}: {exc}")
            return False
        self.session.adopt(
            new, f"{feature} takes {entering.action.name} as a further step", (feature, index + 1)
        )
        return True

    def enter_step(self, feature: str, index: int) -> None:
        """Go through ``feature`` up to (not into) step ``index``: lift any guard, then press
        the first key of each earlier step (exploration presses)."""
        steps = self.session.belief.model.features[feature]
        self.guards.lift(steps[0].actions[0])
        for step in steps[:index]:
            self.session.press(self.session.planned(step.actions[0]), exploring=True)

    def orphans(self) -> list[str]:
        """Keys the appliance offers that no feature of the belief uses (at most eight)."""
        used = {
            a
            for steps in self.session.belief.model.features.values()
            for s in steps
            for a in s.actions
        }
        return [
            a
            for a in self.session.belief.model.actions
            if a not in used and a in self.session.offered
        ][:8]
