"""The variable finder: a setting the goal names and the belief lacks altogether.

A reader can miss a setting entirely — its variable, its procedure, even its keys. The panel
still has the keys (the environment's action names), and the display still shows the setting
when one of them is pressed. The finder tries the keys the belief gives no role, those named
like the setting first; a key whose display the belief cannot read is walked until the text
repeats, and what varies from text to text is the setting's value
(:func:`apbot.agent.infer.infer_template`). From the walk it writes a new variable (its values
or ranges, unit, display template), the key's action and a one-step procedure into the belief —
a data edit the checker validates like any other.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.added_settings import unrole
from apbot.agent.finder_keys import (
    _digit_keys,
    _is_digit,
    _is_reverse,
    _main,
    _planned,
    _press_digit,
    _unknown,
    opposite_key,
    stepping_suspects,
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
    plain_keys,
    plain_steps,
    setting_step,
)
from apbot.agent.session import Executed, Session
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
from apbot.model.key_roles import adjusted_by, is_switch, misread_key
from apbot.model.schema import DiscreteVariable
from apbot.read.actions import action_info

MAX_WALK = 60  # presses of one key while looking at a new setting
MAX_KEYS = 6  # keys tried for one setting
MAX_ADJUSTERS = 4  # keys tried after an entry key


class VariableFinder:
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

    def _named_steps(self, name: str) -> list[tuple[str, tuple[str, int]]]:
        """The last step of each procedure whose name or setting shares a word with ``name``,
        with a key of its own that is no switch's: (that key, (procedure, step index))."""
        model = self.session.belief.model
        words = {w for w in name.split("_") if len(w) >= 3}
        switches = self._switch_keys()
        found: list[tuple[str, tuple[str, int]]] = []
        for feature, steps in model.features.items():
            index = len(steps) - 1
            step = steps[index]
            names = {*feature.split("_"), *(step.variable or "").split("_")}
            keys = [a for a in step.actions if a not in switches and not _is_digit(a)]
            if words & names and len(keys) == 1 and step.variable is not None:
                found.append((keys[0], (feature, index)))
        return found

    def _walked(self, key: str) -> tuple[list[str], str] | None:
        """Walk ``key`` (and its opposite back from an end): the texts in value order and the
        text shown now; None when the key shows nothing the belief cannot read."""
        texts = self._walk(key)
        if not texts:
            return None
        last = texts[-1]
        opposite = self._opposite(key)
        if len(set(texts)) < 2 and opposite is not None:  # stuck at an end: walk back
            back = self._walk(opposite)
            last = back[-1] if back else last
            texts = list(reversed(back)) + texts
        return texts, last

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

    def _adjusters(self, entry: str) -> list[str]:
        """Keys to walk after an entry key: those that step things (▲/▼, dials) first; never
        a lock's, a power switch's or a start key (they change which keys work)."""
        offered = list(self.session.context.actions or self.session.offered)
        stepping = ("plus", "minus", "up", "down", "cw", "ccw", "left", "right", "next", "prev")
        switches = self._switch_keys()
        keys = [
            a
            for a in offered
            if a != entry and not _is_reverse(a) and not _is_digit(a) and a not in switches
        ]
        return sorted(
            keys, key=lambda a: (not any(w in a.split("_") for w in stepping), keys.index(a))
        )

    def _switch_keys(self) -> set[str]:
        """Keys of the steps that change what a guard of the belief tests (power, locks, the
        run state)."""
        model = self.session.belief.model
        tested = {n for guard in model.guards for n in guard.when}
        return {
            a
            for steps in model.features.values()
            for step in steps
            if step.variable in tested or tested & set(step.set)
            for a in step.actions
        }

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

    def _candidates(self, name: str, goal_value: Any = None) -> list[str]:
        """Keys that start nothing the belief knows (unknown, unused, or only later steps of a
        procedure), those named like the setting first; not digits. Then a key named like the
        setting whose role in the belief cannot hold the goal's value ("400 g" on a DEFROST
        key read as a switch): the reader may have got that key wrong."""
        session = self.session
        model = session.belief.model
        starting = {a for steps in model.features.values() for a in steps[0].actions}
        starting |= {a for entry in model.anywhere for a in entry.actions}  # a role of their own
        starting |= {a for a, spec in model.actions.items() if spec.skill == "wait"}
        plain = plain_keys(model)
        offered = list(session.context.actions or session.offered)
        unknown = [a for a in offered if (a not in starting or a in plain) and not _is_digit(a)]
        words = {w for w in name.split("_") if len(w) >= 3}

        def alike(action: str) -> bool:
            parts = [p for p in action_info(action).token.split("_") if len(p) >= 3]
            return any(w.startswith(p) or p.startswith(w) for w in words for p in parts)

        # a key the belief gives a plain step only (press it, nothing changes) may be the very
        # key of the setting the reader missed: after the keys with no role at all
        ranked = sorted(unknown, key=lambda a: (not alike(a), a in plain, unknown.index(a)))
        named = [a for a in ranked if alike(a)]
        self.suspect = [
            a
            for a in offered
            if a not in unknown
            and alike(a)
            and not _is_digit(a)
            and goal_value is not None
            and misread_key(model, a, goal_value)
            and not any(  # a choice the goal makes with it: the key's role taken as read
                v in session.context.goal and not is_switch(model, v) for v in adjusted_by(model, a)
            )
        ]
        # last, a forward stepping key (▲, +, a dial) whose role cannot hold the goal's value
        stepping = stepping_suspects(session, [a for a in offered if a not in unknown], goal_value)
        stepping = [a for a in stepping if a not in self.suspect]
        named += self.suspect
        self.suspect += stepping
        rest = [a for a in ranked if not alike(a)]
        keys = [a for a in [*named, *rest] if not _is_reverse(a)][:MAX_KEYS]
        return keys + [a for a in stepping if a not in keys][: max(0, MAX_KEYS + 1 - len(keys))]

    def _walk(self, key: str) -> list[str]:
        """Press ``key`` until the display repeats a text the belief cannot read; the texts."""
        session = self.session
        action = _planned(key)
        texts: list[str] = []
        self.trail = []
        for _ in range(MAX_WALK):
            done: Executed = session.press(action, exploring=True)
            self.trail.append(done.feedback.text if done.feedback.accepted else None)
            text = _main(done.feedback.text, session.perceiver.reader.lamp_texts())
            if not texts and not done.feedback.text.strip() and self.guards.learn(done):
                # a dark panel the belief had no guard for (asleep): now lit, and the key was
                # pressed again there — what it showed is the walk's first text
                shown = session.last.text
                main = _main(shown, session.perceiver.reader.lamp_texts())
                if main and session.perceiver.reader.read(shown).unknown:
                    self.trail = [shown]
                    texts.append(main)
                continue
            if not done.feedback.accepted or not text or not _unknown(done):
                break  # refused, dark, or a screen the belief knows: not the missing setting
            if text in texts:
                texts.append(text)
                break
            texts.append(text)
        return texts

    def _opposite(self, key: str) -> str | None:
        """The key that walks the other way, if the panel has it."""
        return opposite_key(key, self.session.context.actions or tuple(self.session.offered))


__all__ = ["DiscreteVariable", "VariableFinder", "infer_setting"]
