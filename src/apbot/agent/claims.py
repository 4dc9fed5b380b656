"""The claim at the end of an episode: the belief holds the goal, but does the display say so?

When the plan to the goal is empty, the loop does not claim success on the belief's word alone:
a goal setting the display last showed otherwise, never showed, or showed only before a press
the belief did not foresee is looked at first (a look presses nothing that changes it); a
setting no screen can show, or one the panel lacks, is reported as done but not confirmed.
Kept apart from the loop's planning (:mod:`apbot.agent.loop`), whose part it is.
"""

from __future__ import annotations

import re
from collections import Counter
from typing import Any

from apbot.agent.checking import Checks
from apbot.agent.episode import TaskContext
from apbot.agent.locks import is_lock_setting
from apbot.agent.looking import glance, route_to_screen
from apbot.agent.marked import pushed_to_take
from apbot.agent.session import Stop
from apbot.agent.unread import unread_parts
from apbot.model.display import can_show
from apbot.model.schema import DiscreteVariable

_GAP = re.compile(r"\s{2,}")
RUN_STATES = ("running", "heating", "dispensing", "status", "start")


def starts_appliance(name: str) -> bool:
    """A goal setting that starts the appliance (left for last while settings are missing)."""
    return any(word in name for word in RUN_STATES)


class Claims(Checks):
    """The claim of success and the looks before it (a part of
    :class:`apbot.agent.loop.ClosedLoop`)."""

    context: TaskContext
    unfound: dict[str, Any]
    set_aside: dict[str, str]  # goal settings given up on, with why
    said: dict[str, Any]  # entries the agent made of quantities the goal held nowhere

    def settle_or_claim(self, inside: dict[str, Any]) -> bool:
        """The belief holds ``inside`` and no press is left: settle what the display showed,
        look at what it has not confirmed (True: it pressed or repaired, plan again), or stop
        with the claim the display allows."""
        if self.settle_contradictions(inside):
            return True  # the belief now holds what was shown: plan again
        unseen = self.session.unconfirmed(set(inside))
        if unseen and self._look(unseen):
            return True  # plan again from what the display showed
        if not unseen and self._glance(set(inside)):
            return True  # plan again from what the display showed
        if unseen and self._read_again(unseen):
            return True  # the display rules repaired from the look's texts: plan again
        if unseen:  # believed, but the display last said otherwise: it would be a guess
            raise Stop(
                "the belief holds the goal, but the display last showed "
                + ", ".join(f"{n}={self._last_reading(n)}" for n in unseen)
            )
        unseeable = [
            n
            for n in sorted(inside)
            if n not in self.session.ever_seen and not can_show(self.session.belief.model, n)
        ]
        if unseeable:  # an oven lamp: the plan may have done it, nothing can tell
            raise Stop(
                "the belief holds the goal, but the display cannot show "
                + ", ".join(unseeable)
                + ": done as planned, not confirmed"
            )
        if self.set_aside:
            reason = next(iter(self.set_aside.values()))
            raise Stop(f"{reason}; the rest of the goal holds")
        if self.unfound:
            raise Stop(
                "the rest of the goal holds; not found on the panel: "
                + ", ".join(f"{n}={v!r}" for n, v in self.unfound.items())
            )
        if not inside:  # a request read as nothing: nothing was set, so nothing is confirmed
            raise Stop(
                "the request names no setting the model knows: nothing set, nothing to claim"
            )
        if self._shown_otherwise(inside):
            return True  # the display prints a goal setting at another value: plan again
        if said := sorted(set(inside) & set(self.said)):  # the agent's own reading of the words
            raise Stop(
                "partly done: the goal as read holds; said as a quantity and found on the "
                "panel, but whose setting it is was the agent's guess: "
                + ", ".join(f"{n}={self.said[n]!r}" for n in said)
            )
        context = self.context
        unread = (
            unread_parts(context.belief, context.instruction, context.goal, context.manual)
            if context.goal_read
            else []
        )
        if unread:  # the goal as read holds, but it is not all the user asked for
            raise Stop("partly done: the goal as read holds; not understood: " + ", ".join(unread))
        raise Stop("the goal holds", success=True)

    def _shown_otherwise(self, inside: dict[str, Any]) -> bool:
        """The display prints, as a part of its own, the word the belief prints for another
        value of a goal setting, and not the believed value's word — a press reset it, and the
        screen's reading kept only the setting the press was for: believe the display, once
        per setting (True: plan again). Only words no other setting of the belief prints."""
        session = self.session
        belief = session.belief
        shown = set(_segments(session.last.text))
        printed = _printed_words(belief.model)
        for name in sorted(inside):
            spec = belief.model.variables.get(name)
            if not isinstance(spec, DiscreteVariable) or not isinstance(spec.show, dict):
                continue
            words = {v: w.casefold() for v, w in spec.show.items() if w and "{" not in w}
            if len(set(words.values())) != len(words) or any(
                printed[w] > 1 for w in words.values()
            ):
                continue
            believed = belief.value(name)
            if words.get(str(believed)) in shown:
                continue
            hits = [v for v in session.domain_values(name) if words.get(str(v)) in shown]
            if len(hits) != 1 or not session.budget.once("inspect", f"shown otherwise:{name}"):
                continue
            if not belief.set_value(name, hits[0]):
                continue
            session.evidence[name] = hits[0]
            session.episode.log(
                "repair",
                f"the display {session.last.text.strip()!r} prints {name}={hits[0]}, "
                f"not {believed}",
            )
            return True
        return False

    def take_marked(self) -> bool:
        """A goal setting the macro action left shown only as highlighted (``SEL heavy``,
        :mod:`apbot.agent.marked`) is looked at at once, before the plan sets anything else:
        the press that shows the choice taken (a knob's push) may also bring the choice's other
        settings back to its defaults, so they are set after it. True when it pressed."""
        inside = self.goal()[0]
        marked = [
            n
            for n in sorted(self.session.marked)
            if n in inside and pushed_to_take(self.session.belief.model, n)
        ]
        return bool(marked) and self._look(marked)

    def _look(self, names: list[str]) -> bool:
        """Bring up a goal setting the display has not confirmed since the belief last changed
        it (once each): enter its step and press its key once, and read what it shows."""
        for name in names:
            if not self.session.budget.once("inspect", f"look:{name}"):
                continue
            session = self.session
            route = route_to_screen(
                session.belief.compiled,
                session.belief.state,
                name,
                session.belief.model.variables,  # a look changes nothing else
                sorted(session.offered & set(session.belief.model.actions)),
            )
            if route is not None:
                for action in route:
                    session.press(session.planned(action), exploring=True)
                return True
            if self._guarding_the_goal():
                continue  # getting out would undo the goal (stop a running cycle): no look
            for feature, steps in self.session.belief.model.features.items():
                index = next((i for i, s in enumerate(steps) if s.variable == name), None)
                if index is None:
                    continue
                self.guards.lift_all()  # a dark panel shows nothing
                self.procedures.enter_step(feature, index)
                self.session.press(self.session.planned(steps[index].actions[0]), exploring=True)
                return True
        return False

    def _glance(self, names: set[str]) -> bool:
        """Look at a goal setting the display may not have confirmed (:func:`glance`)."""
        return glance(
            self.session, {n for n in names if not (starts_appliance(n) or is_lock_setting(n))}
        )

    def _guarding_the_goal(self) -> bool:
        """A guard holds whose condition the goal itself asks for (running, locked)."""
        compiled, state = self.session.belief.compiled, self.session.belief.state
        goal = set(self.context.goal)
        return any(
            all(state.values[v] in ok for v, ok in guard.conditions)
            and any(compiled.vars[v].name in goal for v, _ in guard.conditions)
            for guard in compiled.guards
        )

    def _last_reading(self, name: str) -> str:
        if name in self.session.unread:
            return "(unreadable)"
        return repr(self.session.evidence.get(name, "?"))


def _segments(text: str) -> list[str]:
    """A display's parts (the main text and each lamp), in any order."""
    return sorted(part.casefold() for part in _GAP.split(text.strip()) if part)


def _printed_words(model: Any) -> Counter[str]:
    """How many settings of ``model`` print each whole word of their ``show``."""
    return Counter(
        w.casefold()
        for spec in model.variables.values()
        if isinstance(getattr(spec, "show", None), dict)
        for w in set(spec.show.values())
        if w and "{" not in w
    )
