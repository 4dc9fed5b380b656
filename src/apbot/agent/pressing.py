"""The one primitive that acts: press a key on the appliance and on the belief together.

:func:`press` performs an action, simulates it on the belief, reads the feedback in the light of
the prediction and keeps whatever contradicted it as a surprise; it also keeps the session's
bookkeeping of what the display has (not) confirmed. :meth:`Session.press` calls it.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

from apbot.agent.environment import Feedback
from apbot.agent.executed import Executed
from apbot.agent.looking import selecting
from apbot.agent.perception import MISSING, UNREADABLE, Seen
from apbot.agent.quantities import magnitude
from apbot.model.display import display_value, typed_text
from apbot.model.domain import ValueProblem, parse_value
from apbot.model.schema import ApplianceModel, DiscreteVariable, Entry, TimeVariable
from apbot.plan.plan import PlannedAction
from apbot.sim.compiled import State

if TYPE_CHECKING:
    from apbot.agent.session import Session

__all__ = ["lights_up", "locks", "press", "runs", "silent", "suspect_unread", "typing"]


def press(
    session: Session, action: PlannedAction, exploring: bool = False, typing_on: bool = False
) -> Executed:
    """Perform ``action`` on the appliance and on the belief; the belief then follows what
    the display shows, and whatever contradicted its prediction is kept as a surprise
    (``typing_on``: the plan types more digits of this entry next, see :func:`typing`)."""
    before_state = session.belief.state
    before = session.belief.pointer()
    before_text = session.last.text
    unseen = frozenset(session.stale | session.blind | session.unread | session.guessed_initial)
    shown_before = dict(session.evidence)
    if action.name not in session.offered:  # the belief has a control the appliance lacks
        feedback = Feedback(
            session.last.text, dict(session.last.values), False, "the appliance has no such action"
        )
        session.episode.log(
            "action",
            action=action.name,
            display=feedback.text,
            accepted=False,
            exploring=exploring,
        )
        return Executed(action, before, None, feedback, True, before)
    believed = session.belief.advance(action.name, action.seconds)
    pointer = session.belief.pointer() if believed else before
    variable = session.step_variable(pointer) if believed else None
    predicted = session.belief.value(variable) if variable else None
    expected = session.belief.expected()
    feedback = session.env.step(action.name, action.seconds)
    session.episode.execution_steps += 1
    session.last = feedback
    session.episode.log(
        "action",
        action=action.name,
        display=feedback.text,
        values=dict(feedback.values),
        accepted=feedback.accepted,
        exploring=exploring,
    )
    if not feedback.accepted:
        session.belief.state = before_state  # a refused action changes nothing
        # a refusal that left the display as it was (no message) is a key ignored here
        mute = believed and feedback.text == before_text
        return Executed(
            action, pointer, variable, feedback, believed, before, predicted, unchanged=mute
        )
    buffer = session.belief.state.buffer
    seen = session.perceive(feedback, expected)
    if variable and variable in expected.values and silent(session.belief.model, variable):
        unsaid = seen.observed(variable) is MISSING and variable not in seen.candidates
        readable = bool(seen.screens) and not (seen.unknown or seen.blank)
        # silence says something only where the other value's word would be: the
        # setting's own screen, any screen when it is a lamp, or a screen the key changed
        # to with nothing else moved. A screen that shows the key did something else (or
        # nothing) would be as silent had the key failed: a lock still on, its LOCKED
        # shown only when a key is refused
        moved = seen.outside or any(
            session.belief.value(n) != v for n, v in seen.values.items() if n != variable
        )
        speaks = (
            ("focus", variable) in seen.screens
            or variable in session.belief.model.display.indicators
            or (feedback.text != before_text and not moved)
        )
        if unsaid and readable and speaks and predicted in silent(session.belief.model, variable):
            # the value the key was to set prints nothing, and its screen does not show the
            # word of any other value: it shows that value by its silence
            seen.values[variable] = predicted
    if (
        variable is not None
        and variable not in seen.shown()
        and lights_up(session, before_state, variable, before_text, feedback.text)
    ):
        seen.values[variable] = predicted
    surprises = {
        name: (session.belief.value(name), value)
        for name, value in (*seen.values.items(), *seen.outside.items())
        if session.belief.value(name) != value
    }
    for name in seen.absent:
        if session.belief.value(name) is not None:
            surprises[name] = (session.belief.value(name), None)
    typed = (
        typing_on
        and variable is not None
        and variable not in seen.values
        and variable not in seen.candidates
        and set(surprises) <= {variable}  # a display that surprised elsewhere is judged whole
        and typing(session, variable, feedback.text)
    )
    if variable is not None and typed:
        # digits on their way to a value: a keypad that shows the entry as it is typed says
        # nothing yet of the value (nor of its range); the check waits for the entry to end
        seen.outside.pop(variable, None)
        seen.absent.discard(variable)
        surprises.pop(variable, None)
    if variable and not typed and variable in expected.values and variable not in seen.shown():
        # expected on the display, and it is dark (or shows what the belief cannot read)
        surprises[variable] = (predicted, UNREADABLE if seen.unknown else None)
        if seen.unknown:
            session.unread.add(variable)
    unchanged = (
        bool(surprises)
        and feedback.text == before_text
        and (expected.text != before_text or before_state != session.belief.state)
    )
    before_values = session.belief.compiled.assignment(before_state)
    changed = {n for n, v in session.belief.values().items() if before_values[n] != v}
    session.stale |= changed
    hiding = session.belief.compiled.hiding_guard(session.belief.state)
    if hiding is not None:  # changed behind a dark panel: nothing showed it happen
        own = {session.belief.compiled.vars[v].name for v, _ in hiding.conditions}
        session.blind |= changed - own
    model = session.belief.model
    quiet = {n for n in changed if runs(n) or "lock" in n.split("_")} | locks(model)
    if changed - session.discovered - quiet:
        # a setting found on the panel may depend on what just changed (a programme that
        # resets it) though the belief cannot know: it needs seeing again
        session.stale |= session.discovered - set(seen.values)
    if variable in changed - quiet and action.name in selecting(model):
        # a programme chosen: many appliances bring their settings back to its defaults,
        # whether or not the manual says so: what the display showed of them before is in doubt
        reprogrammed = set(session.evidence) - seen.shown() - changed
        session.doubtful |= reprogrammed
        session.reprogrammed |= reprogrammed
    if variable in changed - quiet and pointer is not None:
        # the settings a procedure takes after this choice belong to it (the weight typed for
        # the food chosen): what the display showed of them before is in doubt
        steps = model.features.get(pointer[0], [])
        later = {s.variable for s in steps[pointer[1] + 1 :] if s.variable} - {variable}
        rechosen = (later & set(session.evidence)) - seen.shown() - changed
        session.doubtful |= rechosen
        session.rechosen |= rechosen
    asked_off = {n for n, v in session.context.goal.items() if str(v).casefold() == "off"}
    if any(runs(n) and str(session.belief.value(n)) == "off" for n in changed - asked_off):
        # a cycle stopped: many appliances clear what was set for it with the same key (STOP /
        # CANCEL), whatever the manual says: what the display showed of it before is in doubt,
        # and a keypad setting is typed again — unless the goal itself asks that state off (a
        # heating lamp switched off as asked is no cycle stopped)
        stopped = set(session.evidence) - seen.shown() - changed
        session.doubtful |= stopped
        session.rechosen |= stopped
    for name in session.guessed_initial:  # its programmes' start values are only guesses
        parent = model.variables[name].depends_on if name in model.variables else None
        if parent is not None and (parent in changed or variable == parent):
            session.stale.add(name)
    if surprises and variable is not None and not seen.showing(variable):
        # the display did not come to the step the belief entered: the key did nothing
        # visible, or something else, so the belief must not keep what it predicted the key
        # would do — only what the display shows (``pointer`` still says where it meant to go)
        session.belief.state = before_state
    if surprises and (variable is None or ("focus", variable) not in seen.screens):
        # the press did something else than the belief foresaw (not merely another value of
        # the setting it adjusts): what else it did, the belief cannot say
        session.doubtful |= set(session.evidence) - seen.shown()
    session.sync(seen)
    if seen.partial and not feedback.values:
        suspect_unread(session, seen)
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
        typed,
        before_text,
    )


def typing(session: Session, variable: str, text: str) -> bool:
    """Whether ``text`` shows the digits being typed into ``variable``'s keypad entry in
    place of its value. Real keypads print an entry as it is typed ("SET 5" on the way to
    56) whatever the manual said, filling it from the right (a clock typed 1, 7 shows
    ``00:17``) or from the left (``17:--``), and some keep the last fill that made a time
    while the digits typed since make none (``00:17`` after 1, 7, 0). The belief in the
    middle of typing (a non-empty buffer on the setting's step) that finds such a fill as a
    word of the display has seen no surprise yet."""
    spec = session.belief.model.variables.get(variable)
    entry = getattr(spec, "entry", None)
    buffer = session.belief.state.buffer
    if entry is None or not buffer:
        return False
    pointer = session.belief.pointer()
    if pointer is None or session.step_variable(pointer) != variable:
        return False
    return any(re.search(pattern, text) for pattern in _fills(entry, buffer))


def _fills(entry: Entry, buffer: str) -> list[str]:
    """Patterns of the words a keypad may show while ``buffer`` is typed: the digits shifted
    in from the right (``typed_text``: ``00:17``) or laid in from the left, raw (``170``) or
    in the entry's clock groups with the rest blank (``17:0-``); and, while the digits shifted
    in make no time (``01:70``), the last fill that made one (``00:17``)."""
    words = {typed_text(entry, buffer), buffer}
    if ":" in entry.format:
        groups = {"h:mm": (1, 2), "hh:mm:ss": (2, 2, 2)}.get(entry.format, (2, 2))
        laid, rest = [], buffer
        for width in groups:
            if rest:
                laid.append(rest[:width])
                rest = rest[width:]
        words.add(":".join(laid))
        for end in range(len(buffer), 0, -1):
            shifted = typed_text(entry, buffer[:end])
            if all(int(part) < 60 for part in shifted.split(":")[1:]):
                words.add(shifted)
                break
    # a word of its own: digits glued to a word ("PL7") are the value printed another way;
    # blanks still to fill ("17:0-", "25_") may follow
    return [rf"(?<![\w:.]){re.escape(word)}(?![^\W_]|\.\d|:\d)" for word in sorted(words)]


def lights_up(session: Session, before: State, variable: str, before_text: str, text: str) -> bool:
    """Whether the key that sets ``variable`` lit a dark panel as the belief says it would:
    the belief had the panel dark by a guard on ``variable`` (switched off) and predicts it
    lit, and the display, blank before, now shows something. Whatever the text (a screen
    the belief cannot print), a lit panel says the guard no longer holds: the switch is on."""
    if before_text.strip() or not text.strip():
        return False
    compiled = session.belief.compiled
    hiding = compiled.hiding_guard(before)
    if hiding is None or compiled.hiding_guard(session.belief.state) is not None:
        return False
    return any(compiled.vars[v].name == variable for v, _ in hiding.conditions)


def suspect_unread(session: Session, seen: Seen) -> None:
    """A screen found inside text the belief cannot print. A setting whose label is in that
    text, unread, is shown in a way the belief cannot read; a time in it that is not what
    the belief holds for a time setting shown before may be that setting, changed where
    the belief saw no reason (a CANCEL that also clears the delay). Either needs seeing
    again before anything rests on it."""
    read = seen.shown()
    for name, spec in session.belief.model.variables.items():
        label = spec.display_label(name)
        if name in read or not spec.visible or len(label) < 3:
            continue
        found = re.search(rf"(?<!\w){re.escape(label)}(?!\w)", seen.text, re.IGNORECASE)
        if found is None:
            continue
        after = seen.text[found.end() :].strip().casefold()
        printed = display_value(spec, session.belief.value(name)).strip().casefold()
        if not (printed and after.startswith(printed)):
            # its label is on the display, followed by words the belief cannot read as
            # what it holds: that rests on nothing the display said
            session.unread.add(name)
    times = re.findall(r"(?<![\d:])\d{1,2}:\d{2}(?::\d{2})?(?![\d:])", seen.text)
    if not times:
        return
    for name, spec in session.belief.model.variables.items():
        if not isinstance(spec, TimeVariable) or name in read:
            continue
        if name not in session.evidence or name in session.stale:
            continue
        believed = magnitude(spec, session.belief.value(name))
        for text in times:
            try:
                shown = magnitude(spec, parse_value(spec, text))
            except ValueProblem:
                continue
            if shown is not None and shown != believed:
                session.stale.add(name)
                break


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


def locks(model: ApplianceModel) -> set[str]:
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


def runs(name: str) -> bool:
    """A run state (running, heating…): starting a cycle resets no setting."""
    return any(word in name for word in ("running", "heating", "dispensing", "status"))
