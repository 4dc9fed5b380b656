"""The guard learner: explain, lift and learn the conditions under which keys do not work.

A refusal the belief can explain by one of its guards (the display shows that guard's message)
tells where the appliance is: the lock is on, the knob at OFF. A refusal — or a key ignored
without a sign — that no guard of the belief explains is a guard the reader missed or got wrong:
a key the belief's guard lets through is struck from it; otherwise the learner looks for the
setting that blocks the key (a switched-off appliance behind a dark display, a lock behind a
beep), changes it, presses the key again, and writes the guard it found into the belief.
Bringing the appliance out of the guards the belief thinks hold is in guards_lift.py.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.agent.guards_lift import GuardLifter
from apbot.agent.locks import believe_lock_shown, blocking_words
from apbot.agent.repair import RepairError, add_guard, allow, allow_all, disallow
from apbot.agent.session import MISSING, Executed, Session
from apbot.model.display import OFF_WORDS
from apbot.model.schema import DiscreteVariable
from apbot.plan.plan import Unreachable, plan
from apbot.sim.compiled import CompiledModel

LEARNT = "learnt"  # the name of a guard the agent wrote into the belief
ON_WORDS = frozenset({"on", "locked", "lock", "yes", "true", "enabled", "running"})
MAIN_SWITCHES = frozenset({"power", "on_off", "main_switch", "standby"})
RUN_WORDS = ("running", "cooking", "brewing", "heating", "washing", "blending")
MAX_SUSPECTS = 3  # settings tried as the cause of one refusal
MAX_RELAXATIONS = 12  # guard/key pairs tried when a guard keeps the goal out of reach
RELAX_BUDGET = 1_000  # search nodes for each (5,000 took 40 of 210 s on read beliefs, won nothing)


class GuardLearner(GuardLifter):
    """Explain refusals by the belief's guards; learn the guards it lacks."""

    def __init__(self, session: Session) -> None:
        self.session = session
        # (guard condition, key) pairs seen refused: no relaxation may suppose them allowed
        self.witnessed: set[tuple[str, str]] = set()
        # on the belief ``_hopeless_on``: (state, goal) pairs no relaxation can help, and the
        # goals every relaxation was tried for in vain, with the count of display moves
        # (``Session.moved``) then: a value the display moved is a new question
        self._hopeless_on: CompiledModel | None = None
        self._hopeless_for: set[tuple[Any, str]] = set()
        self._tried_for: dict[str, int] = {}

    def explain(self, refused: Executed) -> bool:
        """A refusal whose display is one of the belief's guard messages: believe that guard
        holds (the knob is at OFF, the lock is on) and let the planner lift it."""
        compiled = self.session.belief.compiled
        action = compiled.action_index.get(refused.action.name)
        text = refused.feedback.text.strip()
        shown = self._guards_shown(text)
        for index, guard in enumerate(compiled.guards):
            if action in guard.allowed or index not in shown:
                continue
            if all(self.session.belief.state.values[v] in ok for v, ok in guard.conditions):
                return False  # the belief already knew: something else is wrong
            if not self.session.budget.once("guard", guard.name or guard.display):
                return False
            for v, ok in guard.conditions:
                domain = compiled.vars[v].domain(self.session.belief.state.values)
                if domain is not None:
                    self.session.belief.set_value(compiled.vars[v].name, domain.values[min(ok)])
            self.session.episode.log(
                "repair", f"refused with {text!r}: the appliance must be in '{guard.name or text}'"
            )
            self.witnessed.add(
                (_condition(self.session.belief.model.guards[index].when), refused.action.name)
            )
            return True
        return believe_lock_shown(self.session, refused)  # a lock word its guard lacks

    def _guards_shown(self, text: str) -> set[int]:
        """The belief's guards whose screen this text is (a message, or a dark panel)."""
        reading = self.session.perceiver.reader.read(text, self.session.belief.values())
        return {h.screen.guard for h in reading.hypotheses if h.screen.guard is not None}

    def learn(self, failed: Executed) -> bool:
        """A key refused (or ignored) that no guard of the belief explains: strike it from a
        guard that wrongly allows it, or find the setting that blocks it. True if the belief
        changed."""
        return self._disallow(failed) or self._find_blocking(failed)

    def _disallow(self, failed: Executed) -> bool:
        """A guard of the belief holds and lists the refused key as allowed: it is not."""
        if not failed.refused:
            return False
        session = self.session
        compiled = session.belief.compiled
        action = compiled.action_index.get(failed.action.name)
        text = failed.feedback.text.strip()
        for index, guard in enumerate(compiled.guards):
            holds = all(session.belief.state.values[v] in ok for v, ok in guard.conditions)
            if not holds or action not in guard.allowed:
                continue
            if guard.display and index not in self._guards_shown(text):
                continue
            if not session.budget.once("guard", f"disallow:{index}:{failed.action.name}"):
                return False
            try:
                new = disallow(session.belief.model, index, failed.action.name)
            except RepairError as exc:
                session.episode.log("repair", f"could not change guard {index}: {exc}")
                return False
            session.adopt(
                new,
                f"{guard.name or 'guard ' + str(index)} does not let {failed.action.name} work",
                session.belief.pointer(),
            )
            self.witnessed.add((_condition(new.guards[index].when), failed.action.name))
            return True
        return False

    def _find_blocking(self, failed: Executed) -> bool:
        """Change each setting that could block the key (an off switch behind a dark display,
        an on lock behind a refusal) and press the key again; the one after which it works is
        the guard."""
        session = self.session
        dark = not failed.feedback.text.strip()
        if dark or failed.refused:
            suspects = self._suspects(dark, action=failed.action.name)
            if not dark:  # a refusal on a lit display: also a main switch at off (standby)
                switches = {n for n in session.belief.model.variables if n in MAIN_SWITCHES}
                suspects += self._suspects(True, switches, action=failed.action.name)
        elif failed.unchanged:  # ignored without a sign on a lit display: a switch at off
            # (standby) that some guard of the belief already tests
            tested = {n for guard in session.belief.model.guards for n in guard.when}
            # or the main switch, whose guard the reader may have missed altogether
            tested |= {n for n in session.belief.model.variables if n in MAIN_SWITCHES}
            suspects = self._suspects(True, tested) + self._cycles_on()
        else:
            return False  # another screen came up: a procedure's step, not a guard
        silent = not (dark or failed.refused)
        for name, blocking in suspects[:MAX_SUSPECTS]:
            if not session.budget.once("guard", f"learn:{failed.action.name}:{name}"):
                continue
            other = next(v for v in session.domain_values(name) if v != blocking)
            keep = {  # change only the suspect: leave every other guard's setting as it is
                u: session.belief.value(u)
                for guard in session.belief.model.guards
                for u in guard.when
                if u != name and session.belief.value(u) is not None
            }
            try:
                route = plan(session.belief.compiled, session.belief.state, {**keep, name: other})
            except Unreachable:
                try:  # the suspect cannot change alone (switching on clears a start time)
                    route = plan(session.belief.compiled, session.belief.state, {name: other})
                except Unreachable:
                    continue
            key = failed.action.name
            if self._refusing_after(route.actions, key) > self._refusing_after([], key):
                continue  # it would lock the key out (a child lock put on): no way to unblock
            lifting = [a.name for a in route.actions]
            for planned in route.actions:
                session.press(planned, exploring=True)
            before = session.last.text
            retry = session.press(failed.action, exploring=True)
            if retry.feedback.accepted and retry.feedback.text == before:
                retry = self._again(retry)  # the screen it came to was up already: once more
            # a key the belief does not know at all (a setting's it lacks) works if it lit
            known = retry.believed_accepted or retry.action.name not in session.belief.model.actions
            if (
                not (known and retry.feedback.accepted)
                or retry.unchanged
                or retry.feedback.text == before
                or (dark and not retry.feedback.text.strip())  # dark again: it did not work
                or (retry.surprises and retry.variable not in retry.surprises)
                or (silent and retry.surprises)  # a lit panel: only what the belief predicted
            ):
                continue
            try:
                new = add_guard(
                    session.belief.model,
                    {name: blocking},
                    sorted(set(lifting) | self._switching(name)),
                    "" if dark or silent else _main_text(failed.feedback.text, session),
                    hide=dark,
                )
            except RepairError as exc:
                session.episode.log("repair", f"could not add a guard on {name}: {exc}")
                continue
            session.adopt(
                new,
                f"while {name} is {blocking}, {failed.action.name} does not work",
                session.belief.pointer(),
            )
            self.witnessed.add((_condition({name: blocking}), failed.action.name))
            return True
        return False

    def _refusing_after(self, actions: list[Any], key: str) -> int:
        """How many of the belief's guards would refuse ``key`` after ``actions`` from the
        believed state."""
        compiled = self.session.belief.compiled
        state = self.session.belief.state
        for planned in actions:
            index = compiled.action_index.get(planned.name)
            after = None if index is None else compiled.apply(state, index, planned.seconds)
            if after is None:
                break
            state = after
        refused = compiled.action_index.get(key)
        return sum(
            all(state.values[v] in ok for v, ok in guard.conditions)
            and refused not in guard.allowed
            for guard in compiled.guards
        )

    def _again(self, retry: Executed) -> Executed:
        """A key pressed again after a retry that left the display as it was: if the setting
        it shows moves, the key works (a first press that only shows the setting, on a screen
        that was showing it already) — the retry counts as the second press."""
        name = retry.variable
        shown = retry.observed(name) if name else None
        if name is None or shown is MISSING or shown is None:
            return retry
        again = self.session.press(retry.action, exploring=True)
        moved = again.observed(name)
        return again if moved is not MISSING and moved != shown else retry

    def _suspects(
        self, dark: bool, tested: set[str] | None = None, action: str | None = None
    ) -> list[tuple[str, Any]]:
        """Two-valued settings at a value that plausibly blocks keys: off behind a dark display
        (``dark``), on (a lock, a running cycle) behind a refusal. With ``tested``: only those
        settings, whatever guards their other value has (a key ignored without a sign)."""
        words = OFF_WORDS if dark else ON_WORDS
        suspects = []
        model = self.session.belief.model
        guarded = {  # a switch whose other value has a guard of its own that would refuse
            # ``action`` too (a lock on, not off); one letting it through (power on) proves nothing
            name: {str(v) for v in (w if isinstance(w, list) else [w])}
            for guard in model.guards
            if len(guard.when) == 1 and (action is None or action not in guard.only)
            for name, w in guard.when.items()
        }
        for name, spec in model.variables.items():
            if not isinstance(spec, DiscreteVariable) or spec.depends_on is not None:
                continue
            if tested is not None:
                if name not in tested:
                    continue
            elif name in guarded and str(self.session.belief.value(name)) not in guarded[name]:
                continue
            value = self.session.belief.value(name)
            if value is None or str(value).casefold() not in blocking_words(name, dark, words):
                continue
            # a switch; or, behind a dark display, a selector at its OFF position (a knob)
            two = len(self.session.domain_values(name)) == 2
            if (two or (dark and str(value).casefold() == "off")) and self._switching(name):
                suspects.append((name, value))
        # a setting some guard already tests (power, a lock) first: it is known to block keys
        tested = {n for guard in model.guards for n in guard.when}
        return sorted(suspects, key=lambda suspect: suspect[0] not in tested)

    def _cycles_on(self) -> list[tuple[str, Any]]:
        """Run states that are on (a cycle running), which a key that did nothing without a
        sign may be locked out by: most appliances lock their settings while they run."""
        found = []
        for name, spec in self.session.belief.model.variables.items():
            if not isinstance(spec, DiscreteVariable) or spec.depends_on is not None:
                continue
            if not any(word in name for word in RUN_WORDS):
                continue
            value = self.session.belief.value(name)
            values = self.session.domain_values(name)
            if str(value).casefold() not in ON_WORDS or str(values[0]).casefold() not in OFF_WORDS:
                continue
            if self._switching(name):
                found.append((name, value))
        return found

    def _switching(self, name: str) -> set[str]:
        """The keys of the steps that change ``name`` itself."""
        model = self.session.belief.model
        return {
            a
            for steps in model.features.values()
            for s in steps
            if s.variable == name
            for a in s.actions
        }

    def relax(self, target: dict[str, Any]) -> bool:
        """The goal is out of reach on the belief because a guard blocks a key it needs (lock
        the keys while running, start while locked): suppose the guard lets that key through,
        if that makes the goal reachable (once each). A refusal later takes it back."""
        session = self.session
        model = session.belief.model
        tested = {n for guard in model.guards for n in guard.when}
        steps = [s for feature in model.features.values() for s in feature]
        # the keys of the locks and run states first (start while locked, lock while running)
        needed = sorted(
            {a for s in steps if s.variable in target for a in s.actions},
            key=lambda a: (not any(s.variable in tested for s in steps if a in s.actions), a),
        )
        # a guard the agent wrote itself guessed every other key refused; the reader's own
        # guards come from the manual: suppose the guess wrong first
        order = sorted(enumerate(model.guards), key=lambda item: item[1].name != LEARNT)
        candidates = [
            (index, action)
            for action in needed
            for index, guard in order
            if action not in guard.only and (_condition(guard.when), action) not in self.witnessed
        ][:MAX_RELAXATIONS]
        if self._hopeless_on is not session.belief.compiled:
            self._hopeless_on = session.belief.compiled
            self._hopeless_for, self._tried_for = set(), {}
        goal = repr(sorted(target.items()))
        # each guess tried in vain for this goal on this belief: the same guards keep it out
        # from the next state too (another plan cycle, the same failure) — until a repair, or
        # the display moves a value where the belief's transitions do not lead
        tried = self._tried_for.get(goal) == session.moved
        if tried or not candidates or self._hopeless(candidates, target):
            return False
        cut = False  # a search gave up at its budget: that guess is untried, not in vain
        for index, action in candidates:
            try:
                variant = allow(model, index, action)
                # a small search each: the variant is a guess, and a throwaway compilation
                plan(CompiledModel(variant), session.belief.state, target, RELAX_BUDGET)
            except RepairError:
                continue
            except Unreachable as exc:
                cut = cut or exc.budget_hit
                continue
            if not session.budget.once("guard", f"relax:{index}:{action}"):
                continue
            guard = model.guards[index]
            label = guard.name or f"guard {index}"
            session.adopt(
                variant, f"{label} may let {action} work (to be seen)", session.belief.pointer()
            )
            return True
        if not cut:
            self._tried_for[goal] = session.moved
        return False

    def _hopeless(self, candidates: list[tuple[int, str]], target: dict[str, Any]) -> bool:
        """Whether no single relaxation can make ``target`` reachable: the model with all of
        them at once (which can do whatever any one can) has no plan — a value no key leads
        to, or a search that ran out, not one that gave up. One search instead of a dozen
        speculative ones, remembered for the same belief, state and goal (the caller resets
        the memory when the belief changes)."""
        session = self.session
        key = (session.belief.state, repr(sorted(target.items())))
        if key in self._hopeless_for:
            return True
        try:
            union = allow_all(session.belief.model, candidates)
            plan(CompiledModel(union), session.belief.state, target, RELAX_BUDGET)
        except RepairError:
            return False
        except Unreachable as exc:
            if exc.budget_hit:
                return False  # too costly to say: try them one by one
            self._hopeless_for.add(key)
            return True
        return False


def _condition(when: dict[str, Any]) -> str:
    """A guard's condition as a key (the same whatever the guard is called)."""
    return repr(sorted((name, str(value)) for name, value in when.items()))


def _main_text(text: str, session: Session) -> str:
    """A refusal's message without the lamps the belief knows after it."""
    parts = re.split(r"\s{2,}", text.strip())
    lamps = session.perceiver.reader.lamp_texts()
    while len(parts) > 1 and parts[-1].casefold() in lamps:
        parts.pop()
    return "  ".join(parts)
