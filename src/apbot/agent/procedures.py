"""The procedure repairer: a step the belief's feature lacks or has in the wrong place.

Values are learnt by walking them; steps are learnt by probing. When the appliance refuses
a key the belief expected to work, or a setting the belief cannot reach at all, the agent
tries the keys the belief gives no clear role (unused keys, keys that do nothing in the step,
the procedure's other keys; ``apbot.agent.keys``) and keeps the one after which the setting
comes up. Each probe is an exploration press: it costs execution steps, not reasoning steps.
A key filed under the wrong procedure is moved by ``apbot.agent.misfiled``; side effects are
learnt by ``apbot.agent.side_effects``.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.guards import GuardLearner
from apbot.agent.keys import RUN_WORDS, doubled_keys, effect_shown, keys_like, orphans, run_states
from apbot.agent.misfiled import KeyMover
from apbot.agent.repair import RepairError, drop_action, insert_step, move_action
from apbot.agent.session import MISSING, Executed, Session, Stop
from apbot.agent.side_effects import SideEffectLearner
from apbot.plan.plan import Unreachable, plan

__all__ = ["ProcedureRepairer"]


class ProcedureRepairer:
    """Find and insert missing steps (a guard that explains the trouble comes first)."""

    def __init__(self, session: Session, guards: GuardLearner) -> None:
        self.session = session
        self.guards = guards
        self.movers = KeyMover(session)
        self.side_effects = SideEffectLearner(session)

    def repair_procedure(self, executed: list[Executed]) -> None:
        """A key the belief expected to work was refused, or brought up another setting:
        explain it by a guard, or find the step in front of it that the belief misses."""
        refused = [e for e in executed if e.refused]
        if refused and self.guards.explain(refused[0]):
            return
        failing = refused or [e for e in executed if e.variable is not None]
        if failing and self.guards.learn(failing[0]):
            return
        if failing and not refused and self.movers.move_key(failing[0]):
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
        self.session.again(
            "procedure",
            feature,
            f"{first.action.name} keeps failing in {feature}",
            [name] if name is not None else [],
        )
        step = self.session.belief.model.features[feature][index]
        idle = [a for a in step.actions if self.session.effect(first.pointer, a) == "none"]
        others = [
            a
            for s in self.session.belief.model.features[feature]
            for a in s.actions
            if a not in step.actions
        ]
        alike = keys_like(self.session, name or feature, exclude=set(step.actions))
        elsewhere = self._entries_elsewhere(feature, name)
        doubles = [a for a in doubled_keys(self.session) if a not in step.actions]
        candidates = orphans(self.session) + idle + others + list(elsewhere) + alike + doubles
        for candidate in dict.fromkeys(candidates):
            if candidate == first.action.name:
                continue
            running = run_states(self.session)
            probe = self.session.press(self.session.planned(candidate), exploring=True)
            if not probe.feedback.accepted:
                continue
            after = self.session.press(first.action, exploring=True)
            shows = name is not None and after.observed(name) is not MISSING
            if not (after.feedback.accepted and shows):
                self._stop_started(running)  # a cycle the probe started locks the next probes
            if after.feedback.accepted and shows and candidate in elsewhere:
                # the key belongs to that other procedure, after its entry key
                assert name is not None
                where = elsewhere[candidate]
                effect = effect_shown(
                    self.session, *where, probe.observed(name), after.observed(name)
                )
                try:
                    new = move_action(self.session.belief.model, first.action.name, where, effect)
                except RepairError as exc:
                    self.session.episode.log("repair", f"could not move a key: {exc}")
                    continue
                self.session.adopt(
                    new,
                    f"{first.action.name} belongs to {where[0]} after {candidate}, not {feature}",
                    where,
                )
                return
            if after.feedback.accepted and shows:
                model = self.session.belief.model
                try:
                    new = insert_step(model, feature, index, [candidate], move=candidate in doubles)
                except RepairError:
                    try:  # it starts another procedure in the belief: shown to do this instead
                        new = insert_step(model, feature, index, [candidate], move=True)
                    except RepairError as exc:
                        self.session.episode.log("repair", f"could not add a step: {exc}")
                        continue
                self.session.adopt(
                    new,
                    f"{feature} starts with {candidate} before {first.action.name}",
                    (feature, index + 1),
                )
                return
        if first.unchanged and self._drop_key(first):
            return
        self.session.forget_pointer()

    def _stop_started(self, before: dict[str, Any]) -> None:
        """A probe that explained nothing but started a cycle: stop it again (by the belief's
        shortest route), so that the keys a running cycle locks can still be probed."""
        session = self.session
        started = {n: v for n, v in before.items() if session.belief.value(n) != v}
        if not started:
            return
        try:
            route = plan(session.belief.compiled, session.belief.state, started)
        except Unreachable:
            return
        for planned in route.actions:
            session.press(planned, exploring=True)

    def _drop_key(self, failed: Executed) -> bool:
        """A key ignored where the belief had it as one of a step's keys, and no probe found
        where it belongs: it is not that step's (its other keys still are), once."""
        assert failed.pointer is not None
        feature, index = failed.pointer
        step = self.session.belief.model.features[feature][index]
        if len(step.actions) < 2 or failed.action.name not in step.actions:
            return False
        if not self.session.budget.once("entry", f"drop:{feature}:{index}:{failed.action.name}"):
            return False
        try:
            new = drop_action(self.session.belief.model, failed.action.name, (feature, index))
        except RepairError:
            return False
        self.session.adopt(
            new, f"{failed.action.name} does nothing in {feature}", self.session.belief.pointer()
        )
        return True

    def _entries_elsewhere(self, feature: str, name: str | None) -> dict[str, tuple[str, int]]:
        """Entry keys of the other procedures that adjust ``name`` too, each with the step of
        that procedure that adjusts it: the failing key may belong there."""
        found: dict[str, tuple[str, int]] = {}
        if name is None:
            return found
        for other, steps in self.session.belief.model.features.items():
            if other == feature or len(steps) < 2 or steps[0].variable is not None:
                continue
            for index, step in enumerate(steps[1:], start=1):
                if step.variable == name:
                    found.setdefault(steps[0].actions[0], (other, index))
        return found

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
            if not features and self._setter(name, blocked[name]):
                return True
        return False

    def _setter(self, name: str, value: Any) -> bool:
        """A goal setting no step adjusts, which none of the belief's side effects brings to
        the goal value (running, set by START): a key named like it — START for a run state —
        may set it as a side effect the reader missed. Press each such key once; the first
        after which the display shows the setting at the goal value teaches that side effect."""
        session = self.session
        compiled = session.belief.compiled
        keys = keys_like(self.session, name, exclude=set())
        if any(word in name for word in RUN_WORDS):
            keys += [a for a in session.belief.model.actions if "start" in a.split("_")]
        for key in list(dict.fromkeys(keys))[:3]:
            if key not in session.offered or not session.budget.once(
                "unreachable", f"setter:{key}"
            ):
                continue
            self.guards.lift(key)
            probe = session.press(session.planned(key), exploring=True)
            observed = probe.observed(name)
            if not probe.feedback.accepted or probe.state_before is None:
                continue
            if observed != value or observed == compiled.value(probe.state_before, name):
                continue
            if self.side_effects.learn_side_effect(name, probe, observed):
                return True
        return False

    def find_entry(self, feature: str) -> bool:
        """An earlier key was believed to start ``feature`` and did nothing: the procedure
        lacks the key that starts it. Probe for it (once per setting)."""
        steps = self.session.belief.model.features.get(feature, [])
        name = next((s.variable for s in steps if s.variable is not None), None)
        if name is None or not self.session.budget.once("unreachable", name):
            return False
        self.session.forget_pointer()
        return self._first_step_from_orphans(name, [feature])

    def _first_step_from_orphans(self, name: str, features: list[str]) -> bool:
        """Keys no procedure uses, or named like the setting (an entry key filed under another
        procedure): the one that brings the setting up is the entry step it lacks."""
        used = set(orphans(self.session))
        firsts = {a for f in features for a in self.session.belief.model.features[f][0].actions}
        for candidate in dict.fromkeys([*used, *keys_like(self.session, name, exclude=firsts)]):
            self.guards.lift(candidate)
            probe = self.session.press(self.session.planned(candidate), exploring=True)
            if not probe.feedback.accepted or not self.session.shows(probe.feedback, name):
                continue
            for feature in features:
                try:
                    new = insert_step(
                        self.session.belief.model,
                        feature,
                        0,
                        [candidate],
                        move=candidate not in used,
                    )
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
        # or a key named like the setting, filed under another procedure (TIMER, which
        # switches the right side to its timer as it does the left side)
        others += keys_like(self.session, name, exclude=inside | {steps[0].actions[0]})
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

    def enter_step(self, feature: str, index: int) -> None:
        """Go through ``feature`` up to (not into) step ``index``: lift any guard, then press
        the first key of each earlier step (exploration presses)."""
        steps = self.session.belief.model.features[feature]
        self.guards.lift(steps[0].actions[0])
        for step in steps[:index]:
            self.session.press(self.session.planned(step.actions[0]), exploring=True)
