"""One episode's shared state, and the primitive every collaborator is built on: a press.

A :class:`Session` holds what the collaborators of the closed loop share — the belief, the
environment, the episode being logged, the budget of attempts, what the display showed last —
and :meth:`Session.press`: act on the appliance and on the belief together, read the feedback
in the light of the prediction, and keep whatever contradicted it as a *surprise*. The
explorer (``apbot.agent.explorer``), the procedure repairer (``.procedures``) and the greedy
executor (``.greedy``) each take a session; ``apbot.agent.loop`` orchestrates them.

In display mode the prediction is the whole display text: when the appliance shows exactly
what the belief renders, nothing needs reading; otherwise the display reader says what the
text means in the belief's terms.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import replace
from typing import Any

from apbot.agent.belief import Belief
from apbot.agent.budget import Budget
from apbot.agent.environment import Environment, Feedback
from apbot.agent.episode import TaskContext
from apbot.agent.executed import AgentConfig, Executed, GiveUp, Stop
from apbot.agent.marked import marked_now, pushed_to_take
from apbot.agent.model_edits import RepairError
from apbot.agent.perception import MISSING, UNREADABLE, Perceiver, Seen
from apbot.agent.pressing import press
from apbot.agent.quantities import magnitude
from apbot.agent.unlit import lit_lamps, unproven_dark
from apbot.model.display import can_show
from apbot.model.effects import default_effect
from apbot.model.schema import Add, ApplianceModel, Skip
from apbot.plan.plan import PlannedAction
from apbot.sim.simulator import Observation

__all__ = ["MISSING", "UNREADABLE", "AgentConfig", "Executed", "Session", "Stop"]


class Session:
    """One episode's state and the primitives every collaborator uses."""

    def __init__(
        self, config: AgentConfig, context: TaskContext, env: Environment, budget: Budget
    ) -> None:
        self.config = config
        self.context = context
        self.env = env
        self.budget = budget
        self.episode = context.episode()
        self.belief = Belief(context.belief)
        self.perceiver = Perceiver(self.belief.model)
        self.offered = frozenset(env.actions)
        self.last = Feedback()
        self.first_text = ""
        self.last_seen = Seen()
        self.explored: set[str] = set()
        self.evidence: dict[str, Any] = {}  # the value the display showed last, per variable
        self.stale: set[str] = set()  # changed in the belief since the display last showed them
        self.discovered: set[str] = set()  # settings the belief lacked, found on the panel
        self.blind: set[str] = set()  # changed while the display was dark, not seen since
        self.guessed_initial: set[str] = set()  # their programmes' start values are guesses
        # discrete values a walk showed spelt out (the belief's "lo" is the panel's "low")
        self.renamed: dict[str, dict[str, str]] = {}
        self.contradicted: dict[str, Any] = {}  # last shown as a value the belief cannot hold
        self.unread: set[str] = set()  # due on the display, but shown as the belief cannot read
        # per setting, the presses that brought up its step and showed text the belief cannot
        # read, since the display last showed it readably
        self.unread_presses: dict[str, list[Executed]] = {}
        self.ever_seen: set[str] = set()  # shown (or shown absent) at least once
        # a word setting's letter case in its last full reading, and the settings last read
        # only partially in another case (``SEL heavy`` after ``REFRESH``: highlighted, not
        # taken; :mod:`apbot.agent.marked`)
        self.forms: dict[str, str] = {}
        self.marked: set[str] = set()
        self.lit: set[str] = set()  # indicators whose lamp the display has shown lit
        # shown before a press the belief did not predict, not shown since: that press may have
        # changed them too (a CANCEL that also clears the delay), though the belief says not
        self.doubtful: set[str] = set()
        # of those, settings a procedure takes after a choice made again (the weight typed for
        # the food chosen): a keypad one is typed again rather than believed
        self.rechosen: set[str] = set()
        # of those, settings shown before a programme was chosen again (a programme key): the
        # choice may have brought them back to its defaults, so they are worth a second look
        self.reprogrammed: set[str] = set()
        # how often the display moved the belief's state where its own transitions did not go
        self.moved = 0
        self._unshowable: tuple[Any, frozenset[str]] = (None, frozenset())

    # --- acting ------------------------------------------------------------------------------

    def start(self) -> None:
        """Reset the appliance and believe what it shows."""
        self.last = self.env.reset()
        self.first_text = self.last.text  # the display before any press (a home screen, or dark)
        self.last_seen = self.perceive(self.last, self.belief.expected())
        self.sync(self.last_seen)

    def press(
        self, action: PlannedAction, exploring: bool = False, typing_on: bool = False
    ) -> Executed:
        """Perform ``action`` on the appliance and on the belief; the belief then follows what
        the display shows, and whatever contradicted its prediction is kept as a surprise
        (:func:`apbot.agent.pressing.press`)."""
        done = press(self, action, exploring, typing_on)
        seen, name = done.seen, done.variable
        if name is not None and seen is not None and (seen.unknown or not seen.showing(name)):
            self.unread_presses.setdefault(name, []).append(done)
        return done

    def planned(self, action: str) -> PlannedAction:
        spec = self.belief.model.actions[action]
        return PlannedAction(action, spec.skill, tuple(spec.control_ids), spec.seconds)

    # --- reading -------------------------------------------------------------------------------

    def perceive(self, feedback: Feedback, expected: Observation) -> Seen:
        """Read ``feedback`` against the belief's prediction ``expected``."""
        if feedback.text == expected.text:
            kind, _ = self.expected_screen()
            seen = Seen(
                feedback.text,
                # a dark panel (a hiding guard) shows no value, not even its lamps
                {} if kind == "guard" else dict(expected.values),
                screen=expected.focus,
                screen_kind=kind,
                screens=frozenset({(kind, expected.focus)}),
            )
            if feedback.values:  # values by name are exact, and win
                estimate = self.perceiver.estimator.estimate(feedback, context=self.belief.values())
                for name in set(estimate.values) | set(estimate.outside):
                    seen.values.pop(name, None)
                seen.values.update(estimate.values)
                seen.outside.update(estimate.outside)
            return seen
        return self.perceiver.perceive(feedback, self.belief.values(), self.expected_screen())

    def expected_screen(self) -> tuple[str, str | None]:
        """What the belief says the main display shows now, as (kind, variable)."""
        compiled = self.belief.compiled
        if compiled.hiding_guard(self.belief.state) is not None:
            return ("guard", None)
        focus = compiled.focus(self.belief.state)
        return ("focus", compiled.vars[focus].name) if focus >= 0 else ("idle", None)

    def sync(self, seen: Seen) -> None:
        """Believe what the display shows; what it showed is confirmed, and a value the belief
        cannot hold is kept as a contradiction until the setting is seen with one it can."""
        if not self.last.values:  # a dark lamp whose lit words were never seen says nothing
            model, domain = self.belief.model, lambda n: tuple(self.domain_values(n))
            self.lit |= lit_lamps(model, seen.text, domain)
            dark = unproven_dark(model, seen.values, self.lit, domain)
            if dark:
                seen = replace(seen, values={n: v for n, v in seen.values.items() if n not in dark})
        self.last_seen = seen
        before = self.belief.state
        for name, value in seen.values.items():
            self.belief.set_value(name, value)
        if self.belief.state != before:
            self.moved += 1
        if not self.last.values:  # the display alone: a setting no screen tells apart (an oven
            # lamp) matched the prediction only because every value prints the same
            hidden = self.unshowable()
            seen = replace(seen, values={n: v for n, v in seen.values.items() if n not in hidden})
        self.evidence.update(seen.values)
        self.evidence.update(seen.outside)
        self.evidence.update({name: None for name in seen.absent})
        self.stale -= set(seen.values) | set(seen.outside) | seen.absent
        self.blind -= set(seen.values) | set(seen.outside) | seen.absent
        self.unread -= set(seen.values) | set(seen.outside) | seen.absent
        for name in (set(seen.values) | set(seen.outside) | seen.absent) & set(self.unread_presses):
            del self.unread_presses[name]  # read since
        self.ever_seen |= set(seen.values) | set(seen.outside) | seen.absent
        marked_now(self.belief.model, seen.values, seen.text, seen.partial, self.forms, self.marked)
        self.doubtful -= set(seen.values) | set(seen.outside) | seen.absent
        self.rechosen -= set(seen.values) | set(seen.outside) | seen.absent
        self.reprogrammed -= set(seen.values) | set(seen.outside) | seen.absent
        self.contradicted.update(seen.outside)
        for name in seen.values:
            self.contradicted.pop(name, None)
        # a display that contradicts the belief one way or another confirms none of them
        self.stale |= seen.doubted & set(self.evidence)

    def unshowable(self) -> frozenset[str]:
        """The belief's settings no screen tells apart (:func:`apbot.model.display.can_show`)."""
        model = self.belief.model
        if self._unshowable[0] is not model:
            names = frozenset(n for n in model.variables if not can_show(model, n))
            self._unshowable = (model, names)
        return self._unshowable[1]

    def unconfirmed(self, names: list[str] | set[str]) -> list[str]:
        """The variables whose last reading on the display may not be what the belief holds
        now: it differs, or the belief changed it since (a press, a side effect, a programme
        that resets it) without the display showing it again, or the display was due to show it
        and showed what the belief cannot read. A variable never due on the display at all
        rests on the model alone."""
        return sorted(
            n
            for n in names
            if (
                n in self.evidence and (self.evidence[n] != self.belief.value(n) or n in self.stale)
            )
            or (n in self.stale and n in self.guessed_initial | self.discovered)
            or n in self.blind
            or n in self.unread
            or (n in self.marked and pushed_to_take(self.belief.model, n))
        )

    def unverified(self, names: list[str] | set[str]) -> list[str]:
        """The variables a claim would rest on without the display's word, though a screen of
        the belief can show them: never shown at all (the value is the reader's guess of the
        starting value, or a side effect nothing showed), or shown only before a press that
        did what the belief did not predict. Worth a look where one changes nothing else;
        where none does, the belief is all there is (:meth:`unconfirmed` is stricter)."""
        hidden = self.unshowable()
        return sorted(
            n
            for n in names
            if n in self.belief.model.variables
            and n not in hidden
            and self.belief.model.variables[n].visible
            and (n not in self.ever_seen or n in self.doubtful)
        )

    def shows(self, feedback: Feedback, name: str) -> bool:
        """Whether ``feedback``'s text prints ``name`` on any screen the belief knows (read
        afresh: a screen matching the prediction records only its own setting)."""
        seen = self.perceiver.perceive(feedback, self.belief.values(), None)
        return seen.observed(name) is not MISSING

    def shown(self, name: str) -> Any:
        """The value of ``name`` on the display now; MISSING if none."""
        return self.last_seen.observed(name)

    def reread(self) -> None:
        """Read the last feedback again (after a repair changed the belief's display rules or
        its state) and believe it."""
        self.sync(self.perceive(self.last, self.belief.expected()))

    # --- the belief model ------------------------------------------------------------------

    def step_variable(self, pointer: tuple[str, int] | None) -> str | None:
        if pointer is None:
            return None
        feature, index = pointer
        return self.belief.model.features[feature][index].variable

    def effect(self, pointer: tuple[str, int], action: str) -> Any:
        feature, index = pointer
        step = self.belief.model.features[feature][index]
        return default_effect(step, action, self.belief.model)

    def stepping(self, pointer: tuple[str, int], action: str) -> bool:
        """Whether ``action`` walks the step's variable through its values (not a go-to)."""
        effect = self.effect(pointer, action)
        return effect in ("next", "prev", "toggle") or isinstance(effect, Add | Skip)

    def domain_values(self, name: str) -> list[Any]:
        compiled = self.belief.compiled
        var = compiled.vars[compiled.var_index[name]]
        domain = var.domain(self.belief.state.values)
        return list(domain.values) if domain is not None else []

    def magnitudes(self, name: str) -> list[float]:
        spec = self.belief.model.variables[name]
        return [m for m in (magnitude(spec, v) for v in self.domain_values(name)) if m is not None]

    def case(self, name: str) -> str | None:
        parent = self.belief.model.variables[name].depends_on
        return None if parent is None else str(self.belief.value(parent))

    def adopt(self, model: ApplianceModel, note: str, pointer: tuple[str, int] | None) -> None:
        """Switch the belief to a repaired model, keeping the believed state."""
        self.belief.replace(model, pointer)
        self.perceiver.rebind(model)
        for name, value in list(self.contradicted.items()):  # values the repair made possible
            if name in model.variables and self.belief.set_value(name, value):
                del self.contradicted[name]
        self.episode.repairs.append(note)
        self.episode.log("repair", note)

    def try_repair(
        self,
        edit: Callable[[], ApplianceModel],
        note: str,
        pointer: tuple[str, int] | None,
        refused: str,
    ) -> bool:
        """Adopt the model ``edit`` writes; when the edit is refused (the repaired model would
        not pass the checker), log why after ``refused`` and keep the belief as it was."""
        try:
            new = edit()
        except RepairError as exc:
            self.episode.log("repair", f"{refused}: {exc}")
            return False
        self.adopt(new, note, pointer)
        return True

    def count_reasoning_step(self) -> None:
        """One more decision; the run ends instead when the limit is reached."""
        if self.episode.reasoning_steps >= self.context.max_reasoning_steps:
            raise Stop(f"reached the limit of {self.context.max_reasoning_steps} reasoning steps")
        self.episode.reasoning_steps += 1

    def again(self, kind: Any, key: str, message: str, names: Iterable[str] = ()) -> None:
        """One more occurrence of a repeated problem; give up when it keeps coming back (on
        the settings ``names`` only, when the problem is theirs: :class:`GiveUp`)."""
        if not self.budget.again(kind, key):
            names = frozenset(names)
            raise GiveUp(message, names) if names else Stop(message)

    def forget_pointer(self) -> None:
        """After presses the belief cannot follow, assume no procedure is in progress."""
        self.belief.set_pointer(None)
        self.reread()
