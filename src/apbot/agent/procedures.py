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
from apbot.agent.repair import (
    RepairError,
    drop_action,
    drop_dependence,
    entry_then_keys,
    insert_step,
    move_action,
    set_effects,
    set_side_effect,
)
from apbot.agent.session import MISSING, UNREADABLE, Executed, Session, Stop
from apbot.model.schema import GoTo
from apbot.plan.plan import PlannedAction, Unreachable, plan

_RUN_WORDS = ("running", "heating", "dispensing", "status", "brewing", "cooking")


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
        if failing and not refused and self.move_key(failing[0]):
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
        alike = self.keys_like(name or feature, exclude=set(step.actions))
        elsewhere = self._entries_elsewhere(feature, name)
        doubles = [a for a in self.doubled_keys() if a not in step.actions]
        candidates = self.orphans() + idle + others + list(elsewhere) + alike + doubles
        for candidate in dict.fromkeys(candidates):
            if candidate == first.action.name:
                continue
            running = self._run_states()
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
                effect = self._effect_shown(*where, probe.observed(name), after.observed(name))
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

    def _run_states(self) -> dict[str, Any]:
        """The belief's run states (running, heating…) as they are now."""
        belief = self.session.belief
        return {
            n: belief.value(n) for n in belief.model.variables if any(w in n for w in _RUN_WORDS)
        }

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

    def move_key(self, done: Executed) -> bool:
        """The key brought up another setting's screen than the belief's step: the key belongs
        to that setting's procedure. Move it there — as a key that sets, steps or only shows
        the setting, as its value showed — and out of the step the belief had it in."""
        session = self.session
        seen = done.seen
        if seen is None or seen.screen_kind != "focus" or done.unchanged:
            return False
        target = seen.screen
        if target is None or target == done.variable or done.state_before is None:
            return False
        model = session.belief.model
        places = [
            (feature, index)
            for feature, steps in model.features.items()
            for index, step in enumerate(steps)
            if step.variable == target and done.action.name not in step.actions
        ]
        first = [(f, i) for f, i in places if i == 0]
        entered = [(f, i) for f, i in places if i > 0 and model.features[f][i - 1].variable is None]
        if not first and not entered:
            return False
        before = session.belief.compiled.value(done.state_before, target)
        shown = seen.observed(target)
        if (first or entered)[0] in first:
            feature, index = first[0]
            effect = self._effect_shown(feature, index, before, shown)
            where = (feature, index)
        else:
            feature, index = entered[0]
            effect, where = None, (feature, index - 1)
        if not session.budget.once("entry", f"move:{done.action.name}:{feature}"):
            return False
        try:
            new = move_action(model, done.action.name, where, effect)
        except RepairError as exc:
            session.episode.log("repair", f"could not move {done.action.name}: {exc}")
            return False
        old = done.pointer[0] if done.pointer else "?"
        session.adopt(new, f"{done.action.name} belongs to {feature}, not {old}", (feature, index))
        session.reread()
        return True

    def find_sibling(self, name: str, pointer: tuple[str, int], stuck: PlannedAction) -> bool:
        """A walk under ``stuck`` stayed on one value: it may be at an end of a setting it walks
        the other way than believed, with the key that walks it back filed under another
        procedure. Press each key named like the setting that the step lacks, once; the first
        that moves the setting joins the step as the display showed it, and ``stuck`` is taken
        to go the opposite way (once per setting)."""
        session = self.session
        if not session.budget.once("entry", f"sibling:{name}"):
            return False
        feature, index = pointer
        step = session.belief.model.features[feature][index]
        for candidate in self.keys_like(name, exclude=set(step.actions)):
            before = session.belief.value(name)
            probe = session.press(session.planned(candidate), exploring=True)
            shown = probe.observed(name)
            if not probe.feedback.accepted or shown is MISSING or shown == before:
                continue
            effect = self._effect_shown(feature, index, before, shown)
            back = {"next": "prev", "prev": "next"}.get(effect) if isinstance(effect, str) else None
            try:
                new = move_action(session.belief.model, candidate, pointer, effect)
                if back is not None:
                    new = set_effects(new, feature, index, {stuck.name: back})
            except RepairError as exc:
                session.episode.log("repair", f"could not move {candidate}: {exc}")
                continue
            note = f"{candidate} belongs to {feature} ({effect})"
            if back is not None:
                note += f", and {stuck.name} goes the other way ({back})"
            session.adopt(new, note, pointer)
            session.belief.set_value(name, shown)
            return True
        return self._entry_then_steppers(name, pointer, stuck)

    def _entry_then_steppers(
        self, name: str, pointer: tuple[str, int], stuck: PlannedAction
    ) -> bool:
        """The step's only key brings the setting up and leaves it as it is: it may be an
        entry key, with the panel's stepping keys (+ and − of another procedure) adjusting
        the setting after it. With the setting on the display (brought up again after a probe
        took it away), press each such pair's first key once (three at most); the first that
        moves it makes the step an entry press followed by that pair's step. Only for a key
        believed to step the setting: a toggle pressed again would undo itself."""
        session = self.session
        model = session.belief.model
        feature, index = pointer
        if model.features[feature][index].actions != [stuck.name]:
            return False
        if session.effect(pointer, stuck.name) not in ("next", "prev"):
            return False  # a toggle pressed again would undo itself (a switch off)
        if session.shown(name) in (MISSING, None):
            return False  # the key left the setting off the display: no stepping to see
        pairs = []
        for other, steps in model.features.items():
            for j, step in enumerate(steps):
                if (other, j) == pointer or step.variable is None:
                    continue
                effects = {a: session.effect((other, j), a) for a in step.actions}
                moving = {a: str(e) for a, e in effects.items() if e in ("next", "prev")}
                fits = moving and stuck.name not in moving and set(moving) <= session.offered
                if fits and moving not in pairs:
                    pairs.append(moving)
        for moving in pairs[:3]:
            before = session.shown(name)
            if before in (MISSING, None):  # a probe took the display elsewhere: bring it back
                before = session.press(stuck, exploring=True).observed(name)
                if before in (MISSING, None):
                    return False
            key = next(iter(moving))
            probe = session.press(session.planned(key), exploring=True)
            shown = probe.observed(name)
            if not probe.feedback.accepted or shown is MISSING or shown in (None, before):
                continue
            effect = self._effect_shown(feature, index, before, shown)
            if effect not in ("next", "prev"):
                continue
            flip = {"next": "prev", "prev": "next"}
            mapping = moving if effect == moving[key] else {a: flip[e] for a, e in moving.items()}
            try:
                new = entry_then_keys(model, feature, index, mapping)
            except RepairError as exc:
                session.episode.log("repair", f"could not make {stuck.name} an entry: {exc}")
                return False
            keys = ", ".join(mapping)
            session.adopt(
                new, f"{stuck.name} only brings {name} up; {keys} adjust it", (feature, index + 1)
            )
            session.belief.set_value(name, shown)
            return True
        return False

    def plausibly_moved(self, done: Executed) -> bool:
        """Whether another setting came up and changed as one of its own keys would change it
        (set, one step either way, or not at all): the key is filed under the wrong procedure,
        rather than the belief printing its own setting wrong."""
        seen = done.seen
        if seen is None or seen.screen_kind != "focus" or done.state_before is None:
            return False
        target = seen.screen
        if target is None or target == done.variable:
            return False
        places = [
            (f, i)
            for f, steps in self.session.belief.model.features.items()
            for i, step in enumerate(steps)
            if step.variable == target
        ]
        if not places:
            return False
        before = self.session.belief.compiled.value(done.state_before, target)
        shown = seen.observed(target)
        feature, index = places[0]
        effect = self._effect_shown(feature, index, before, shown)
        values = self.session.domain_values(target)
        return (
            effect in ("none", "prev")
            or isinstance(effect, dict)
            or (
                effect == "next"
                and before in values
                and shown in values
                and values[(values.index(before) + 1) % len(values)] == shown
            )
        )

    def _effect_shown(self, feature: str, index: int, before: Any, shown: Any) -> Any:
        """What the key did to the step's setting, as the display showed it: set it (the step's
        other keys set values too), stepped it one way or the other, or only showed it."""
        model = self.session.belief.model
        step = model.features[feature][index]
        effects = [self.session.effect((feature, index), a) for a in step.actions]
        if shown == before or shown is MISSING or shown is None:
            return "none"
        if any(isinstance(e, GoTo) for e in effects):
            return {"to": shown}
        values = self.session.domain_values(step.variable or "")
        if before in values and shown in values:
            i, j = values.index(before), values.index(shown)
            if (i + 1) % len(values) == j:
                return "next"
            if (j + 1) % len(values) == i:
                return "prev"
        return "next"

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

    def doubled_keys(self) -> list[str]:
        """Keys the belief files beside another key of the same step with the same effect: a
        second key doing exactly what the first does is more likely one misfiled there."""
        found = []
        for feature, steps in self.session.belief.model.features.items():
            for index, step in enumerate(steps):
                effects = [(a, self.session.effect((feature, index), a)) for a in step.actions]
                for i, (action, effect) in enumerate(effects):
                    if any(effect == other for _, other in effects[:i]):
                        found.append(action)
        return [a for a in found if a in self.session.offered]

    def keys_like(self, name: str, exclude: set[str]) -> list[str]:
        """Keys of the panel whose names share a word with ``name`` (``press_timer`` for
        ``timer``, ``set_timer``): an entry key filed under another procedure."""
        words = {w for w in name.split("_") if len(w) >= 3 and w not in ("set", "press")}
        found = []
        for action in self.session.belief.model.actions:
            if action in exclude or action not in self.session.offered:
                continue
            if self._locks(action):
                continue  # a lock hold named like the setting (hold TIMER ▲) would lock out
            parts = set(action.split("_"))
            if words & parts or any(
                w.startswith(p) or p.startswith(w) for w in words for p in parts if len(p) >= 3
            ):
                found.append(action)
        return found[:4]

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
        keys = self.keys_like(name, exclude=set())
        if any(word in name for word in _RUN_WORDS):
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
            if self.learn_side_effect(name, probe, observed):
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
        used = set(self.orphans())
        firsts = {a for f in features for a in self.session.belief.model.features[f][0].actions}
        for candidate in dict.fromkeys([*used, *self.keys_like(name, exclude=firsts)]):
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

    def _locks(self, action: str) -> bool:
        """Whether the belief says ``action`` puts the panel under a guard (locks it, switches
        it off) from where it is now."""
        compiled = self.session.belief.compiled
        index = compiled.action_index.get(action)
        if index is None:
            return False
        state = self.session.belief.state
        after = compiled.apply(state, index, compiled.hold_seconds[index] or None)
        if after is None:
            return False

        def holding(values: tuple[int, ...]) -> int:
            return sum(
                all(values[v] in ok for v, ok in guard.conditions) for guard in compiled.guards
            )

        return holding(after.values) > holding(state.values)

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
        others += self.keys_like(name, exclude=inside | {steps[0].actions[0]})
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

    def learn_side_effect(self, name: str, done: Executed, observed: Any) -> bool:
        """A press of another setting's step changed ``name`` otherwise than the belief said:
        the step leaves it alone (the display kept the value), sets it to what was shown, or
        resets it to its starting value — once per step and setting."""
        session = self.session
        if done.pointer is None or done.state_before is None or done.refused:
            return False
        if observed is MISSING or observed is UNREADABLE or observed is None:
            return False
        seen = done.seen
        if seen is None or seen.blank or name not in seen.values or seen.values[name] != observed:
            return False  # a dark panel shows no lamp; a value the setting cannot have is no set
        feature, index = done.pointer
        step = session.belief.model.features[feature][index]
        if step.variable == name or name not in session.belief.model.variables:
            return False
        if name in session.discovered:
            return False  # what it depends on is a guess
        kept = done.shown_before.get(name, MISSING) == observed  # as last shown: untouched
        if name in done.unseen_before and not kept:
            return False  # what it was before is a guess: the change may be older
        compiled = session.belief.compiled
        before = compiled.value(done.state_before, name)
        initial = session.belief.initial_value(name, done.state_before)
        value, reset = None, False
        if observed == before:
            if name not in step.set and name not in step.reset:
                return False
            change = "leaves it alone"
        elif observed == initial:
            reset, change = True, "resets it"
        else:
            value, change = observed, f"sets it to {observed}"
        if not session.budget.once("side", f"{feature}:{index}:{name}"):
            return False
        try:
            new = set_side_effect(session.belief.model, feature, index, name, value, reset)
        except RepairError as exc:
            session.episode.log("repair", f"could not change {feature}'s side effect: {exc}")
            return False
        session.adopt(new, f"{feature}: {done.action.name} {change} ({name})", done.pointer)
        session.belief.set_value(name, observed)
        return True

    def independent(self, name: str, done: Executed, observed: Any) -> bool:
        """A setting found on the panel, guessed to depend on the programme, shows again the
        value it showed before a programme change the belief said would reset it: it does not
        depend on the programme (once)."""
        session = self.session
        spec = session.belief.model.variables.get(name)
        if spec is None or spec.depends_on is None or name not in session.discovered:
            return False
        if observed is MISSING or done.shown_before.get(name, MISSING) != observed:
            return False
        case = session.case(name)
        if case is None or not session.budget.once("side", f"independent:{name}"):
            return False
        try:
            new = drop_dependence(session.belief.model, name, case)
        except RepairError as exc:
            session.episode.log("repair", f"could not make {name} independent: {exc}")
            return False
        session.adopt(
            new, f"{name} keeps its value whatever the {spec.depends_on}", session.belief.pointer()
        )
        session.belief.set_value(name, observed)
        return True

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
        """Keys the appliance offers that no feature of the belief uses, nor its keys that
        act from anywhere, nor a wait (at most eight)."""
        model = self.session.belief.model
        used = {a for steps in model.features.values() for s in steps for a in s.actions}
        used |= {a for entry in model.anywhere for a in entry.actions}
        used |= {a for a, spec in model.actions.items() if spec.skill == "wait"}
        return [
            a
            for a in self.session.belief.model.actions
            if a not in used and a in self.session.offered
        ][:8]
