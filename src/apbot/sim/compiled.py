"""The semantics of a model, compiled into lookup tables so that one step costs a few microseconds.

State
    A :class:`State` holds the index of every variable's value in its current domain (``-1``
    when a programme-dependent setting does not exist in the current programme), the feature
    pointer (a global step id, ``-1`` before any feature), and the keypad input buffer.

Feature pointer (kept from the paper)
    An action that belongs to the current step keeps the pointer there; otherwise one that
    belongs to the next step of the same feature advances to it; otherwise the action enters
    the first feature (in declaration order) whose first step contains it. An action that fits
    none of these is refused. The keypad buffer empties whenever the pointer moves to another
    step, so a digit typed for the timer never leaks into the clock. Past an ``optional``
    next step, the step after it is accepted too. Keys listed under ``anywhere`` bypass the
    pointer (it stays, or with ``leave`` returns to no feature; the buffer empties), and a
    ``wait`` at least as long as the current step's ``timeout`` returns it to no feature.

Effects
    The action that enters a step applies the step's effect too, unless the step says
    ``on_entry: show``. Every value-changing effect (next, prev, toggle, go-to, add, reset)
    compiles to a table
    ``new_index = table[current_index]`` per case of the variable; a keypad digit appends to the
    buffer and sets the variable when the buffer parses to one of its values. Side effects
    (``set``, ``reset``) of a step follow its main effect. When a programme is chosen, settings
    that depend on it return to that programme's defaults: whenever it changes, and also when
    it is assigned without changing (a go-to key pressed again, a ``reset`` or ``set`` when the
    appliance is switched off) — a real appliance re-applies the programme's defaults then.

Guards
    Checked before anything else: while a guard's condition holds, only its listed actions are
    accepted (power off, child lock, running).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, NamedTuple

from apbot.model.display import display_value
from apbot.model.domain import Domain, build_domain
from apbot.model.schema import (
    Add,
    ApplianceModel,
    DiscreteVariable,
    Entry,
    GoTo,
    NumericVariable,
    TimeVariable,
    time_step_seconds,
)
from apbot.model.values import format_hms, parse_hms, tidy_number

NONE, TABLE, DIGIT, CLEAR = 0, 1, 2, 3

# rejection reasons (negative codes; a guard's refusal is its index >= 0)
NOT_HERE = -1
TOO_SHORT = -2


class State(NamedTuple):
    """An appliance state: value indices, feature-pointer step id, keypad buffer. Hashable."""

    values: tuple[int, ...]
    step: int
    buffer: str


@dataclass(frozen=True)
class VarInfo:
    """A variable with its domains: one, or one per value of the parent (``None`` = absent)."""

    name: str
    spec: DiscreteVariable | NumericVariable | TimeVariable
    domains: tuple[Domain | None, ...]
    parent: int  # index of the variable selecting the case, or -1

    def domain(self, values: tuple[int, ...] | list[int]) -> Domain | None:
        """The domain in force for these values."""
        return self.domains[values[self.parent]] if self.parent >= 0 else self.domains[0]

    def case(self, values: tuple[int, ...] | list[int]) -> int:
        return values[self.parent] if self.parent >= 0 else 0


@dataclass(frozen=True)
class StepInfo:
    """A compiled feature step."""

    feature: str
    index: int
    variable: int  # -1 when the step adjusts no variable
    actions: frozenset[int]
    effects: dict[int, tuple[Any, ...]]  # action -> (kind, per-case tables | digit)
    side: tuple[tuple[int, tuple[tuple[int, ...] | None, ...]], ...]  # (var, per-case tables)
    next_step: int  # the next step of the same feature, or -1
    show_on_entry: bool = False  # the entering action only shows the value
    optional: bool = False  # the step may be skipped (``Step.optional``)
    timeout: float | None = None  # seconds without a key that return to no feature
    leave: bool = False  # an anywhere step that returns the pointer to no feature
    blank_clears: bool = False  # a non-digit key of this keypad step empties the buffer


@dataclass(frozen=True)
class GuardInfo:
    conditions: tuple[tuple[int, frozenset[int]], ...]
    allowed: frozenset[int]
    display: str
    name: str
    hide: bool = False


def _index_table(domain: Domain, target: int) -> tuple[int, ...]:
    return (target,) * len(domain)


def _table_for(effect: Any, domain: Domain, var: Any) -> tuple[int, ...] | None:
    """``new_index = table[index]`` for one effect on one domain (None: no such table)."""
    n = len(domain)
    if effect == "next":
        return tuple(domain.next_index(i) for i in range(n))
    if effect == "prev":
        return tuple(domain.prev_index(i) for i in range(n))
    if effect == "toggle":
        return tuple((i + 1) % n for i in range(n))
    if effect == "reset":
        return _index_table(domain, domain.initial)
    if isinstance(effect, GoTo):
        target = _value_index(domain, effect.to)
        return None if target is None else _index_table(domain, target)
    if isinstance(effect, Add):
        amount = _amount(effect.add, var)
        assert domain.magnitudes is not None
        mags = domain.magnitudes
        return tuple(domain.snap_index(mags[i] + amount, down=amount < 0) for i in range(n))
    return tuple(range(n))


def _amount(amount: Any, var: Any) -> float:
    if isinstance(var, TimeVariable):
        return float(time_step_seconds(amount) if isinstance(amount, str) else amount)
    return float(amount)


def _value_index(domain: Domain, raw: Any) -> int | None:
    """Index of a model-written value (``to:``, ``set:``, guard values) in a domain."""
    if domain.kind == "discrete":
        return domain.index.get(str(raw))
    if domain.kind == "time":
        try:
            seconds = parse_hms(str(raw))
        except ValueError:
            return None
        assert domain.magnitudes is not None
        return next((i for i, m in enumerate(domain.magnitudes) if m == seconds), None)
    try:
        number = float(raw)
    except (TypeError, ValueError):
        return None
    assert domain.magnitudes is not None
    return next((i for i, m in enumerate(domain.magnitudes) if abs(m - number) < 1e-9), None)


def parse_entry(buffer: str, entry: Entry) -> float | None:
    """The number a keypad buffer stands for (seconds for times), or None if it is not valid.

    >>> parse_entry("130", Entry(format="mm:ss")), parse_entry("190", Entry(format="mm:ss"))
    (90.0, None)
    """
    if not buffer:
        return None
    fmt = entry.format
    if fmt == "number":
        return float(int(buffer))
    if fmt == "minutes":
        return float(int(buffer) * 60)
    if fmt == "seconds":
        return float(int(buffer))
    padded = buffer.zfill(6 if fmt == "hh:mm:ss" else 4)
    if fmt == "hh:mm:ss":
        hours, minutes, secs = int(padded[:-4]), int(padded[-4:-2]), int(padded[-2:])
        if minutes >= 60 or secs >= 60:
            return None
        return float(hours * 3600 + minutes * 60 + secs)
    high, low = int(padded[:-2]), int(padded[-2:])
    if low >= 60:
        return None
    return float(high * 60 + low) if fmt == "mm:ss" else float(high * 3600 + low * 60)


def type_digit(buffer: str, digit: str, entry: Entry) -> str:
    """The buffer after typing one digit (shift out the oldest, or ignore, when full)."""
    if len(buffer) < entry.digits():
        return buffer + digit
    return (buffer + digit)[1:] if entry.overflow == "shift" else buffer


class CompiledModel:
    """Lookup tables for a validated model. Build once, step many times."""

    def __init__(self, model: ApplianceModel) -> None:
        self.model = model
        names = list(model.variables)
        self.var_index = {name: i for i, name in enumerate(names)}
        self.action_names = list(model.actions)
        self.action_index = {name: i for i, name in enumerate(self.action_names)}
        self.vars = tuple(self._compile_variable(name) for name in names)
        self.dependents: dict[int, tuple[int, ...]] = {}
        for i, var in enumerate(self.vars):
            if var.parent >= 0:
                self.dependents.setdefault(var.parent, ())
                self.dependents[var.parent] += (i,)
        self.steps = self._compile_steps()
        self.anywhere_steps = self._compile_anywhere()
        # every step an analysis must know about: features' (ids as in State.step), then anywhere
        self.all_steps = self.steps + self.anywhere_steps
        self.anywhere = {a: info for info in self.anywhere_steps for a in sorted(info.actions)}
        self.waits = {
            self.action_index[name]: float(spec.seconds or 0)
            for name, spec in model.actions.items()
            if spec.skill == "wait"
        }
        # actions that do not go through the feature pointer's table
        self.free_actions = tuple(sorted({*self.anywhere, *self.waits}))
        self.short_enters = frozenset(
            self.action_index[name]
            for name, spec in model.actions.items()
            if spec.too_short == "enters"
        )
        self.first_steps = self._first_steps()
        self.targets = self._compile_targets()
        self.guards = self._compile_guards()
        self.hold_seconds = tuple(
            model.actions[a].seconds if model.actions[a].skill == "hold" else None
            for a in self.action_names
        )
        self.digits = tuple(
            str(model.actions[a].digit) if model.actions[a].digit is not None else ""
            for a in self.action_names
        )
        self.feature_names = list(model.features)
        self.cache: dict[str, Any] = {}  # planner data derived from this model, built lazily

    # --- building ------------------------------------------------------------------------

    def _compile_variable(self, name: str) -> VarInfo:
        spec = self.model.variables[name]
        if spec.depends_on is None:
            return VarInfo(name, spec, (build_domain(spec),), -1)
        parent_index = self.var_index[spec.depends_on]
        parent = build_domain(self.model.variables[spec.depends_on])
        cases = spec.cases or {}
        domains = tuple(
            build_domain(spec, cases[value]) if value in cases else None for value in parent.values
        )
        return VarInfo(name, spec, domains, parent_index)

    def _effect(self, effect: Any, var: VarInfo | None, action: int) -> tuple[Any, ...]:
        if var is None or effect in (None, "none"):
            return (NONE,)
        if effect == "digit":
            return (DIGIT, self.model.actions[self.action_names[action]].digit)
        if effect == "clear":
            reset = tuple(None if d is None else _index_table(d, d.initial) for d in var.domains)
            return (CLEAR, reset)
        tables = tuple(None if d is None else _table_for(effect, d, var.spec) for d in var.domains)
        assigns = effect == "reset" or isinstance(effect, GoTo)  # choosing, not stepping
        return (TABLE, tables, assigns)

    def _step_parts(
        self, step: Any
    ) -> tuple[
        list[int],
        dict[int, tuple[Any, ...]],
        tuple[tuple[int, tuple[tuple[int, ...] | None, ...]], ...],
    ]:
        """A step's action ids, their compiled effects and its side effects."""
        var = self.vars[self.var_index[step.variable]] if step.variable else None
        action_ids = [self.action_index[a] for a in step.actions]
        effects = {
            a: self._effect(default_effect(step, self.action_names[a], self.model), var, a)
            for a in action_ids
        }
        side: list[tuple[int, tuple[tuple[int, ...] | None, ...]]] = []
        for target, value in step.set.items():
            info = self.vars[self.var_index[target]]
            side.append(
                (
                    self.var_index[target],
                    tuple(
                        None if d is None else _table_for(GoTo(to=value), d, info.spec)
                        for d in info.domains
                    ),
                )
            )
        for target in step.reset:
            info = self.vars[self.var_index[target]]
            side.append(
                (
                    self.var_index[target],
                    tuple(None if d is None else _index_table(d, d.initial) for d in info.domains),
                )
            )
        return action_ids, effects, tuple(side)

    def _compile_steps(self) -> tuple[StepInfo, ...]:
        steps: list[StepInfo] = []
        for feature, feature_steps in self.model.features.items():
            base = len(steps)
            for index, step in enumerate(feature_steps):
                action_ids, effects, side = self._step_parts(step)
                next_step = base + index + 1 if index + 1 < len(feature_steps) else -1
                entry = (
                    getattr(self.model.variables[step.variable], "entry", None)
                    if step.variable
                    else None
                )
                steps.append(
                    StepInfo(
                        feature,
                        index,
                        self.var_index[step.variable] if step.variable else -1,
                        frozenset(action_ids),
                        effects,
                        side,
                        next_step,
                        step.on_entry == "show",
                        optional=step.optional,
                        timeout=step.timeout,
                        blank_clears=entry is not None and entry.other_keys == "clear",
                    )
                )
        return tuple(steps)

    def _compile_anywhere(self) -> tuple[StepInfo, ...]:
        """The ``anywhere`` entries, as steps of no feature (index -1, no next step)."""
        compiled = []
        for step in self.model.anywhere:
            action_ids, effects, side = self._step_parts(step)
            compiled.append(
                StepInfo(
                    "",
                    -1,
                    self.var_index[step.variable] if step.variable else -1,
                    frozenset(action_ids),
                    effects,
                    side,
                    -1,
                    leave=step.leave,
                )
            )
        return tuple(compiled)

    def _first_steps(self) -> dict[int, int]:
        """Action -> the step id of the first feature (in order) whose first step has it."""
        first: dict[int, int] = {}
        for sid, step in enumerate(self.steps):
            if step.index == 0:
                for action in sorted(step.actions):
                    first.setdefault(action, sid)
        return first

    def _compile_targets(self) -> tuple[tuple[int, ...], ...]:
        """``targets[pointer + 1][action]``: the step an action moves the pointer to, or -1."""
        rows = []
        for pointer in range(-1, len(self.steps)):
            row = []
            for action in range(len(self.action_names)):
                target = self.first_steps.get(action, -1)
                if pointer >= 0:
                    step = self.steps[pointer]
                    if action in step.actions:
                        target = pointer
                    else:
                        later = step.next_step  # the next step, or past optional ones
                        while later >= 0:
                            if action in self.steps[later].actions:
                                target = later
                                break
                            later = (
                                self.steps[later].next_step if self.steps[later].optional else -1
                            )
                if action in self.anywhere or action in self.waits:
                    target = -1  # these never move the pointer through this table
                row.append(target)
            rows.append(tuple(row))
        return tuple(rows)

    def _compile_guards(self) -> tuple[GuardInfo, ...]:
        guards = []
        for guard in self.model.guards:
            conditions = []
            for name, wanted in guard.when.items():
                var = self.vars[self.var_index[name]]
                domain = var.domains[0]
                assert domain is not None
                options = wanted if isinstance(wanted, list) else [wanted]
                indices = frozenset(
                    i for o in options if (i := _value_index(domain, o)) is not None
                )
                conditions.append((self.var_index[name], indices))
            allowed = frozenset(self.action_index[a] for a in guard.only)
            guards.append(
                GuardInfo(tuple(conditions), allowed, guard.display, guard.name, guard.hide)
            )
        return tuple(guards)

    # --- running -----------------------------------------------------------------------------

    def initial_state(self) -> State:
        """Every variable at its initial value; no feature active; empty buffer."""
        values: list[int] = []
        for var in self.vars:
            if var.parent < 0:
                domain = var.domains[0]
                assert domain is not None
                values.append(domain.initial)
            else:
                values.append(-1)
        for i, var in enumerate(self.vars):
            if var.parent >= 0:
                domain = var.domain(values)
                values[i] = -1 if domain is None else domain.initial
        return State(tuple(values), -1, "")

    def check_state(self, state: Any, argument: str = "state") -> None:
        """Raise a clear error unless ``state`` is a state of this model.

        A state is a :class:`State` (from ``initial_state()``, ``Simulator.state`` or an
        earlier plan): one value index per variable within its domain (``-1`` for a setting
        absent in the current programme), a step id or ``-1``, and a buffer of digits.
        """
        if not isinstance(state, State):
            raise TypeError(
                f"{argument} must be a State (Simulator.state, CompiledModel.initial_state()) "
                f"or None, not {type(state).__name__}"
            )
        values, step, buffer = state
        if not isinstance(values, tuple) or len(values) != len(self.vars):
            raise ValueError(
                f"{argument}.values must hold one value index for each of the model's "
                f"{len(self.vars)} variables"
            )
        for i, var in enumerate(self.vars):
            index = values[i]
            if isinstance(index, bool) or not isinstance(index, int):
                raise ValueError(f"{argument}.values[{i}] ({var.name}) is not an index: {index!r}")
        for i, var in enumerate(self.vars):  # parents first: a case depends on its parent
            if var.parent < 0 and not 0 <= values[i] < len(var.domains[0] or ()):
                raise ValueError(
                    f"{argument}.values[{i}]: {values[i]} is not an index of {var.name}'s "
                    f"{len(var.domains[0] or ())} values"
                )
        for i, var in enumerate(self.vars):
            if var.parent >= 0:
                domain = var.domain(values)
                allowed = f"0 to {len(domain) - 1}" if domain is not None else "-1 (absent)"
                if (domain is None and values[i] != -1) or (
                    domain is not None and not 0 <= values[i] < len(domain)
                ):
                    raise ValueError(
                        f"{argument}.values[{i}]: {values[i]} is not an index of {var.name} "
                        f"in this programme ({allowed})"
                    )
        if isinstance(step, bool) or not isinstance(step, int) or not -1 <= step < len(self.steps):
            raise ValueError(
                f"{argument}.step must be -1 or a step id below {len(self.steps)}, not {step!r}"
            )
        if not isinstance(buffer, str) or not (buffer == "" or buffer.isdigit()):
            raise ValueError(f"{argument}.buffer must be a string of typed digits, not {buffer!r}")

    def hiding_guard(self, state: State) -> GuardInfo | None:
        """A guard with ``hide`` that holds now: the display shows only its text."""
        for guard in self.guards:
            if guard.hide and all(state.values[v] in ok for v, ok in guard.conditions):
                return guard
        return None

    def refusal(self, state: State, action: int) -> int | None:
        """Why ``action`` would be refused in ``state`` (guard index or negative code), or None."""
        if action in self.waits:
            return None  # nothing stops anyone from waiting
        values = state.values
        for g, guard in enumerate(self.guards):
            if action not in guard.allowed and all(values[v] in ok for v, ok in guard.conditions):
                return g
        if action not in self.anywhere and self.targets[state.step + 1][action] < 0:
            return NOT_HERE
        return None

    def apply(self, state: State, action: int, seconds: float | None = None) -> State | None:
        """The state after ``action``, or None when the appliance refuses it."""
        if action in self.waits:
            return self._wait(state, self.waits[action] if seconds is None else seconds)
        values = state.values
        for guard in self.guards:
            if action not in guard.allowed:
                for v, ok in guard.conditions:
                    if values[v] not in ok:
                        break
                else:
                    return None
        needed = self.hold_seconds[action]
        short = needed is not None and seconds is not None and seconds + 1e-9 < needed
        anywhere = self.anywhere.get(action)
        if anywhere is not None:
            if short:
                return None  # an anywhere hold has no procedure to enter when released early
            target = -1 if anywhere.leave else state.step
            return self._effects(state, anywhere, action, target, "", anywhere.effects[action][0])
        target = self.targets[state.step + 1][action]
        if target < 0:
            return None
        if short:
            if action not in self.short_enters:
                return None
            # released early: the procedure moves as usual, the change does not happen
            return state if target == state.step else State(values, target, "")
        step = self.steps[target]
        buffer = state.buffer if target == state.step else ""
        effect = step.effects[action]
        kind = NONE if step.show_on_entry and target != state.step else effect[0]
        if kind == NONE and step.blank_clears and effect[0] == NONE:
            buffer = ""  # a non-digit key ends the typing (Entry.other_keys)
        return self._effects(state, step, action, target, buffer, kind)

    def _wait(self, state: State, seconds: float) -> State:
        """``seconds`` without a key: a step's timeout returns the appliance to no feature."""
        if state.step >= 0:
            timeout = self.steps[state.step].timeout
            if timeout is not None and seconds + 1e-9 >= timeout:
                return State(state.values, -1, "")
        return state

    def _effects(
        self, state: State, step: StepInfo, action: int, target: int, buffer: str, kind: int
    ) -> State:
        """Apply a step's effect of ``action`` (of ``kind``) and its side effects."""
        values = state.values
        effect = step.effects[action]
        new = list(values)
        v = step.variable
        if kind == TABLE:
            var = self.vars[v]
            current = new[v]
            if current >= 0:
                table = effect[1][var.case(new)]
                if table is not None:
                    new[v] = table[current]
        elif kind == DIGIT:
            new[v], buffer = self._type(new, v, buffer, str(effect[1]))
        elif kind == CLEAR:
            buffer = ""
            var = self.vars[v]
            if new[v] >= 0:
                table = effect[1][var.case(new)]
                if table is not None:
                    new[v] = table[new[v]]
        if (
            v >= 0
            and v in self.dependents
            and (new[v] != values[v] or kind == CLEAR or (kind == TABLE and effect[2]))
        ):
            self._reset_dependents(new, v)
        for target_var, tables in step.side:
            before = new[target_var]
            var = self.vars[target_var]
            if before >= 0:
                table = tables[var.case(new)]
                if table is not None:
                    new[target_var] = table[before]
            if target_var in self.dependents:  # a side effect always assigns
                self._reset_dependents(new, target_var)
        return State(tuple(new), target, buffer)

    def _reset_dependents(self, values: list[int], parent: int) -> None:
        for d in self.dependents[parent]:
            domain = self.vars[d].domain(values)
            values[d] = -1 if domain is None else domain.initial

    def _type(self, values: list[int], v: int, buffer: str, digit: str) -> tuple[int, str]:
        var = self.vars[v]
        entry = var.spec.entry if not isinstance(var.spec, DiscreteVariable) else None
        domain = var.domain(values)
        if entry is None or domain is None:
            return values[v], buffer
        buffer = type_digit(buffer, digit, entry)
        magnitude = parse_entry(buffer, entry)
        index = self.magnitude_index(domain, magnitude)
        return (values[v] if index is None else index), buffer

    @staticmethod
    def magnitude_index(domain: Domain, magnitude: float | None) -> int | None:
        if magnitude is None:
            return None
        return domain.index.get(_canonical(domain, magnitude))

    # --- reading -----------------------------------------------------------------------------

    def value(self, state: State, name: str) -> Any:
        """The canonical value of a variable (None when absent in the current programme)."""
        v = self.var_index[name]
        index = state.values[v]
        domain = self.vars[v].domain(state.values)
        return None if index < 0 or domain is None else domain.values[index]

    def assignment(self, state: State) -> dict[str, Any]:
        """Every variable's canonical value."""
        return {var.name: self.value(state, var.name) for var in self.vars}

    def focus(self, state: State) -> int:
        """The variable the display is showing: the current step's, else the next step's."""
        if state.step < 0:
            return -1
        step = self.steps[state.step]
        if step.variable >= 0:
            return step.variable
        if step.next_step >= 0:
            return self.steps[step.next_step].variable
        return -1

    def render_value(self, state: State, v: int) -> str:
        """A value as the display prints it (unit, time style)."""
        return display_value(self.vars[v].spec, self.value(state, self.vars[v].name))


def _canonical(domain: Domain, magnitude: float) -> Any:
    if domain.kind == "time":
        return format_hms(int(magnitude))
    return tidy_number(magnitude)


def default_effect(step: Any, action: str, model: ApplianceModel) -> Any:
    """The effect of ``action`` in ``step``, with the defaults filled in.

    With no ``effect``: a step that adjusts a variable with keypad keys types digits; with a
    single action it steps to the next value; a step without a variable has no main effect.
    """
    if isinstance(step.effect, dict):
        return step.effect.get(action, "none")
    if step.effect is not None:
        return step.effect
    if step.variable is None:
        return "none"
    if model.actions[action].digit is not None:
        return "digit"
    return "next"


def entry_digits(magnitude: float, entry: Entry) -> str | None:
    """The shortest digit string whose entry parses to ``magnitude`` (None: not typeable).

    Digits are right-aligned and zero-padded, so leading zeros never help.

    >>> entry_digits(90, Entry(format="mm:ss")), entry_digits(5400, Entry(format="h:mm"))
    ('130', '130')
    """
    if magnitude < 0 or abs(magnitude - round(magnitude)) > 1e-9:
        return None
    total = round(magnitude)
    fmt = entry.format
    if fmt in ("number", "seconds"):
        text = str(total)
    elif fmt == "minutes":
        if total % 60:
            return None
        text = str(total // 60)
    elif fmt == "mm:ss":
        text = str((total // 60) * 100 + total % 60)
    elif fmt in ("hh:mm", "h:mm"):
        if total % 60:
            return None
        text = str((total // 3600) * 100 + (total % 3600) // 60)
    else:
        hours, rest = divmod(total, 3600)
        text = str(hours * 10000 + (rest // 60) * 100 + rest % 60)
    return text if len(text) <= entry.digits() else None


_COMPILED: dict[int, tuple[ApplianceModel, CompiledModel]] = {}


def compiled_model(model: ApplianceModel | CompiledModel) -> CompiledModel:
    """A compiled model, reusing earlier compilations of the same model object.

    Models are immutable, so a compilation (and the planner data cached on it) stays valid.
    """
    if isinstance(model, CompiledModel):
        return model
    hit = _COMPILED.get(id(model))
    if hit is not None and hit[0] is model:
        return hit[1]
    if len(_COMPILED) >= 256:
        _COMPILED.pop(next(iter(_COMPILED)))
    compiled = CompiledModel(model)
    _COMPILED[id(model)] = (model, compiled)
    return compiled
