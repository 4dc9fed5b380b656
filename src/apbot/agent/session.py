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

import re
from dataclasses import dataclass, field, replace
from typing import Any

from apbot.agent.belief import Belief
from apbot.agent.budget import Budget
from apbot.agent.environment import Environment, Feedback
from apbot.agent.episode import TaskContext
from apbot.agent.perception import MISSING, UNREADABLE, Perceiver, Seen
from apbot.model.display import can_show, display_value
from apbot.model.domain import ValueProblem, parse_value
from apbot.model.effects import default_effect
from apbot.model.schema import Add, ApplianceModel, DiscreteVariable, Skip, TimeVariable
from apbot.model.values import format_hms, parse_hms
from apbot.plan.plan import PlannedAction
from apbot.sim.compiled import State
from apbot.sim.simulator import Observation

__all__ = ["MISSING", "UNREADABLE", "AgentConfig", "Executed", "Session", "Stop"]

EXPLORE_LIMIT = 400  # presses per direction (a 1-minute clock over 6 hours; most domains < 100)
# Search per plan. On the true models every plan of the bundled suite (750 tasks, stored or
# read goals, from every state the loop plans from) needs at most 14,149 expanded states (and
# keeps up to twice the budget in memory) and 730,469 successors generated; on a model read
# from a manual a search past that much work is almost always one that cannot succeed (the
# goal is out of the belief's reach and the search would walk its whole space, 2,000,000
# successors at 20 per state), so it gives up at the work limit instead.
PLAN_BUDGET = 100_000  # expanded states
PLAN_WORK = 1_000_000  # successors generated


@dataclass(frozen=True)
class AgentConfig:
    """Which parts of ApBot are switched on (the ablations switch them off)."""

    closed_loop: bool = True
    button_policy: bool = True
    explore_limit: int = EXPLORE_LIMIT
    plan_budget: int = PLAN_BUDGET
    plan_work: int = PLAN_WORK


class Stop(Exception):
    """The run ends: ``success`` claimed, or a declared failure with its reason."""

    def __init__(self, reason: str, success: bool = False) -> None:
        super().__init__(reason)
        self.reason = reason
        self.success = success


@dataclass
class Executed:
    """One action as performed: where the belief was, what it predicted, what was shown.

    ``surprises`` maps each variable the feedback contradicted to (predicted, observed); an
    observed None means the display was dark where the belief expected the value, and
    ``UNREADABLE`` that it showed text the belief's display rules cannot print. ``unchanged``:
    the display stayed exactly as it was although the belief predicted a change (a key
    ignored without a sign looks like this).
    """

    action: PlannedAction
    pointer: tuple[str, int] | None  # the belief's feature step after the action
    variable: str | None  # the variable that step adjusts
    feedback: Feedback
    believed_accepted: bool
    before: tuple[str, int] | None = None  # the belief's feature step before the action
    predicted: Any = None  # the belief's value of ``variable`` after the action
    seen: Seen | None = None
    surprises: dict[str, tuple[Any, Any]] = field(default_factory=dict)
    unchanged: bool = False
    buffer: str = ""  # the keypad digits the belief had typed into the step after the action
    state_before: State | None = None  # the belief's state before the action
    unseen_before: frozenset[str] = frozenset()  # changed unseen (or guessed) before the action
    shown_before: dict[str, Any] = field(default_factory=dict)  # last shown, before the action

    def observed(self, name: str) -> Any:
        """The value of ``name`` the display showed after this action (MISSING if none)."""
        return MISSING if self.seen is None else self.seen.observed(name)

    @property
    def refused(self) -> bool:
        """The appliance refused what the belief expected to work."""
        return self.believed_accepted and not self.feedback.accepted

    @property
    def surprising(self) -> bool:
        return self.refused or bool(self.surprises)


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
        self.last_seen = Seen()
        self.explored: set[str] = set()
        self.evidence: dict[str, Any] = {}  # the value the display showed last, per variable
        self.stale: set[str] = set()  # changed in the belief since the display last showed them
        self.discovered: set[str] = set()  # settings the belief lacked, found on the panel
        self.blind: set[str] = set()  # changed while the display was dark, not seen since
        self.guessed_initial: set[str] = set()  # their programmes' start values are guesses
        self.contradicted: dict[str, Any] = {}  # last shown as a value the belief cannot hold
        self.unread: set[str] = set()  # due on the display, but shown as the belief cannot read
        self.ever_seen: set[str] = set()  # shown (or shown absent) at least once
        # how often the display moved the belief's state where its own transitions did not go
        self.moved = 0
        self._unshowable: tuple[Any, frozenset[str]] = (None, frozenset())

    # --- acting ------------------------------------------------------------------------------

    def start(self) -> None:
        """Reset the appliance and believe what it shows."""
        self.last = self.env.reset()
        self.last_seen = self.perceive(self.last, self.belief.expected())
        self.sync(self.last_seen)

    def press(self, action: PlannedAction, exploring: bool = False) -> Executed:
        """Perform ``action`` on the appliance and on the belief; the belief then follows what
        the display shows, and whatever contradicted its prediction is kept as a surprise."""
        before_state = self.belief.state
        before = self.belief.pointer()
        before_text = self.last.text
        unseen = frozenset(self.stale | self.blind | self.unread | self.guessed_initial)
        shown_before = dict(self.evidence)
        if action.name not in self.offered:  # the belief has a control the appliance lacks
            feedback = Feedback(
                self.last.text, dict(self.last.values), False, "the appliance has no such action"
            )
            self.episode.log(
                "action",
                action=action.name,
                display=feedback.text,
                accepted=False,
                exploring=exploring,
            )
            return Executed(action, before, None, feedback, True, before)
        believed = self.belief.advance(action.name, action.seconds)
        pointer = self.belief.pointer() if believed else before
        variable = self.step_variable(pointer) if believed else None
        predicted = self.belief.value(variable) if variable else None
        expected = self.belief.expected()
        feedback = self.env.step(action.name, action.seconds)
        self.episode.execution_steps += 1
        self.last = feedback
        self.episode.log(
            "action",
            action=action.name,
            display=feedback.text,
            values=dict(feedback.values),
            accepted=feedback.accepted,
            exploring=exploring,
        )
        if not feedback.accepted:
            self.belief.state = before_state  # a refused action changes nothing
            # a refusal that left the display as it was (no message) is a key ignored here
            mute = believed and feedback.text == before_text
            return Executed(
                action, pointer, variable, feedback, believed, before, predicted, unchanged=mute
            )
        buffer = self.belief.state.buffer
        seen = self.perceive(feedback, expected)
        if variable and variable in expected.values and silent(self.belief.model, variable):
            unsaid = seen.observed(variable) is MISSING and variable not in seen.candidates
            readable = bool(seen.screens) and not (seen.unknown or seen.blank)
            # silence says something only where the other value's word would be: the
            # setting's own screen, any screen when it is a lamp, or a screen the key changed
            # to with nothing else moved. A screen that shows the key did something else (or
            # nothing) would be as silent had the key failed: a lock still on, its LOCKED
            # shown only when a key is refused
            moved = seen.outside or any(
                self.belief.value(n) != v for n, v in seen.values.items() if n != variable
            )
            speaks = (
                ("focus", variable) in seen.screens
                or variable in self.belief.model.display.indicators
                or (feedback.text != before_text and not moved)
            )
            if unsaid and readable and speaks and predicted in silent(self.belief.model, variable):
                # the value the key was to set prints nothing, and its screen does not show the
                # word of any other value: it shows that value by its silence
                seen.values[variable] = predicted
        surprises = {
            name: (self.belief.value(name), value)
            for name, value in (*seen.values.items(), *seen.outside.items())
            if self.belief.value(name) != value
        }
        for name in seen.absent:
            if self.belief.value(name) is not None:
                surprises[name] = (self.belief.value(name), None)
        if variable and variable in expected.values and variable not in seen.shown():
            # expected on the display, and it is dark (or shows what the belief cannot read)
            surprises[variable] = (predicted, UNREADABLE if seen.unknown else None)
            if seen.unknown:
                self.unread.add(variable)
        unchanged = (
            bool(surprises)
            and feedback.text == before_text
            and (expected.text != before_text or before_state != self.belief.state)
        )
        before_values = self.belief.compiled.assignment(before_state)
        changed = {n for n, v in self.belief.values().items() if before_values[n] != v}
        self.stale |= changed
        hiding = self.belief.compiled.hiding_guard(self.belief.state)
        if hiding is not None:  # changed behind a dark panel: nothing showed it happen
            own = {self.belief.compiled.vars[v].name for v, _ in hiding.conditions}
            self.blind |= changed - own
        model = self.belief.model
        quiet = {n for n in changed if _runs(n) or "lock" in n.split("_")} | _locks(model)
        if changed - self.discovered - quiet:
            # a setting found on the panel may depend on what just changed (a programme that
            # resets it) though the belief cannot know: it needs seeing again
            self.stale |= self.discovered - set(seen.values)
        for name in self.guessed_initial:  # its programmes' start values are only guesses
            parent = model.variables[name].depends_on if name in model.variables else None
            if parent is not None and (parent in changed or variable == parent):
                self.stale.add(name)
        if surprises and variable is not None and not seen.showing(variable):
            # the display did not come to the step the belief entered: the key did nothing
            # visible, or something else, so the belief must not keep what it predicted the key
            # would do — only what the display shows (``pointer`` still says where it meant to go)
            self.belief.state = before_state
        self.sync(seen)
        if seen.partial and not feedback.values:
            self._suspect_unread(seen)
        return Executed(
            action,
            pointer,
            variable,
            feedback,
            believed,
            before,
            predicted,
            seen,
            surprises,
            unchanged,
            buffer,
            before_state,
            unseen,
            shown_before,
        )

    def _suspect_unread(self, seen: Seen) -> None:
        """A screen found inside text the belief cannot print. A setting whose label is in that
        text, unread, is shown in a way the belief cannot read; a time in it that is not what
        the belief holds for a time setting shown before may be that setting, changed where
        the belief saw no reason (a CANCEL that also clears the delay). Either needs seeing
        again before anything rests on it."""
        read = seen.shown()
        for name, spec in self.belief.model.variables.items():
            label = spec.display_label(name)
            if name in read or not spec.visible or len(label) < 3:
                continue
            found = re.search(rf"(?<!\w){re.escape(label)}(?!\w)", seen.text, re.IGNORECASE)
            if found is None:
                continue
            after = seen.text[found.end() :].strip().casefold()
            printed = display_value(spec, self.belief.value(name)).strip().casefold()
            if not (printed and after.startswith(printed)):
                # its label is on the display, followed by words the belief cannot read as
                # what it holds: that rests on nothing the display said
                self.unread.add(name)
        times = re.findall(r"(?<![\d:])\d{1,2}:\d{2}(?::\d{2})?(?![\d:])", seen.text)
        if not times:
            return
        for name, spec in self.belief.model.variables.items():
            if not isinstance(spec, TimeVariable) or name in read:
                continue
            if name not in self.evidence or name in self.stale:
                continue
            believed = magnitude(spec, self.belief.value(name))
            for text in times:
                try:
                    shown = magnitude(spec, parse_value(spec, text))
                except ValueProblem:
                    continue
                if shown is not None and shown != believed:
                    self.stale.add(name)
                    break

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
        self.ever_seen |= set(seen.values) | set(seen.outside) | seen.absent
        self.contradicted.update(seen.outside)
        for name in seen.values:
            self.contradicted.pop(name, None)

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

    def count_reasoning_step(self) -> None:
        """One more decision; the run ends instead when the limit is reached."""
        if self.episode.reasoning_steps >= self.context.max_reasoning_steps:
            raise Stop(f"reached the limit of {self.context.max_reasoning_steps} reasoning steps")
        self.episode.reasoning_steps += 1

    def again(self, kind: Any, key: str, message: str) -> None:
        """One more occurrence of a repeated problem; give up when it keeps coming back."""
        if not self.budget.again(kind, key):
            raise Stop(message)

    def forget_pointer(self) -> None:
        """After presses the belief cannot follow, assume no procedure is in progress."""
        self.belief.set_pointer(None)
        self.reread()


def silent(model: ApplianceModel, name: str) -> frozenset[Any]:
    """The values of discrete ``name`` that its screen prints as nothing ("off" of a lock
    shown as LOCKED or not at all), when every other value prints a word of its own; empty
    otherwise."""
    spec = model.variables.get(name)
    if not isinstance(spec, DiscreteVariable) or not isinstance(spec.show, dict):
        return frozenset()
    texts = {value: (spec.show.get(str(value)) or "").strip() for value in spec.values or []}
    quiet = frozenset(v for v, text in texts.items() if not text)
    words = [text.casefold() for text in texts.values() if text]
    if len(quiet) != 1 or len(set(words)) != len(words):
        return frozenset()
    return quiet


def _locks(model: ApplianceModel) -> set[str]:
    """Locks: settings a guard of the model tests for a value other than their starting one
    (a child lock on) without darkening the panel. Engaging one freezes keys, resets nothing
    (a setting named a lock is one too, where the reader missed its guard)."""
    found = set()
    for guard in model.guards:
        if guard.hide:
            continue
        for name, condition in guard.when.items():
            spec = model.variables.get(name)
            if not isinstance(spec, DiscreteVariable) or not spec.values:
                continue
            held = condition if isinstance(condition, list) else [condition]
            start = spec.initial if spec.initial is not None else spec.values[0]
            if start not in held:
                found.add(name)
    return found


def _runs(name: str) -> bool:
    """A run state (running, heating…): starting a cycle resets no setting."""
    return any(word in name for word in ("running", "heating", "dispensing", "status"))


# --- values ------------------------------------------------------------------------------------


def magnitude(spec: Any, value: Any) -> float | None:
    """A numeric or time value as a number (seconds for times); None for anything else."""
    if value is None:
        return None
    try:
        if isinstance(spec, TimeVariable):
            return float(parse_hms(str(value)))
        return float(value)
    except (TypeError, ValueError):
        return None


def loose(spec: Any, raw: Any) -> Any:
    """``raw`` in canonical form for ``spec``'s type, whether or not its domain has it."""
    try:
        return parse_value(spec, raw)
    except ValueProblem:
        return None


def canonical(spec: Any, number: float | None) -> Any:
    """A number back in the model's notation (``HH:MM:SS`` for times)."""
    if number is None:
        return None
    if isinstance(spec, TimeVariable):
        return format_hms(int(number))
    return tidy(number)


def tidy(number: float) -> int | float:
    return int(number) if float(number).is_integer() else number


def summary(values: list[Any] | None) -> str:
    if not values:
        return "nothing"
    shown = [str(v) for v in values]
    return ", ".join(shown) if len(shown) <= 12 else ", ".join(shown[:10]) + f", … ({len(shown)})"
