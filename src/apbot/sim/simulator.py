"""Run a model as a deterministic appliance: press things, read the display.

The same engine runs the benchmark's ground truth and an agent's belief model.

>>> from apbot.examples import load_example
>>> sim = Simulator(load_example("microwave_keypad"))
>>> [sim.step(a).display for a in ("press_time_cook", "press_1", "press_3", "press_0")]
['COOK 00:00', 'COOK 00:01', 'COOK 00:13', 'COOK 01:30']
"""

from __future__ import annotations

import math
import operator
from collections.abc import Mapping
from dataclasses import dataclass, field
from numbers import Real
from typing import Any

from apbot.model.display import lamp_for, show_template, typed_text
from apbot.model.schema import TEMPLATE_FIELD, ApplianceModel
from apbot.sim.compiled import NOT_HERE, CompiledModel, State, compiled_model


@dataclass(slots=True)
class Observation:
    """What an agent sees after one action.

    ``display`` is the text on the appliance's main display; ``lamps`` the texts of the lit
    indicator lamps (``display.indicators``), and ``text`` both together, as a camera on the
    panel would read them. ``values`` are the variables shown (the one being adjusted, the
    idle screen's, the indicators'), visible ones only. ``accepted`` says whether the
    appliance took the action, ``reason`` why not, and ``perceptible`` whether a refusal makes
    a sign (a beep, a message) or passes unnoticed.
    """

    display: str
    values: dict[str, Any] = field(default_factory=dict)
    accepted: bool = True
    reason: str = ""
    focus: str | None = None
    lamps: tuple[str, ...] = ()
    perceptible: bool = True

    @property
    def text(self) -> str:
        """The whole panel as text: the main display, then the lit lamps."""
        return panel_text(self.display, self.lamps)


def panel_text(display: str, lamps: tuple[str, ...] | list[str]) -> str:
    """The main display and the lit lamps, separated by two spaces."""
    return "  ".join(part for part in (display, *lamps) if part)


class UnknownAction(KeyError, ValueError):
    """An action name (or index) the model does not have. A ``ValueError`` too: the argument
    is wrong; a ``KeyError`` for callers that looked names up in a dict before."""

    def __str__(self) -> str:
        return str(self.args[0])


class UnknownVariable(KeyError, ValueError):
    """A variable name the model does not have (in a goal, or asked for by name)."""

    def __str__(self) -> str:
        return str(self.args[0])


def require_model(model: Any, who: str) -> CompiledModel:
    """The compiled form of ``model``, or a :class:`TypeError` saying what ``who`` needs.

    A model that fails to compile (built with ``check=False`` and broken) is reported with
    the checker's problems rather than the compiler's KeyError.
    """
    if not isinstance(model, ApplianceModel | CompiledModel):
        raise TypeError(
            f"{who} needs an ApplianceModel (from apbot.model.load.load_model or parse_model) "
            f"or a CompiledModel, not {type(model).__name__}"
        )
    if isinstance(model, CompiledModel):
        return model
    try:
        return compiled_model(model)
    except Exception:
        from apbot.model.problems import ModelError
        from apbot.model.validate import check_model

        errors = [p for p in check_model(model) if p.severity == "error"]
        if errors:
            raise ModelError(errors, f"the model given to {who}") from None
        raise


def hold_seconds(seconds: Any) -> float:
    """``seconds`` as a hold duration: a finite number above zero, or a clear error.

    The terminal simulator always refused ``nan``, ``inf`` and negative holds; the Python API
    now does too, instead of comparing them with the required duration.
    """
    if isinstance(seconds, bool) or not isinstance(seconds, Real):
        raise TypeError(
            f"seconds is how long a hold lasts, a number; got {type(seconds).__name__} {seconds!r}"
        )
    value = float(seconds)
    if not math.isfinite(value) or value <= 0:
        raise ValueError(f"seconds must be a finite number above zero; got {seconds!r}")
    return value


class Simulator:
    """A stateful wrapper around :class:`CompiledModel` with names instead of indices."""

    def __init__(self, model: ApplianceModel | CompiledModel) -> None:
        self.compiled = (
            model if isinstance(model, CompiledModel) else require_model(model, "Simulator")
        )
        self.model = self.compiled.model
        self.state: State = self.compiled.initial_state()
        self._display_cache: dict[tuple[int, int, int], str] = {}
        self._plain_show = {v: _is_plain(var.spec.show) for v, var in enumerate(self.compiled.vars)}
        self._goal_values: dict[tuple[str, type, Any], Any] = {}
        self.running_for: list[float] = [0.0] * len(self.compiled.cycles)  # seconds, per cycle

    @property
    def actions(self) -> list[str]:
        """Action names, in model order."""
        return list(self.compiled.action_names)

    def reset(self, state: State | None = None) -> Observation:
        """Back to the initial state (or to ``state``); returns what the display shows."""
        if state is not None:
            self.compiled.check_state(state)
        self.state = state if state is not None else self.compiled.initial_state()
        self.running_for = [0.0] * len(self.compiled.cycles)
        return self.observe()

    def action_id(self, action: str | int) -> int:
        """The index of an action given by name or by index (checked either way)."""
        if isinstance(action, str):
            try:
                return self.compiled.action_index[action]
            except KeyError:
                from apbot.model.values import closest_matches

                close = closest_matches(action, self.compiled.action_names, limit=1)
                hint = f"; did you mean {close[0]!r}?" if close else ""
                raise UnknownAction(f"unknown action {action!r}{hint}") from None
        try:
            if isinstance(action, bool):
                raise TypeError
            index = operator.index(action)
        except TypeError:
            raise TypeError(
                f"an action is a name (str) or an index (int), not {type(action).__name__} "
                f"{action!r}"
            ) from None
        count = len(self.compiled.action_names)
        if not 0 <= index < count:
            raise UnknownAction(
                f"action index {index} is out of range: the model has {count} actions, "
                f"0 to {count - 1}"
            )
        return index

    def step(self, action: str | int, seconds: float | None = None) -> Observation:
        """Perform one action, by name or index. ``seconds`` is how long a hold lasts
        (default: long enough); a press ignores it, but it must be a positive number."""
        aid = self.action_id(action)
        if seconds is not None:
            seconds = hold_seconds(seconds)
        compiled = self.compiled
        new = compiled.apply(self.state, aid, seconds)
        if new is None:
            return self._refused(aid, seconds)
        self.state = new
        for c in range(len(compiled.cycles)):  # a press takes no time; one that stops a cycle
            if not compiled.cycle_running(new, c):  # (or never started it) restarts its clock
                self.running_for[c] = 0.0
        return self.observe()

    def wait(self, seconds: float) -> Observation:
        """Let ``seconds`` pass without touching the panel: a running cycle (``cycles``) that
        reaches its length ends by itself. Presses take no time; only waiting does."""
        seconds = hold_seconds(seconds)
        compiled = self.compiled
        for c in range(len(compiled.cycles)):
            if not compiled.cycle_running(self.state, c):
                continue
            self.running_for[c] += seconds
            if self.running_for[c] + 1e-9 >= compiled.cycle_seconds(self.state, c):
                self.state = compiled.end_cycle(self.state, c)
                self.running_for[c] = 0.0
        return self.observe()

    def _refused(self, aid: int, seconds: float | None) -> Observation:
        compiled = self.compiled
        name = compiled.action_names[aid]
        code = compiled.refusal(self.state, aid)
        observation = self.observe()
        ignored_beeps = compiled.model.display.ignored == "beep"
        if code is not None and code >= 0:
            guard = compiled.guards[code]
            conditions = ", ".join(
                f"{compiled.vars[v].name} is {compiled.value(self.state, compiled.vars[v].name)}"
                for v, _ in guard.conditions
            )
            allowed = [compiled.action_names[a] for a in sorted(guard.allowed)]
            verb = "works" if len(allowed) == 1 else "work"
            reason = (
                f"{guard.name + ': ' if guard.name else ''}{conditions}; only "
                f"{', '.join(allowed)} {verb}"
            )
            if guard.display:  # the message replaces the main display; every lamp stays lit
                observation.display = guard.display
                observation.lamps = self._lamps(-1)
                observation.values = {
                    name: value
                    for name, value in observation.values.items()
                    if name in compiled.model.display.indicators
                }
                observation.focus = None
            perceptible = compiled.model.guards[code].refusal_signal() == "beep"
        elif code == NOT_HERE:
            reason = f"{name} does nothing here"
            perceptible = ignored_beeps
        else:
            needed = compiled.hold_seconds[aid]
            reason = f"{name} must be held for {needed:g} s (held {seconds:g} s)"
            perceptible = ignored_beeps
        observation.accepted = False
        observation.reason = reason
        observation.perceptible = perceptible
        return observation

    def observe(self) -> Observation:
        """The display for the current state, without acting."""
        compiled = self.compiled
        state = self.state
        focus = compiled.focus(state)
        values: dict[str, Any] = {}
        hiding = compiled.hiding_guard(state) if compiled.guards else None
        if hiding is not None:
            self._indicator_values(values)
            return Observation(hiding.display, values, True, "", None)
        if focus >= 0:
            var = compiled.vars[focus]
            if var.spec.visible:
                values[var.name] = compiled.value(state, var.name)
            key = (focus, state.values[focus], state.values[var.parent] if var.parent >= 0 else 0)
            typed = self._typed(state, focus)
            text = self._display_cache.get(key) if self._plain_show[focus] and not typed else None
            if text is None:
                text = self._show(state, focus, typed)
                if self._plain_show[focus] and not typed:
                    self._display_cache[key] = text
        else:
            text = self._template(compiled.model.display.idle, state)
            for name in TEMPLATE_FIELD.findall(compiled.model.display.idle):
                if compiled.model.variables[name].visible:
                    values[name] = compiled.value(state, name)
        self._indicator_values(values)
        return Observation(
            text,
            values,
            True,
            "",
            compiled.vars[focus].name if focus >= 0 else None,
            self._lamps(focus),
        )

    def _lamps(self, focus: int) -> tuple[str, ...]:
        """The lit lamps, but for the variable the main display shows already."""
        compiled = self.compiled
        return tuple(
            lamp
            for name in compiled.model.display.indicators
            if compiled.var_index[name] != focus
            and (lamp := lamp_text(compiled, self.state, compiled.var_index[name]))
        )

    def _indicator_values(self, values: dict[str, Any]) -> None:
        for name in self.compiled.model.display.indicators:
            if self.compiled.model.variables[name].visible:
                values[name] = self.compiled.value(self.state, name)

    def _typed(self, state: State, v: int) -> str:
        """The digits on display while they are typed (``Entry.shows: typed``), else ""."""
        if not state.buffer or self.compiled.steps[state.step].variable != v:
            return ""
        entry = getattr(self.compiled.vars[v].spec, "entry", None)
        return typed_text(entry, state.buffer) if entry and entry.shows == "typed" else ""

    def _show(self, state: State, v: int, typed: str = "") -> str:
        var = self.compiled.vars[v]
        spec = var.spec
        if not spec.visible:
            return ""
        value = typed or self.compiled.render_value(state, v)
        show = show_template(spec, self.compiled.value(state, var.name))
        return self._template(show, state, value=value, label=spec.display_label(var.name)).strip()

    def _template(self, text: str, state: State, **extra: str) -> str:
        def fill(match: Any) -> str:
            name = match.group(1)
            if name in extra:
                return extra[name]
            return self.compiled.render_value(state, self.compiled.var_index[name])

        return TEMPLATE_FIELD.sub(fill, text)

    # --- convenience ---------------------------------------------------------------------------

    def value(self, name: str) -> Any:
        """Canonical value of a variable now."""
        try:
            return self.compiled.value(self.state, name)
        except (KeyError, TypeError):
            raise self._unknown_variable(name) from None

    def _unknown_variable(self, name: Any) -> UnknownVariable:
        from apbot.model.values import closest_matches, preview

        names = list(self.compiled.var_index)
        close = closest_matches(str(name), names, limit=1)
        hint = f"; did you mean {close[0]!r}?" if close else f" (it has {preview(names)})"
        return UnknownVariable(f"the model has no variable {name!r}{hint}")

    def assignment(self) -> dict[str, Any]:
        """Every variable's canonical value now."""
        return self.compiled.assignment(self.state)

    def satisfies(self, goal: Mapping[str, Any]) -> bool:
        """Whether every goal variable has its goal value now.

        Goal values may be written in any accepted notation ("80 °C", "on"); they are
        normalised once and remembered. An unknown variable or a value outside the variable's
        values raises (a goal that can never hold is a mistake, not a False).
        """
        if not isinstance(goal, Mapping):
            raise TypeError(
                f"a goal maps variable names to values, e.g. {{'power': 'on'}}; "
                f"got {type(goal).__name__}"
            )
        for name, wanted in goal.items():
            current = self.value(name)
            if current != wanted and current != self._goal_value(name, wanted):
                return False
        return True

    def _goal_value(self, name: str, raw: Any) -> Any:
        key = (name, type(raw), raw)
        try:
            known = self._goal_values.get(key, _UNSEEN)
        except TypeError:  # unhashable: a list or a dict is not one value
            raise TypeError(
                f"goal {name}: a goal value is one value, not a {type(raw).__name__}"
            ) from None
        if known is _UNSEEN:
            from apbot.model.domain import ValueProblem, normalise

            try:
                known = normalise(self.model.variables[name], raw)
            except ValueProblem as exc:
                raise ValueProblem(f"goal {name}={raw!r}: {exc}") from None
            self._goal_values[key] = known
        return known


_UNSEEN = object()


def lamp_text(compiled: CompiledModel, state: State, v: int) -> str:
    """What an indicator lamp shows now (:func:`apbot.model.display.lamp_for`).

    >>> from apbot.examples import load_example
    >>> compiled = CompiledModel(load_example("washing_machine"))
    >>> lamp_text(compiled, compiled.initial_state(), compiled.var_index["child_lock"])
    ''
    """
    var = compiled.vars[v]
    values = var.domains[0].values if var.parent < 0 and var.domains[0] is not None else ()
    return lamp_for(var.spec, var.name, compiled.value(state, var.name), values)


def _is_plain(show: Any) -> bool:
    """Whether a display template depends only on the shown variable (so it can be cached)."""
    texts = show.values() if isinstance(show, dict) else [show or ""]
    return all(set(TEMPLATE_FIELD.findall(t)) <= {"value", "label"} for t in texts)
