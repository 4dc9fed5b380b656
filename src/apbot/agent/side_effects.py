"""Side effects the display contradicted, and steps a key was shown to belong to.

A press of one procedure changed another setting otherwise than its step says: the step's
``set`` or ``reset`` is written as the display showed it. A setting found on the panel that kept
its value through a programme change does not depend on the programme. A key meant to start a
new procedure that changed nothing is one more step of the procedure in progress.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.repair import (
    RepairError,
    drop_dependence,
    insert_step,
    set_side_effect,
    set_start,
)
from apbot.agent.session import MISSING, UNREADABLE, Executed, Session

__all__ = ["SideEffectLearner"]


class SideEffectLearner:
    """Write into the belief what a press was shown to do beyond its own step."""

    def __init__(self, session: Session) -> None:
        self.session = session

    def learn_side_effect(self, name: str, done: Executed, observed: Any) -> bool:
        """A press of another setting's step changed ``name`` otherwise than the belief said:
        the step leaves it alone (the display kept the value), sets it to what was shown, or
        resets it to its starting value — once per step, setting and kind of change, so that a
        later press of the same step that contradicts what was learnt revises it (an entry key
        first seen showing the programme's time, "sets it to 8:00", then showing 0:30 where a
        walk left it: it leaves it alone)."""
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
        kind = "alone" if value is None and not reset else "reset" if reset else "set"
        if not session.budget.once("side", f"{feature}:{index}:{name}:{kind}"):
            return False
        if not session.try_repair(
            lambda: set_side_effect(session.belief.model, feature, index, name, value, reset),
            f"{feature}: {done.action.name} {change} ({name})",
            done.pointer,
            refused=f"could not change {feature}'s side effect",
        ):
            return False
        session.belief.set_value(name, observed)
        return True

    def programme_start(self, name: str, done: Executed, observed: Any) -> bool:
        """A setting that depends on the programme, changed unseen by a programme choice the
        belief says starts it at the case's first value, is first shown by a press believed
        to leave it as it is (an entry key that only shows it) with another value of that
        case: the programme starts it there (a manual's "starting power" column the reader
        missed). Without it the planner keeps choosing the programme again to bring the
        setting back to a start the appliance never gives (once per setting and case)."""
        session = self.session
        spec = session.belief.model.variables.get(name)
        if spec is None or spec.depends_on is None or done.state_before is None:
            return False
        if name in session.discovered:
            return False  # what it depends on is a guess
        if name in done.shown_before and name not in done.unseen_before:
            return False  # the display has shown it since it last changed
        if observed in (MISSING, UNREADABLE, None) or done.refused:
            return False
        compiled = session.belief.compiled
        before = compiled.value(done.state_before, name)
        if before != session.belief.initial_value(name, done.state_before):
            return False  # the belief did not put it at the programme's start
        if name not in done.surprises or done.surprises[name][0] != before:
            return False  # the press was believed to move it: its start is not what it shows
        if observed not in session.domain_values(name):
            return False
        case = session.case(name)
        if case is None or not session.budget.once("side", f"start:{name}:{case}"):
            return False
        if not session.try_repair(
            lambda: set_start(session.belief.model, name, case, observed),
            f"{name} starts at {observed} in {spec.depends_on} {case}",
            session.belief.pointer(),
            refused=f"could not change {name}'s start",
        ):
            return False
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
        if not session.try_repair(
            lambda: drop_dependence(session.belief.model, name, case),
            f"{name} keeps its value whatever the {spec.depends_on}",
            session.belief.pointer(),
            refused=f"could not make {name} independent",
        ):
            return False
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
