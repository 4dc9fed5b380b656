"""The explorer: walk a variable's values and learn its definition from what the display shows.

On a mismatch the agent presses the step's key again and again until a shown value repeats
(and walks back with the opposite key after an end, or when the walk went dark at once), then
writes what it saw into the belief: the order of the values, piecewise ranges, wrap or clamp,
which way a key moves, how much an ``add`` key adds (``apbot.agent.infer`` does the inference,
``apbot.agent.repair`` the model edit).

The repairs a walk leads to are in :mod:`apbot.agent.walk_learning`.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.displays import DisplayLearner
from apbot.agent.infer import Dark, Unread
from apbot.agent.legend_walk import learn_legend, read_sign
from apbot.agent.perception import Seen
from apbot.agent.quantities import summary
from apbot.agent.renamed import by_own_parts, rename_walk, translate
from apbot.agent.repair import RepairError
from apbot.agent.said_choices import said_choices
from apbot.agent.session import MISSING, Executed, Session
from apbot.agent.time_styles import restyle_walk
from apbot.agent.walk_learning import WalkLearning
from apbot.agent.worded import as_choices, as_text, reads_all, worded_values
from apbot.model.domain import ValueProblem, normalise
from apbot.model.schema import Add, NumericVariable, Skip
from apbot.plan.plan import PlannedAction


class Explorer(WalkLearning):
    """Walk a variable's values with its step's keys and repair the belief from the walk."""

    def __init__(self, session: Session, displays: DisplayLearner) -> None:
        self.session = session
        self.displays = displays
        # the last walk stayed on one value with no other key to try: (setting, step, key)
        self.stuck: tuple[str, tuple[str, int], PlannedAction] | None = None

    def explore(self, name: str, last: Executed, history: list[Any] | None = None) -> None:
        """Explore ``name`` with ``last``'s key (from the step ``last`` left the belief in)."""
        assert last.pointer is not None
        self.session.explored.add(name)
        pointer, key = last.pointer, last.action
        single = self.single_step(pointer, key)
        if single is not key:  # walk one value at a time: its history was in strides
            key, history = single, []
        forward, unseen = self.walk(name, key, history or [])
        visible = [v for v in forward if not isinstance(v, Dark)]
        opposite = self.opposite(pointer, key.name)
        backward: list[Any] | None = None
        final = key
        swapped = opposite is not None and len(visible) < 2
        if swapped and opposite is not None:
            # nothing to learn this way (dark, or stuck at once): the other key leads
            key, opposite = opposite, key
            forward, unseen = self.walk(name, key)
            final = key
        elif opposite is not None and forward[-1] == forward[-2]:  # an end: walk back
            # no further than the goal's value: the walk has found the step and one end, and
            # what lies beyond the goal is not asked for
            backward, unseen = self.walk(name, opposite, stop_at=self._goal_value(name))
            final = opposite
        self.session.episode.log(
            "explore",
            f"{name} under {key.name}: {summary(forward)}"
            + (
                f"; under {opposite.name}: {summary(backward)}"
                if opposite is not None and backward is not None
                else ""
            ),
        )
        renamed, learnt, every = False, None, False
        walked = [v for v in forward + (backward or []) if not isinstance(v, Dark)]
        unread_walk = bool(walked) and all(isinstance(v, Unread) for v in walked)
        if not swapped and (signs := learn_legend(self.session, name, forward + (backward or []))):
            # the manual's legend names the signs the walk showed: read the walk again by it
            forward, backward = (
                self._by_legend(name, forward, signs),
                (None if backward is None else self._by_legend(name, backward, signs)),
            )
            learnt = True
        elif not swapped:
            # the belief's own words for the texts first (a template, one value's word); else
            # the walk may be the belief's own with values printed otherwise
            if any(isinstance(v, Unread) for v in forward + (backward or [])):
                learnt = self._template_or_word(
                    name, forward, backward, last.predicted, self._start_read(name, last)
                )
            if not learnt:
                walks = self._renamed(name, last, key, opposite, forward, backward, history)
                renamed = walks is not None
                if walks is not None:  # ``every``: the walk went round every value, not stuck
                    forward, backward, every = walks
        forward, backward = self._read_unread(
            name, forward, backward, last.predicted, learnt, self._start_read(name, last)
        )
        forward, backward = restyle_walk(self.session, name, forward, backward)
        seen = [v for v in forward + (backward or []) if not isinstance(v, Dark)]
        if not seen:
            return
        last_walk = [
            v for v in (backward if backward is not None else forward) if not isinstance(v, Dark)
        ]
        current = last_walk[-1] if last_walk else seen[-1]
        self.stuck = None
        several = len(set(map(repr, seen))) >= 2
        if several and not renamed:  # renamed: the walk was as predicted
            self.learn(name, pointer, key.name, opposite, forward, backward, current)
        elif opposite is None and not every and not several:
            # one value over and over, no other key in the step: at an end, or not this key's
            # setting at all — nothing to say about the range. A renamed walk that read several
            # values went round: it is not stuck, and probing other keys would only move them
            self.stuck = (name, pointer, key)
        self.session.belief.set_value(name, current)
        if unread_walk and self.session.budget.once("inspect", f"rewalk:{name}"):
            # a walk none of whose texts could be read as it went stopped where it could not
            # tell a value repeat, and its range is read from those few texts: the setting is
            # walked once more, readable now, before a goal value is taken to be missing
            self.session.explored.discard(name)
        for _ in range(unseen):  # presses taken in the dark: the (repaired) model says where to
            self.session.belief.advance(final.name, final.seconds)

    def _template_or_word(
        self,
        name: str,
        forward: list[Any],
        backward: list[Any] | None,
        believed: Any,
        start_read: bool = False,
    ) -> bool:
        """Learn how the display prints the setting from the texts a walk could not read: one
        value's word, or the template they share; True when the belief changed."""
        texts = [v.text for v in forward + (backward or []) if isinstance(v, Unread)]
        return self.displays.learn_word(
            name, forward + (backward or []), believed, start_read
        ) or self.displays.learn(name, texts)

    def _by_legend(self, name: str, walk: list[Any], signs: dict[str, Any]) -> list[Any]:
        """The walk read again after the legend's signs were learnt: a value read as a sign
        is the sign's value, a text is read by the repaired belief."""
        result: list[Any] = []
        for value in walk:
            if isinstance(value, Unread):
                read = self.displays.read(name, value.text)
                if read is None:  # a lamp: shown beside another setting's screen
                    read = read_sign(self.session, name, value.text)
                value = value if read is None else read
            elif isinstance(value, str) and value in signs:
                value = signs[value]
            result.append(value)
        return result

    @staticmethod
    def _start_read(name: str, last: Executed) -> bool:
        """Whether the value ``last`` moved ``name`` from was read on the display (so what it
        was to give is known), not the belief's guess."""
        return last.start_shown(name)

    def _read_unread(
        self,
        name: str,
        forward: list[Any],
        backward: list[Any] | None,
        believed: Any = None,
        learnt: bool | None = None,
        start_read: bool = False,
    ) -> tuple[list[Any], list[Any] | None]:
        """Texts the belief could not read: learn how the display prints the setting from them,
        then read them again; what stays unreadable counts as dark. ``learnt``: what the word
        and template learners made of these texts already (:meth:`_template_or_word`; None:
        not tried yet)."""
        texts = [v.text for v in forward + (backward or []) if isinstance(v, Unread)]
        if learnt is None and texts:
            learnt = self._template_or_word(name, forward, backward, believed, start_read)
        if texts and not learnt and self._learn_words(name, texts):
            forward, backward = as_text(forward), None if backward is None else as_text(backward)
        elif texts and not learnt:
            self._learn_said(name, texts)

        def again(trace: list[Any]) -> list[Any]:
            result = []
            for value in trace:
                if isinstance(value, Unread):
                    read = self.displays.read(name, value.text)
                    value = Dark() if read is None else read
                result.append(value)
            return result

        return again(forward), None if backward is None else again(backward)

    def _renamed(
        self,
        name: str,
        last: Executed,
        key: PlannedAction,
        opposite: PlannedAction | None,
        forward: list[Any],
        backward: list[Any] | None,
        history: list[Any] | None,
    ) -> tuple[list[Any], list[Any] | None, bool] | None:
        """A walk that is the belief's own with some values printed in other words: learn
        those words (:mod:`apbot.agent.renamed`) and read the walk in the belief's values,
        with whether they were learnt from its own parts, having gone round every value
        (None: not such a walk)."""
        opened = len(history) - 1 if history and forward[: len(history)] == history else 0
        if not forward[opened:] or forward[opened] != self._value(name, last.seen):
            return None  # the walk does not open on the display ``last`` left
        walks = [(forward[opened:], key.name)]
        if backward is not None and opposite is not None:
            walks.append((backward, opposite.name))
        pairs = rename_walk(self.session, self.displays.main, name, last, walks, key.seconds)
        if pairs is None:
            return None
        main = self.displays.main
        return (
            translate(forward, pairs, main),
            None if backward is None else translate(backward, pairs, main),
            by_own_parts(pairs),
        )

    def _learn_words(self, name: str, texts: list[str]) -> bool:
        """A numeric setting whose walk showed words where numbers were due ("no spin"):
        its positions become choices, numbers and words alike (:mod:`apbot.agent.worded`)."""
        session = self.session
        model = session.belief.model
        spec = model.variables[name]
        if not isinstance(spec, NumericVariable):
            return False
        mains = [self.displays.main(t) for t in dict.fromkeys(texts)]
        words = worded_values(spec, name, mains)
        if words is None or not session.budget.once("template", f"{name}:words"):
            return False
        try:
            new = as_choices(model, name, words)
        except RepairError as exc:
            session.episode.log("repair", f"could not repair {name}: {exc}")
            return False
        if not reads_all(new, name, mains):
            return False
        session.adopt(new, f"{name}: choices, some shown as words ({', '.join(words)})", None)
        return True

    def _learn_said(self, name: str, texts: list[str]) -> bool:
        """A list setting whose walk showed the user's word among words the belief cannot
        read: they are its values (:mod:`apbot.agent.said_choices`)."""
        said = self.session.context.goal.get(name)
        if said is None or said in self.session.domain_values(name):
            return False
        mains = [self.displays.main(t) for t in dict.fromkeys(texts)]
        new = said_choices(self.session.belief.model, name, mains, str(said))
        if new is None or not reads_all(new, name, mains):
            return False
        if not self.session.budget.once("template", f"{name}:said"):
            return False
        self.session.adopt(new, f"{name}: choices as shown ({', '.join(mains)})", None)
        return True

    def _goal_value(self, name: str) -> Any:
        """The goal's value for a numeric setting ``name`` in the belief's terms (MISSING: none,
        or not one its domain has: a walk that stops there would learn a range around a
        value the belief never expected). Times are left out: a walk of a time is also how
        its display style (``m:ss`` or ``h:mm``) is told apart."""
        raw = self.session.context.goal.get(name)
        spec = self.session.belief.model.variables.get(name)
        if raw is None or not isinstance(spec, NumericVariable):
            return MISSING
        raw = self.session.renamed.get(name, {}).get(str(raw), raw)
        try:
            return normalise(spec, raw)
        except ValueProblem:
            return MISSING

    def walk(
        self,
        name: str,
        action: PlannedAction,
        history: list[Any] | None = None,
        stop_at: Any = MISSING,
    ) -> tuple[list[Any], int]:
        """Press ``action`` until the value of ``name`` shown repeats (or is ``stop_at``).

        ``history`` (values shown under the same key just before) opens the walk. A press after
        which the display shows nothing for ``name`` (an OFF position) is recorded as
        :class:`Dark`; two in a row end the walk. Returns the values (dark ones included) and
        how many presses at the end went unseen (the appliance moved on in the dark).
        """
        start = self._value(name, self.session.last_seen)
        values = [] if start is MISSING else [start]  # not shown now: start from the first press
        if history and values and history[-1] == values[0]:
            values = list(history)
            if len(values) >= 2 and values[-1] in values[:-1]:
                return values, 0  # they already went round
        dark = 0
        for _ in range(self.session.config.explore_limit):
            done = self.session.press(action, exploring=True)
            if not done.feedback.accepted:
                break
            value = self._value(name, done.seen)
            if value is MISSING:
                dark += 1
                values.append(Dark())
                if dark >= 2:
                    break
                continue
            dark = 0
            values.append(value)
            if value in values[:-1] or (stop_at is not MISSING and value == stop_at):
                break
            unread = [v.text for v in values if isinstance(v, Unread)]
            if len(unread) >= 2 and self.displays.learn(name, unread):
                break  # the belief printed it wrong: read again, the walk has done its job
        return values, dark

    @staticmethod
    def _value(name: str, seen: Seen | None) -> Any:
        """What a walk records: the value shown, text the belief cannot read, or MISSING."""
        if seen is None:
            return MISSING
        value = seen.observed(name)
        if value is MISSING and seen.text.strip() and (seen.unknown or not seen.showing(name)):
            return Unread(seen.text)  # text, but not this setting's as the belief prints it
        return value

    def history(self, name: str, last: Executed, executed: list[Executed]) -> list[Any]:
        """Values ``name`` showed under the presses of ``last``'s key that end the macro
        action: the start of the walk, already paid for."""
        values: list[Any] = []
        for done in reversed(executed):
            if done.action.name != last.action.name or done.pointer != last.pointer:
                break
            value = done.observed(name)
            if value is MISSING:
                break
            values.append(value)
        return list(reversed(values))

    def opposite(self, pointer: tuple[str, int], action: str) -> PlannedAction | None:
        """The step's key that walks the other way, if there is one."""
        feature, index = pointer
        effect = self.session.effect(pointer, action)
        stepping = [
            other
            for other in self.session.belief.model.features[feature][index].actions
            if other != action
            and (
                (theirs := self.session.effect(pointer, other)) in ("next", "prev")
                or isinstance(theirs, Add)
            )
        ]
        # a key believed to go the same way may be the one the reader got backwards
        ordered = sorted(
            stepping,
            key=lambda other: (
                self.session.effect(pointer, other) == effect
                or _way(self.session.effect(pointer, other)) == _way(effect) != 0
            ),
        )
        return self.session.planned(ordered[0]) if ordered else None

    def single_step(self, pointer: tuple[str, int], key: PlannedAction) -> PlannedAction:
        """For a key that scrolls several values at once (a held ▲, ``skip``), the step's key
        that moves one value the same way: a walk in strides skips values."""
        effect = self.session.effect(pointer, key.name)
        if not isinstance(effect, Skip):
            return key
        feature, index = pointer
        for other in self.session.belief.model.features[feature][index].actions:
            if _way(self.session.effect(pointer, other)) == _way(effect) and self.session.effect(
                pointer, other
            ) in ("next", "prev"):
                return self.session.planned(other)
        return key

    def stepping_key(self, name: str) -> Executed | None:
        """The step the belief is in, as an action to explore ``name`` with, if it steps it."""
        pointer = self.session.belief.pointer()
        if pointer is None or self.session.step_variable(pointer) != name:
            return None
        feature, index = pointer
        for action in self.session.belief.model.features[feature][index].actions:
            if self.session.stepping(pointer, action):
                return Executed(
                    self.session.planned(action), pointer, name, self.session.last, True
                )
        return None


def _way(effect: Any) -> int:
    """Which way an effect moves a value along its order: +1, -1, or 0 (a go-to, none)."""
    if effect == "next":
        return 1
    if effect == "prev":
        return -1
    amount: float | None = effect.skip if isinstance(effect, Skip) else None
    if isinstance(effect, Add):
        amount = effect.add if isinstance(effect.add, int | float) else None
        if isinstance(effect.add, str):
            amount = -1 if effect.add.startswith("-") else 1
    if amount is None or amount == 0:
        return 0
    return 1 if amount > 0 else -1
