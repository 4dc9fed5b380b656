"""The finder's keys and walks: which keys may set a missing setting (those with no role, named
like it first; the stepping keys after an entry key; the last step of a procedure named like
it), and walking a key until its display repeats. Apart from :mod:`apbot.agent.discovery`,
which writes what a walk showed into the belief, because choosing and pressing keys is a job
of its own that the finder's every search shares; a part of
:class:`apbot.agent.discovery.VariableFinder`."""

from __future__ import annotations

from typing import Any

from apbot.agent.finder_keys import (
    _is_digit,
    _is_reverse,
    _main,
    _planned,
    _unknown,
    opposite_key,
    stepping_suspects,
)
from apbot.agent.guards import GuardLearner
from apbot.agent.repair import plain_keys
from apbot.agent.session import Executed, Session
from apbot.model.key_roles import adjusted_by, is_switch, misread_key
from apbot.read.actions import action_info

MAX_WALK = 60  # presses of one key while looking at a new setting
MAX_KEYS = 6  # keys tried for one setting


class KeyWalks:
    """The keys to try and their walks (a part of :class:`apbot.agent.discovery.VariableFinder`)."""

    session: Session
    guards: GuardLearner
    trail: list[str | None]  # the full texts of the last walk (None: refused)
    suspect: list[str]  # keys named like the setting sought, their role unfit

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
