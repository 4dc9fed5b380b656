"""The variable finder: a setting the goal names and the belief lacks altogether.

A reader can miss a setting entirely — its variable, its procedure, even its keys. The panel
still has the keys (the environment's action names), and the display still shows the setting
when one of them is pressed. The finder tries the keys the belief gives no role, those named
like the setting first; a key whose display the belief cannot read is walked until the text
repeats, and what varies from text to text is the setting's value
(:func:`apbot.agent.infer.infer_template`). From the walk it writes a new variable (its values
or ranges, unit, display template), the key's action and a one-step procedure into the belief —
a data edit the checker validates like any other. Which keys to try, and their walks, are
:mod:`apbot.agent.discovery_walks`.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.added_settings import unrole
from apbot.agent.discovery_walks import MAX_KEYS, KeyWalks
from apbot.agent.finder_keys import (
    _digit_keys,
    _is_digit,
    _main,
    _planned,
    _press_digit,
    _unknown,
)
from apbot.agent.guards import GuardLearner
from apbot.agent.reader import DisplayReader
from apbot.agent.reentry import typed_after_named
from apbot.agent.repair import (
    RepairError,
    add_choice_setting,
    add_indicator,
    add_keypad_setting,
    add_setting,
    plain_steps,
    setting_step,
)
from apbot.agent.session import Session
from apbot.agent.setting_texts import (
    GAP,
    _fits,
    _kind_of,
    _typing,
    day_walk,
    infer_setting,
    lamp_word,
    typed_setting,
)
from apbot.model.schema import DiscreteVariable

MAX_ADJUSTERS = 4  # keys tried after an entry key


class VariableFinder(KeyWalks):
    """Find a setting the belief lacks by pressing the keys it gives no role."""

    def __init__(self, session: Session, guards: GuardLearner) -> None:
        self.session = session
        self.guards = guards
        self.trail: list[str | None] = []  # the full texts of the last walk (None: refused)
        self.misread: set[str] = set()  # settings a walk showed the reader gave a wrong key
        self.suspect: list[str] = []  # keys named like the setting sought, their role unfit

    def find(self, name: str, goal_value: Any, attempt: int = 1) -> bool:
        """Look for ``name`` on the panel (once per attempt); True when the belief now has it.

        A key that brings up a screen the belief cannot read is walked; if it shows one screen
        only, it is an entry key ("press TIMER, then ▲/▼") and the panel's other keys are
        walked after it."""
        session = self.session
        if not session.budget.once("discover", f"{name}:{attempt}"):
            return False
        keys = self._candidates(name, goal_value)
        single: dict[str, str] = {}  # keys that showed one text, again and again
        before = session.last.text
        for key in keys[:MAX_KEYS]:
            self.guards.lift_all()
            before = session.last.text
            found = self._walked(key)
            if found is None:
                continue
            texts, last = found
            if len(set(texts)) >= 2:
                if self._learn(name, goal_value, texts, last, before, None, key):
                    return True
                if self._learn_lamp(name, goal_value, key):  # a lamp lit and put out
                    return True
                continue
            if self._learn_lamp(name, goal_value, key):
                return True
            single[key] = texts[0]
        if self._learn_choice(name, goal_value, single, before):
            return True
        for key in single:
            for adjuster in self._adjusters(key)[:MAX_ADJUSTERS]:
                self.guards.lift_all()
                entered = session.press(_planned(key), exploring=True)
                if not entered.feedback.accepted or not _unknown(entered):
                    break
                found = self._walked(adjuster)
                if found is None or len(set(found[0])) < 2:
                    continue
                if self._learn(name, goal_value, found[0], found[1], before, key, adjuster):
                    return True
        if any(self._typed(name, goal_value, key) for key in single):
            return True
        keypad = [a for a in session.belief.model.actions if _is_digit(a)]
        typing_first = bool(keypad) and bool(plain_steps(session.belief.model, keypad))
        if typing_first and self._typed(name, goal_value, None):
            return True
        if self._after_named(name, goal_value, before):
            return True
        return typed_after_named(self, name, goal_value)

    def _after_named(self, name: str, goal_value: Any, before: str) -> bool:
        """A procedure named like the setting (``auto_menu`` for ``auto_weight``) may go on
        with it as a step the reader missed ("press AUTO MENU, then turn the dial for the
        weight"): press the procedure's key, walk the panel's stepping keys after it, and a
        walk the belief cannot read is the setting, a further step of that procedure."""
        session = self.session
        for key, site in self._named_steps(name)[:2]:
            for adjuster in self._adjusters(key)[:MAX_ADJUSTERS]:
                self.guards.lift_all()
                entered = session.press(session.planned(key), exploring=True)
                if not entered.feedback.accepted or _unknown(entered):
                    break  # refused, or not the procedure the belief knows
                entered_values = session.belief.values()
                found = self._walked(adjuster)
                if found is None or len(set(found[0])) < 2:
                    continue
                texts, last = found
                if self._learn(name, goal_value, texts, last, before, key, adjuster, site):
                    # the walk was the new step's: what the belief took the keys to do
                    # elsewhere (another setting's steps, its resets) never happened
                    for other, value in entered_values.items():
                        if other != name and session.belief.value(other) != value:
                            session.belief.set_value(other, value)
                    return True
        return False

    def _learn(
        self,
        name: str,
        goal_value: Any,
        texts: list[str],
        last: str,
        before: str,
        entry: str | None,
        key: str,
        site: tuple[str, int] | None = None,
    ) -> bool:
        """Write the setting a walk of ``key`` (after ``entry``) showed into the belief — if
        the goal's value could be one of its values (a walk of grams is not a power level);
        with ``site``, as the step after that step of a procedure."""
        session = self.session
        if day_walk(texts, goal_value):
            session.episode.log("explore", f"{name}: {key} shows a time of day, not {goal_value!r}")
            return False
        learnt = infer_setting(name, texts, _kind_of(goal_value), last)
        if learnt is not None and not _fits(learnt.variable, goal_value):
            # each text a value of its own, named by its first word (MUG 300mL)?
            learnt = infer_setting(name, texts, "worded", last) or learnt
        if learnt is None:
            return False
        if not _fits(learnt.variable, goal_value):
            session.episode.log(
                "explore", f"{name}: {key} shows {learnt.note}, which {goal_value!r} is not"
            )
            return False
        model = session.belief.model
        try:
            if entry is None and site is None and key in self.suspect:
                model = unrole(model, key)  # the walk showed what the key really sets
            new = add_setting(
                model, name, learnt.variable, key, learnt.effect, self._opposite(key),
                entry=entry, after=site,
            )  # fmt: skip
        except RepairError as exc:
            session.episode.log("repair", f"could not add {name}: {exc}")
            return False
        new = self._as_lamp(new, name, before)
        under = f"{entry}, then {key}" if entry else key
        self.misread |= set(session.belief.model.variables) - set(new.variables)
        session.adopt(new, f"{name}: found under {under}; {learnt.note}", setting_step(new, name))
        session.discovered.add(name)
        if new.variables[name].depends_on is not None:
            session.guessed_initial.add(name)
        session.belief.set_value(name, learnt.current)
        session.evidence[name] = learnt.current  # the walk showed it
        session.reread()
        return True

    def _learn_lamp(self, name: str, goal_value: Any, key: str) -> bool:
        """A key whose presses light a word on the display and put it out again (``SYNC``,
        ``LIGHT``): an on/off setting the key toggles, shown as that lamp while on. One more
        press must light it again."""
        session = self.session
        lit, unlit = [*self.trail, None, None][:2]
        if len(self.trail) != 2 or lit is None or unlit is None:
            return False
        word = lamp_word(lit, unlit)
        variable: dict[str, Any] = {
            "type": "discrete",
            "values": ["off", "on"],
            "show": {"off": "", "on": word},
            "initial": "off",
        }
        if word is None or not _fits(variable, goal_value):
            return False
        again = session.press(_planned(key), exploring=True)
        if again.feedback.text != lit:
            return False
        try:
            new = add_setting(session.belief.model, name, variable, key, "toggle")
            new = add_indicator(new, name)
        except RepairError as exc:
            session.episode.log("repair", f"could not add {name}: {exc}")
            return False
        session.adopt(
            new,
            f"{name}: found under {key}; an on/off lamp shown as {word!r}",
            setting_step(new, name),
        )
        session.discovered.add(name)
        session.belief.set_value(name, "on")
        session.evidence[name] = "on"
        session.reread()
        return True

    def _typed(self, name: str, goal_value: Any, key: str | None) -> bool:
        """On a panel with a keypad, type the goal's value — after an entry key that shows one
        screen (``key``), or straight away where the belief has the digits as a procedure that
        sets nothing; a display that then shows the value is the setting, typed in as a number
        (``P 100%`` → ``P 70%``) or a clock (``TIME 00:01`` → ``TIME 01:30``)."""
        session = self.session
        digits = _digit_keys(session.context.actions or tuple(session.offered))
        typing = _typing(goal_value)
        if typing is None or len(digits) < 10:
            return False
        _, typed, value, _ = typing
        self.guards.lift_all()
        lamps = session.perceiver.reader.lamp_texts()
        texts: list[str] = []
        if key is not None:
            entered = session.press(_planned(key), exploring=True)
            texts.append(_main(entered.feedback.text, lamps))
            if not entered.feedback.accepted or not texts[0] or not _unknown(entered):
                return False
        for digit in typed:
            done = _press_digit(session, digits[digit])
            if not done.feedback.accepted:
                return False
            texts.append(_main(done.feedback.text, lamps))
        found = typed_setting(name, texts, typing, goal_value)
        if found is None:
            return False
        learnt, variable = found
        try:
            new = add_keypad_setting(
                session.belief.model, name, variable, key, [digits[d] for d in sorted(digits)]
            )
        except RepairError as exc:
            session.episode.log("repair", f"could not add {name}: {exc}")
            return False
        under = f"{key}, then the digits" if key else "the digits"
        session.adopt(new, f"{name}: found under {under}; {learnt.note}", setting_step(new, name))
        session.discovered.add(name)
        session.belief.set_value(name, value)
        session.evidence[name] = value
        session.reread()
        return True

    def _learn_choice(
        self, name: str, goal_value: Any, single: dict[str, str], before: str
    ) -> bool:
        """Keys that each showed one text of their own, varying in one place (``white rice``,
        ``brown rice``): one setting, each key selecting the value it showed."""
        session = self.session
        if len(single) < 2 or len(set(single.values())) < len(single):
            return False
        learnt = infer_setting(name, list(single.values()), "discrete")
        if learnt is None or not _fits(learnt.variable, goal_value):
            return False
        values = learnt.variable.get("values") or []
        if len(values) != len(single):
            return False
        learnt.variable.pop("wrap", None)
        try:
            new = add_choice_setting(
                session.belief.model, name, learnt.variable, dict(zip(single, values, strict=True))
            )
        except RepairError as exc:
            session.episode.log("repair", f"could not add {name}: {exc}")
            return False
        new = self._as_lamp(new, name, before)
        current = values[-1]
        session.adopt(
            new,
            f"{name}: each of {', '.join(single)} selects one ({learnt.note})",
            setting_step(new, name),
        )
        session.discovered.add(name)
        session.belief.set_value(name, current)
        session.stale.add(name)  # other keys may have been walked since: see it again
        session.reread()
        return True

    def _as_lamp(self, model: Any, name: str, text: str) -> Any:
        """The new setting also as a lamp, when the display showed it after its main text
        before its key was pressed (``P1  3:00  CRUST medium``)."""
        reader = DisplayReader(model)
        for segment in GAP.split(text.strip())[1:]:
            if any(
                h.screen.variable == name and name in h.values
                for h in reader.read(segment).hypotheses
            ):
                try:
                    return add_indicator(model, name)
                except RepairError:
                    return model
        return model


__all__ = ["DiscreteVariable", "VariableFinder", "infer_setting"]
