"""A key filed under the wrong procedure, found from where the display says it went.

When a key brings up another setting than the belief's step, or a walk stays stuck on one value,
the key belongs elsewhere — or the key that walks the setting back is filed under another
procedure, or the stuck key only enters the setting and the panel's stepping pair adjusts it.
"""

from __future__ import annotations

from apbot.agent.keys import effect_shown, keys_like
from apbot.agent.repair import RepairError, entry_then_keys, move_action, set_effects
from apbot.agent.session import MISSING, Executed, Session
from apbot.model.schema import ApplianceModel
from apbot.plan.plan import PlannedAction

__all__ = ["KeyMover"]


class KeyMover:
    """Move a key to the procedure the display showed it belongs to."""

    def __init__(self, session: Session) -> None:
        self.session = session

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
        if _held_too(model, done):
            return False
        before = session.belief.compiled.value(done.state_before, target)
        shown = seen.observed(target)
        if (first or entered)[0] in first:
            feature, index = first[0]
            effect = effect_shown(self.session, feature, index, before, shown)
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
        for candidate in keys_like(self.session, name, exclude=set(step.actions)):
            before = session.belief.value(name)
            probe = session.press(session.planned(candidate), exploring=True)
            shown = probe.observed(name)
            if not probe.feedback.accepted or shown is MISSING or shown == before:
                continue
            effect = effect_shown(self.session, feature, index, before, shown)
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
        took it away), press each key of such a pair once (three pairs at most); the first that
        moves it makes the step an entry press followed by that pair's step. Only for a key
        believed to step the setting: a toggle pressed again would undo itself."""
        session = self.session
        model = session.belief.model
        feature, index = pointer
        if model.features[feature][index].actions != [stuck.name]:
            return False
        if session.effect(pointer, stuck.name) not in ("next", "prev"):
            return False  # a toggle pressed again would undo itself (a switch off)
        # a probe of a key named like it may have taken the display elsewhere: bring it back
        if session.shown(name) in (MISSING, None) and session.press(stuck, exploring=True).observed(
            name
        ) in (MISSING, None):
            return False  # the key leaves the setting off the display: no stepping to see
        # a lone key that cycles the programme is no stepping pair: choosing another programme
        # moves the probed setting itself (to the new programme's start, or a fixed value)
        # and resets others. A dial that turns both ways may well adjust the setting too
        parents = {v.depends_on for v in model.variables.values() if v.depends_on}
        pairs = []
        for other, steps in model.features.items():
            for j, step in enumerate(steps):
                if (other, j) == pointer or step.variable is None:
                    continue
                effects = {a: session.effect((other, j), a) for a in step.actions}
                moving = {a: str(e) for a, e in effects.items() if e in ("next", "prev")}
                choosing = step.variable in parents or step.set or step.reset
                if choosing and len(set(moving.values())) < 2:
                    continue
                fits = moving and stuck.name not in moving and set(moving) <= session.offered
                if fits and moving not in pairs:
                    pairs.append(moving)
        # each key of a pair in turn: the setting may be at the end the first one goes to
        for moving, key in [(m, k) for m in pairs[:3] for k in m]:
            before = session.shown(name)
            if before in (MISSING, None):  # a probe took the display elsewhere: bring it back
                before = session.press(stuck, exploring=True).observed(name)
                if before in (MISSING, None):
                    return False
            probe = session.press(session.planned(key), exploring=True)
            shown = probe.observed(name)
            if not probe.feedback.accepted or shown is MISSING or shown in (None, before):
                continue
            effect = effect_shown(self.session, feature, index, before, shown)
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
        effect = effect_shown(self.session, feature, index, before, shown)
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


def _held_too(model: ApplianceModel, done: Executed) -> bool:
    """The step also has the key's other touch (▼ pressed and ▼ held for a bigger step of
    the same setting): the key is that setting's stepping key; a screen taken for another
    setting's says nothing against it (moving one touch alone would split the key)."""
    if done.pointer is None:
        return False
    feature, index = done.pointer
    action = model.actions.get(done.action.name)
    if action is None or action.control is None:
        return False
    return any(
        other != done.action.name
        and (a := model.actions.get(other)) is not None
        and "hold" in (a.skill, action.skill)
        and a.control == action.control
        for other in model.features[feature][index].actions
    )
