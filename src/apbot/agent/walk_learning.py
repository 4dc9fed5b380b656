"""What a walk teaches: write the values a walk showed into the belief model.

The explorer (:mod:`apbot.agent.explorer`) presses a step's keys until the shown values
repeat; this module turns such walks into repairs — the order of the values or their
piecewise ranges, wrap or clamp, which way a key moves, how much an ``add`` key adds — and
the single-observation repairs of a go-to key, an ``on_entry`` and a keypad's entry format.
Split from the explorer so each keeps one job; :class:`WalkLearning` is the explorer's base
class, so the moved code runs as before.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from itertools import pairwise
from typing import Any

from apbot.agent.entry_learning import learn_entry_format
from apbot.agent.infer import (
    Dark,
    Unread,
    common_step,
    fill_dark,
    order_from_traces,
    ranges_from_values,
    splice,
    typical_change,
)
from apbot.agent.quantities import canonical, loose, magnitude, summary, tidy
from apbot.agent.repair import (
    RepairError,
    redefine_domain,
    set_effects,
    set_on_entry,
)
from apbot.agent.session import Executed, Session
from apbot.model.domain import all_values, case_domains
from apbot.model.effects import default_effect
from apbot.model.schema import (
    Add,
    ApplianceModel,
    DiscreteVariable,
    TimeVariable,
    time_step_seconds,
)
from apbot.plan.plan import PlannedAction
from apbot.sim.compiled import CompiledModel


class WalkLearning:
    """Repairs of the belief from what walks and single presses showed (base of the explorer)."""

    session: Session

    def learn(
        self,
        name: str,
        pointer: tuple[str, int],
        action: str,
        opposite: PlannedAction | None,
        forward: list[Any],
        backward: list[Any] | None,
        current: Any,
    ) -> bool:
        """Write what the walks show into the belief model; False when nothing could be."""
        model = self.session.belief.model
        spec = model.variables[name]
        effect = self.session.effect(pointer, action)
        order = order_from_traces(forward, backward)
        if not [v for v in order.values if not isinstance(v, Dark)]:
            return False
        new: ApplianceModel | None
        try:
            if isinstance(spec, DiscreteVariable):
                new, note = self._learn_values(name, effect, order, current)
            else:
                new, note = self._learn_numbers(
                    name, pointer, action, opposite, forward, backward, order, current
                )
        except RepairError as exc:
            self.session.episode.log("repair", f"could not repair {name}: {exc}")
            return False
        if new is None:
            return False
        self.session.adopt(new, note, pointer)
        return True

    def _learn_values(
        self, name: str, effect: Any, order: Any, current: Any
    ) -> tuple[ApplianceModel, str]:
        values = [v if isinstance(v, Dark) else str(v) for v in order.values]
        if effect == "prev":
            values.reverse()
        known = self.session.domain_values(name)
        values = fill_dark(values, known, order.wrap)
        if not order.complete:
            values = splice(known, values)
        renamed = _spelt_out([str(v) for v in known], [str(v) for v in values])
        if renamed:
            self.session.renamed.setdefault(name, {}).update(renamed)
        new = redefine_domain(
            self.session.belief.model,
            name,
            self.session.case(name),
            values=values,
            wrap=order.wrap,
            current=current,
            initial=self._first_of_programme(name, order.values),
        )
        return new, f"{name}: values {summary(values)}{_ends(order.wrap)}"

    def _learn_numbers(
        self,
        name: str,
        pointer: tuple[str, int],
        action: str,
        opposite: PlannedAction | None,
        forward: list[Any],
        backward: list[Any] | None,
        order: Any,
        current: Any,
    ) -> tuple[ApplianceModel | None, str]:
        spec = self.session.belief.model.variables[name]
        effect = self.session.effect(pointer, action)
        # a dark slot (an OFF position, a setting shown as a dark panel) is the believed value
        # between its neighbours
        filled = fill_dark(list(order.values), self.session.domain_values(name), order.wrap)
        numbers = [m for m in (magnitude(spec, v) for v in filled) if m is not None]
        if not numbers:
            return None, ""
        change = _direction(spec, forward, backward)
        new = self.session.belief.model
        notes: list[str] = []
        walked = sorted(set(numbers))  # what the walk showed, never dropped
        if isinstance(effect, Add):
            new, numbers = self._learn_add(new, pointer, action, spec, change, numbers, notes)
        elif effect in ("next", "prev") and change is not None:
            rising = change > 0
            if rising != (effect == "next"):
                flipped = {action: "prev" if effect == "next" else "next"}
                if opposite is not None:
                    flipped[opposite.name] = effect
                new = set_effects(new, pointer[0], pointer[1], flipped)
                notes.append(f"{action} moves {name} the other way")
            if not order.complete:
                numbers = _keep_unseen(
                    self.session.magnitudes(name),
                    numbers,
                    clamped_high=rising if order.wrap is False else None,
                )
        ranges = ranges_from_values(numbers)
        initial = self._first_of_programme(name, forward)

        def redefined(ranges: list[tuple[float, float, float]]) -> ApplianceModel:
            return redefine_domain(
                new,
                name,
                self.session.case(name),
                ranges=ranges,
                wrap=order.wrap if effect != "toggle" else None,
                current=canonical(spec, magnitude(spec, current)),
                initial=initial,
            )

        try:
            new = redefined(ranges)
        except RepairError:
            # a key that adds more than believed leaves the believed values between its
            # strides unreached: what the step's keys reach from a value seen is the domain
            # (only when this walk changed the amount and stepped evenly, by that grid, so
            # every value it showed stays)
            if not (isinstance(effect, Add) and new is not self.session.belief.model):
                raise
            grid = _grid(new, pointer)
            shown = magnitude(spec, current)  # the grid runs through what the panel showed
            anchor = shown if shown is not None else (numbers[0] if numbers else 0.0)
            strides = _on_grid(numbers, grid, anchor)
            if grid is None or strides is None or not _even(walked, grid, strides):
                raise
            new = self._snap_other_cases(new, name, grid, anchor)
            ranges = ranges_from_values(strides)
            new = redefined(ranges)
        notes.append(f"{name}: ranges {ranges}{_ends(order.wrap)}")
        return new, "; ".join(notes)

    def _snap_other_cases(
        self, model: ApplianceModel, name: str, grid: float, anchor: float
    ) -> ApplianceModel:
        """The other programmes' domains of ``name`` on the same grid (the same keys set it
        there); left unchecked until the current case is written."""
        spec = model.variables[name]
        here = self.session.case(name)
        for case, domain in case_domains(spec).items():
            numbers = list(domain.magnitudes or ())
            kept = _on_grid(numbers, grid, anchor)
            if case == here or kept is None:
                continue
            model = redefine_domain(
                model, name, case, ranges=ranges_from_values(kept), checked=False
            )
        return model

    def _first_of_programme(self, name: str, trace: list[Any]) -> Any:
        """A programme's starting value of a setting the belief only guessed (one it found on
        its own): the first value this walk showed."""
        if name not in self.session.guessed_initial:
            return None
        self.session.guessed_initial.discard(name)
        return next((v for v in trace if not isinstance(v, Dark | Unread)), None)

    def _learn_add(
        self,
        model: ApplianceModel,
        pointer: tuple[str, int],
        action: str,
        spec: Any,
        change: float | None,
        numbers: list[float],
        notes: list[str],
    ) -> tuple[ApplianceModel, list[float]]:
        """An ``add`` key: learn its amount and sign; widen (never shrink) the domain, since
        the key may skip values other keys reach."""
        effect = self.session.effect(pointer, action)
        believed = float(
            time_step_seconds(effect.add) if isinstance(effect.add, str) else effect.add
        )
        if change is not None and change != believed:
            amount: Any = int(change) if isinstance(spec, TimeVariable) else tidy(change)
            try:
                model = set_effects(model, pointer[0], pointer[1], {action: {"add": amount}})
            except RepairError:  # values between the strides: the domain repair drops them
                change_only = {action: {"add": amount}}
                model = set_effects(model, pointer[0], pointer[1], change_only, checked=False)
            notes.append(f"{action} adds {amount}")
        known = self.session.magnitudes(self.session.step_variable(pointer) or "")
        return model, sorted(set(known) | set(numbers))

    def learn_goto(self, name: str, last: Executed, observed: Any) -> None:
        """A go-to key set another value than believed: it sets that one."""
        assert last.pointer is not None
        try:
            new = set_effects(
                self.session.belief.model,
                last.pointer[0],
                last.pointer[1],
                {last.action.name: {"to": observed}},
            )
        except RepairError as exc:
            self.session.episode.log("repair", f"could not repair {last.action.name}: {exc}")
            return
        self.session.adopt(new, f"{last.action.name} sets {name} to {observed}", last.pointer)

    def learn_on_entry(self, name: str, entering: Executed) -> bool:
        """The press that entered a step showed what the other ``on_entry`` would have given
        (the first press of TEMP already changed it, or only showed it): the step says so."""
        session = self.session
        if entering.pointer is None or entering.before == entering.pointer:
            return False
        if entering.state_before is None or not session.stepping(
            entering.pointer, entering.action.name
        ):
            return False
        feature, index = entering.pointer
        step = session.belief.model.features[feature][index]
        other = "apply" if step.on_entry == "show" else "show"
        try:
            flipped = set_on_entry(session.belief.model, feature, index, other)
        except RepairError:
            return False
        compiled = CompiledModel(flipped)
        after = compiled.apply(
            entering.state_before,
            compiled.action_index[entering.action.name],
            entering.action.seconds,
        )
        shown = entering.observed(name)
        if after is None or compiled.value(after, name) != shown or shown == entering.predicted:
            return False
        if not session.budget.once("entry", f"{feature}:{index}"):
            return False
        # a key that moves the other way, stuck at an end, also leaves the value as it was:
        # one more press must go as the other on_entry predicts
        action = compiled.action_index[entering.action.name]
        then = compiled.apply(after, action, entering.action.seconds)
        again = session.press(entering.action, exploring=True)
        if then is None or again.observed(name) != compiled.value(then, name):
            return False
        session.adopt(
            flipped,
            f"{feature}: the press that enters {name}'s step "
            + ("changes it at once" if other == "apply" else "only shows it"),
            entering.pointer,
        )
        session.belief.set_value(name, again.observed(name))  # where the confirming press left it
        return True

    def learn_entry_format(
        self,
        name: str,
        last: Executed,
        observed: Any,
        unchanged: bool,
        typed: Sequence[Executed] = (),
    ) -> bool:
        """:func:`apbot.agent.entry_learning.learn_entry_format` on this session."""
        return learn_entry_format(self.session, name, last, observed, unchanged, typed)

    def widen(self, name: str, observed: list[Any]) -> None:
        """Let a keypad setting take values the belief's ranges missed."""
        spec = self.session.belief.model.variables[name]
        if isinstance(spec, DiscreteVariable):
            return
        known = self.session.magnitudes(name)
        if not known and spec.depends_on is not None:  # no case for this programme: what the
            # other programmes take is the best guess of its range
            known = [m for m in (magnitude(spec, v) for v in all_values(spec)) if m is not None]
        extra = [m for m in (magnitude(spec, loose(spec, v)) for v in observed) if m is not None]
        if not known or not extra or set(extra) <= set(self.session.magnitudes(name)):
            return
        points = sorted(set(known) | set(extra))
        step = common_step(points)
        low, high = points[0], points[-1]
        try:
            new = redefine_domain(
                self.session.belief.model, name, self.session.case(name), ranges=[(low, high, step)]
            )
        except RepairError as exc:
            self.session.episode.log("repair", f"could not widen {name}: {exc}")
            return
        self.session.adopt(
            new,
            f"{name}: allow {low:g}..{high:g} in steps of {step:g}",
            self.session.belief.pointer(),
        )


def _ends(wrap: bool | None) -> str:
    return {True: ", wraps", False: ", stops at the ends", None: ""}[wrap]


def _keep_unseen(known: list[float], seen: list[float], clamped_high: bool | None) -> list[float]:
    """Numbers after a partial walk: what was seen replaces the belief between the lowest and
    highest value seen; beyond them the belief stands, except past an end the walk hit."""
    low, high = min(seen), max(seen)
    kept = [
        m
        for m in known
        if (m < low and clamped_high is not False) or (m > high and clamped_high is not True)
    ]
    return sorted(set(seen) | set(kept))


def _grid(model: ApplianceModel, pointer: tuple[str, int]) -> float | None:
    """The greatest common divisor of what a step's ``add`` keys add (None: no such key).

    A walk just showed a key's real stride; the belief's finer values between strides came
    from a manual that gave none (or a guess), and no key of the step reaches them.
    """
    feature, index = pointer
    step = model.features[feature][index]
    amounts: list[float] = []
    for action in step.actions:
        effect = default_effect(step, action, model)
        if isinstance(effect, Add):
            add = time_step_seconds(effect.add) if isinstance(effect.add, str) else effect.add
            amounts.append(abs(float(add)))
    grid = common_step([0.0, *amounts]) if amounts else 0
    return float(grid) if grid else None


def _on_grid(numbers: list[float], grid: float | None, anchor: float) -> list[float] | None:
    """The numbers a whole number of ``grid`` strides from ``anchor`` (None: all or fewer
    than two are).

    >>> _on_grid([0, 60, 600, 660, 1200], 600, 0)
    [0, 600, 1200]
    """
    if not grid:
        return None
    kept = [n for n in numbers if abs((n - anchor) / grid - round((n - anchor) / grid)) < 1e-9]
    return kept if 1 < len(kept) < len(numbers) else None


def _even(walked: list[float], grid: float, kept: list[float]) -> bool:
    """Whether a walk's values (sorted) step evenly by ``grid`` and all stay in ``kept``: a
    walk whose stride changes (1 min, then 5) is no grid to snap the domain to.

    >>> _even([300, 600, 900], 300, [300, 600, 900, 1200])
    True
    >>> _even([60, 120, 180, 2100, 2400], 300, [2100, 2400])
    False
    """
    steps = {round(b - a, 9) for a, b in pairwise(walked)}
    return steps <= {round(grid, 9)} and set(walked) <= set(kept)


def _direction(spec: Any, forward: list[Any], backward: list[Any] | None) -> float | None:
    """The usual change one press of the explored key makes (from the opposite key's walk,
    reversed, when the first walk showed no change)."""

    def numbers(trace: list[Any]) -> list[float]:
        return [m for m in (magnitude(spec, v) for v in trace) if m is not None]

    change = typical_change(numbers(forward))
    if change is None and backward:
        opposite = typical_change(numbers(backward))
        change = None if opposite is None else -opposite
    return change


def _spelt_out(old: list[str], new: list[str]) -> dict[str, str]:
    """Each old value the walk showed only spelt out (``lo`` → ``low``), when the walk shows
    as many values as the belief had and each old one begins exactly one new one: the same
    values, printed in full. Empty otherwise.

    >>> _spelt_out(["lo", "hi"], ["low", "high"])
    {'lo': 'low', 'hi': 'high'}
    >>> _spelt_out(["lo", "hi"], ["low", "medium", "high"])
    {}
    >>> _spelt_out(["1", "2", "3"], ["10", "20", "30"])  # other numbers, not the same ones
    {}
    """
    if len(old) != len(new) or set(old) == set(new):
        return {}
    if not all(re.fullmatch(r"[^\W\d_]+(?:[ -][^\W\d_]+)*", v) for v in old):
        return {}  # only words are shortened on a display; "1" is no short "10"
    found: dict[str, str] = {}
    for value in old:
        fits = [n for n in new if n.casefold().startswith(value.casefold())]
        if len(fits) != 1 or fits[0] in found.values():
            return {}
        found[value] = fits[0]
    return {o: n for o, n in found.items() if o != n}
