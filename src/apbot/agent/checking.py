"""The check after each macro action, and the repairs it dispatches.

After every macro action the closed loop compares what the display showed after each press
with what the belief predicted; the first press that surprised it says which collaborator
repairs the belief (a lamp that is no lamp, a procedure split or entered wrongly, a key filed
under another procedure, a display rule, a guard, a value's definition). Kept apart from the
loop's planning (:mod:`apbot.agent.loop`), which it shares one :class:`Session` with.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.absent import absent_here
from apbot.agent.blocked import blocked_by_manual
from apbot.agent.closing import learn_closing
from apbot.agent.displays import DisplayLearner
from apbot.agent.ends import stopped_at_end
from apbot.agent.explorer import Explorer
from apbot.agent.guards import GuardLearner
from apbot.agent.merged import ProcedureSplitter
from apbot.agent.misfiled import KeyMover
from apbot.agent.mismatch import shown_otherwise, wrong_setting
from apbot.agent.procedures import ProcedureRepairer
from apbot.agent.quantities import loose
from apbot.agent.relit import relit
from apbot.agent.session import MISSING, UNREADABLE, AgentConfig, Executed, Session, Stop
from apbot.agent.side_effects import SideEffectLearner
from apbot.model.schema import GoTo
from apbot.plan.plan import MacroAction


class Checks:
    """The loop's checks and repairs (a part of :class:`apbot.agent.loop.ClosedLoop`)."""

    session: Session
    config: AgentConfig
    displays: DisplayLearner
    explorer: Explorer
    guards: GuardLearner
    procedures: ProcedureRepairer
    movers: KeyMover
    side_effects: SideEffectLearner
    splitter: ProcedureSplitter
    values_before: dict[str, Any]

    def goal(self) -> tuple[dict[str, Any], dict[str, Any]]:
        raise NotImplementedError  # the loop's: the goal split by what the belief has

    def explore(self, name: str, last: Executed, history: list[Any] | None = None) -> None:
        raise NotImplementedError  # the loop's: walk a setting with a key

    def inspect(self, name: str) -> bool:
        raise NotImplementedError  # the loop's: walk a setting the belief cannot reach

    def check(self, macro: MacroAction, executed: list[Executed]) -> bool:
        """Compare what the display showed with what the belief predicted, press by press;
        repair on a mismatch. True when all was as predicted (the rest of the plan holds)."""
        if not self.config.closed_loop:
            return True
        first = next((i for i, e in enumerate(executed) if e.surprises or e.refused), None)
        if first is None:
            self.session.episode.log("check", "ok", expected=dict(macro.expect))
            self.session.budget.works("value", {e.variable for e in executed if e.variable})
            self.session.budget.works("procedure", {macro.feature})
            outside = self.goal()[1]
            return not (outside and self._look_at(outside))
        done = executed[first]
        self.session.episode.log(
            "check",
            "mismatch",
            expected={n: p for n, (p, _) in done.surprises.items()},
            values={
                n: "(unreadable)" if o is UNREADABLE else o for n, (_, o) in done.surprises.items()
            },
        )
        if blocked_by_manual(self.session, done):
            pass  # the manual says what blocks the key: plan again, lifting it first
        elif not done.refused and self.displays.no_lamp(done):
            pass  # plan again, reading the setting on its own screen only
        elif relit(self.session, done):
            pass  # the lamp's words were learnt from the press that switched it
        elif not done.refused and self.splitter.split(done):
            pass  # plan again with the procedure the key really starts
        elif (
            not done.refused
            and (feature := self.splitter.misentered(done)) is not None
            and self.procedures.find_entry(feature)
        ):
            pass  # the procedure lacked its entry key: found
        elif (
            not done.refused and self.movers.plausibly_moved(done) and (self.movers.move_key(done))
        ):
            pass  # plan again with the key where it belongs
        elif not done.refused and shown_otherwise(self.session, done):
            assert done.variable is not None and done.pointer is not None
            # the key is the setting's own, and the screen that came up belongs to a setting
            # no step of which has this key: more likely the belief prints the setting wrong
            if self.session.stepping(done.pointer, done.action.name):
                self.explore(done.variable, done)
            else:
                self._learn_display(done.variable, executed[: first + 1])
        elif learn_closing(self.session, done):
            pass  # the key closes the procedure typed last: plan again from there
        elif stopped_at_end(self.session, done):
            pass  # plan again the long way round
        elif done.refused or wrong_setting(self.session, done):
            self.procedures.repair_procedure(executed[first:])
            name = self.session.step_variable(self.session.belief.pointer())
            key = self.explorer.stepping_key(name) if name else None
            if (
                name is not None
                and key is not None
                and self.session.shown(name)
                not in (
                    MISSING,
                    self.session.belief.value(name),
                )
            ):
                self.explore(name, key)  # the probe showed a value the belief cannot hold
        else:
            name = done.variable if done.variable in done.surprises else next(iter(done.surprises))
            predicted, observed = done.surprises[name]
            if observed is UNREADABLE and self._learn_display(name, executed[: first + 1]):
                pass  # read again and plan again with the repaired display rules
            else:
                self.repair_value(name, predicted, observed, executed, first)
        outside = self.goal()[1]  # a repair may have taught the belief the goal value
        self._look_at(outside)
        return False

    def _learn_display(self, name: str, executed: list[Executed]) -> bool:
        """The display showed text the belief cannot read where it expected ``name``: learn
        how the display prints it from the texts of the presses that adjusted it."""
        unread = [
            e
            for e in executed
            if e.variable == name
            and not e.typed  # the entry as typed says nothing of how the value is shown
            and e.seen is not None
            and e.seen.text.strip()
            and (e.seen.unknown or not e.seen.showing(name))
        ]
        if not unread:
            return False
        texts = [e.feedback.text for e in unread]
        if not self.displays.learn(name, texts, believed=unread[-1].predicted):
            return False
        value = self.displays.read(name, unread[-1].feedback.text)
        if value is not None:
            self.session.belief.set_value(name, value)
        self.session.reread()
        return True

    def _read_again(self, names: list[str]) -> bool:
        """A goal setting whose screen the last looks brought up as text the belief cannot
        read: learn how the display prints it from those texts (as after a macro action's
        press: an on/off lamp's word, :func:`relit`, or a template, :meth:`_learn_display`)
        rather than give up on it. True when the belief changed."""
        session = self.session
        for name in names:
            presses = session.unread_presses.get(name, [])
            if name not in session.unread:
                continue
            if (switched := _latest_switch(name, presses)) and relit(session, switched):
                return True  # an on/off lamp's word, from the look that switched it
            if not self._learn_display(name, presses):
                continue
            shown = self.displays.read(name, presses[-1].feedback.text)
            if (
                name in session.unread
                and shown is not None
                and not session.belief.set_value(name, shown)
            ):
                # read now, as a value the belief cannot hold: the walk settles it
                session.unread.discard(name)
                session.contradicted[name] = shown
            return True
        return False

    def _look_at(self, outside: dict[str, Any]) -> bool:
        focused = {
            name: raw
            for name, raw in outside.items()
            if self.session.shown(name) is not MISSING and name not in self.session.explored
        }
        if focused:
            self.explore_outside(focused)
        return bool(focused)

    def repair_value(
        self, name: str, predicted: Any, observed: Any, executed: list[Executed], upto: int
    ) -> None:
        """The display showed ``observed`` for ``name`` where the belief predicted otherwise."""
        self.session.again(
            "value",
            name,
            f"{name} keeps showing values the model does not predict (last: "
            f"{observed!r}, expected {predicted!r})",
            [name],
        )
        if self.side_effects.independent(name, executed[upto], observed):
            return
        if absent_here(self.session, name, executed[upto], observed):
            return
        if self.side_effects.programme_start(name, executed[upto], observed):
            return
        adjusting = [e for e in executed[: upto + 1] if e.variable == name and e.believed_accepted]
        if not adjusting:  # changed as a side effect: the step that did it says so now
            self.side_effects.learn_side_effect(name, executed[upto], observed)
            return
        last = adjusting[-1]
        assert last.pointer is not None
        unchanged = observed == self.values_before.get(name)
        first = next((e for e in executed[: upto + 1] if e.surprises), None)
        if (
            first is not None
            and first.variable == name
            and self.explorer.learn_on_entry(name, first)
        ):
            return
        if unchanged and self.side_effects.absorbed(adjusting[0]):
            return
        if first is not None and first.unchanged and self.guards.learn(first):
            return  # a key ignored without a sign: a guard the belief lacked (now learnt)
        effect = self.session.effect(last.pointer, last.action.name)
        if self.session.stepping(last.pointer, last.action.name):
            self.explore(name, last, self.explorer.history(name, last, executed))
        elif isinstance(effect, GoTo) and observed not in (None, UNREADABLE) and not unchanged:
            # (text the belief cannot read is no value the key goes to)
            self.explorer.learn_goto(name, last, observed)
        elif effect == "digit" and observed is not None:
            if self.explorer.learn_entry_format(name, last, observed, unchanged, adjusting):
                return
            shown = [e.observed(name) for e in executed[upto:]]
            self.explorer.widen(name, [observed, *(v for v in shown if v not in (MISSING, None))])
            self.settle_contradictions({name: None})

    def settle_contradictions(self, names: dict[str, Any]) -> bool:
        """A setting last shown with a value the belief cannot hold must not count as done:
        a keypad setting learns the value, another is walked again once (True: plan again);
        otherwise the run gives up."""
        settled = False
        for name in [n for n in self.session.contradicted if n in names]:
            value = self.session.contradicted.pop(name)
            spec = self.session.belief.model.variables[name]
            if getattr(spec, "entry", None) is not None:
                self.explorer.widen(name, [value])
                if self.session.belief.set_value(name, value):
                    settled = True
                    continue
            elif self.session.budget.once("inspect", f"contradicted:{name}"):
                # walk it again where it is now (another programme may have other values)
                key = self.explorer.stepping_key(name)
                if key is not None:
                    self.explore(name, key)
                    settled = True
                    continue
                if self.inspect(name):
                    settled = True
                    continue
            raise Stop(f"the display showed {name}={value!r}, which the belief cannot hold")
        return settled

    def explore_outside(self, outside: dict[str, Any]) -> None:
        """Look at a variable whose goal value the belief lacks: explore it, or for a keypad
        setting, allow the value and let the next check say whether it exists."""
        for name, raw in outside.items():
            spec = self.session.belief.model.variables[name]
            if getattr(spec, "entry", None) is not None:
                self.session.explored.add(name)
                value = loose(spec, raw)
                if value is not None:
                    self.explorer.widen(name, [value])
                continue
            key = self.explorer.stepping_key(name)
            if key is not None:
                self.explore(name, key)
            elif self.session.step_variable(self.session.belief.pointer()) == name:
                self.session.explored.add(
                    name
                )  # its setting is up, and no key walks it: seen it all


def _latest_switch(name: str, presses: list[Executed]) -> Executed | None:
    """The latest press that showed ``name`` other than predicted, when the display has not
    changed since (what it switched ``name`` to is still its value); an older one would set a
    stale value."""
    for i in range(len(presses) - 1, -1, -1):
        if name in presses[i].surprises:
            text = presses[i].feedback.text
            later = presses[i + 1 :]
            return presses[i] if all(p.feedback.text == text for p in later) else None
    return None
