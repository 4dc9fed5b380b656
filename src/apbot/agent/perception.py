"""Perception: one piece of feedback, read in the belief's terms, in the light of a prediction.

Feedback comes as display text (what a robot sees), and from some environments also as values
under the environment's own names (the paper's simulator). Values, when given, are mapped by
name (:mod:`apbot.agent.estimate`); otherwise the display text is read by inverting the
belief's own display rules (:mod:`apbot.agent.reader`). Either way the result is a
:class:`Seen`.

The display reader returns every reading that fits; the one that counts is the one closest to
what the belief predicted (the predicted screen first, then the fewest values the belief
cannot hold, then the most values as predicted). Readings that remain tied and disagree about
a variable leave it as a set of candidates — later presses decide it.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from apbot.agent.environment import Feedback
from apbot.agent.estimate import StateEstimator
from apbot.agent.reader import DisplayReader, Hypothesis, Reading, is_read
from apbot.model.domain import ValueProblem, normalise, parse_value
from apbot.model.schema import ApplianceModel, NumericVariable, TimeVariable

LOOK_ALIKE_COST = 1.0
"""How much more a photo's reading may cost (in the decoder's units, where a cell's look-alikes
lie within 1.5 of its best glyph) and still win by being one the display rules explain whole."""

MISSING: Any = type("Missing", (), {"__repr__": lambda self: "MISSING"})()
"""Not shown on the display at all (a ``None`` value means shown as ``--``)."""
UNREADABLE: Any = type("Unreadable", (), {"__repr__": lambda self: "UNREADABLE"})()
"""The display showed something, but nothing the belief's display rules can print."""


@dataclass
class Seen:
    """What one feedback says about the belief's variables.

    ``values``: variable → value in its belief domain; ``outside``: variable → a value of the
    right type the belief's domain lacks (evidence the belief is wrong); ``candidates``:
    variables the display leaves ambiguous, with the values it allows; ``absent``: shown as
    ``--``. ``screen``: the variable the main display is adjusting, and ``screen_kind`` what the
    main display shows (``focus``, ``idle``, ``guard``; None when the readings disagree or in
    values mode, where there is no screen to read); ``screens`` every (kind, variable) the
    best readings allow. ``unknown``: the text fits none of the belief's
    screens; ``blank``: the display shows nothing. ``doubted``: ambiguous settings of a display
    every reading of which contradicts the belief on one of them (``TIME 00:02``, the cook time
    or the timer, where the belief holds neither): which one is wrong is not known, but one is.
    """

    text: str = ""
    values: dict[str, Any] = field(default_factory=dict)
    outside: dict[str, Any] = field(default_factory=dict)
    candidates: dict[str, frozenset[Any]] = field(default_factory=dict)
    absent: set[str] = field(default_factory=set)
    screen: str | None = None
    screen_kind: str | None = None
    screens: frozenset[tuple[str, str | None]] = frozenset()
    unknown: bool = False
    blank: bool = False
    partial: bool = False
    doubted: frozenset[str] = frozenset()

    def observed(self, name: str) -> Any:
        """The value shown for ``name``: MISSING if not shown, None if shown as ``--``."""
        if name in self.values:
            return self.values[name]
        if name in self.outside:
            return self.outside[name]
        if name in self.absent:
            return None
        return MISSING

    def showing(self, name: str) -> bool:
        """Whether the main display may be adjusting ``name`` (True when it cannot tell)."""
        return not self.screens or ("focus", name) in self.screens

    def shown(self) -> set[str]:
        """The variables this feedback says something about."""
        return set(self.values) | set(self.outside) | set(self.candidates) | self.absent


class Perceiver:
    """Reads feedback against one belief model; rebind it after a repair."""

    def __init__(self, belief: ApplianceModel) -> None:
        self.estimator = StateEstimator(belief)
        self.reader = DisplayReader(belief)
        self.model = belief

    def rebind(self, belief: ApplianceModel) -> None:
        """Use a repaired belief (name matches learnt by the estimator are kept)."""
        self.estimator.rebind(belief)
        self.reader = DisplayReader(belief)
        self.model = belief

    def perceive(
        self,
        feedback: Feedback,
        context: Mapping[str, Any],
        expected_screen: tuple[str, str | None] | None = None,
    ) -> Seen:
        """Read ``feedback``; ``context`` holds the predicted values, ``expected_screen`` the
        predicted screen as (kind, variable), e.g. ``("focus", "timer")`` or ``("idle", None)``.
        """
        alternatives = getattr(feedback.image, "alternatives", None)
        if alternatives and not feedback.values:
            return self._best_alternative(alternatives, context, expected_screen)
        seen = choose(self.reader.read(feedback.text, context), context, expected_screen)
        if not feedback.values:
            if expected_screen is not None and expected_screen[0] == "focus":
                return by_unit(self.model, seen, expected_screen[1]) or seen
            return seen
        # values by name are exact; the text adds what they leave out (and the screen), when
        # the belief can read it at all (a third-party display may look nothing like it)
        estimate = self.estimator.estimate(feedback, context=context)
        named = set(estimate.values) | set(estimate.outside)
        if seen.unknown:  # still unknown if a value shown by name fits none of the belief's
            seen = Seen(feedback.text, unknown=bool(estimate.unmatched))
        for name in named:
            seen.values.pop(name, None)
            seen.outside.pop(name, None)
            seen.candidates.pop(name, None)
            seen.absent.discard(name)
        seen.values.update(estimate.values)
        seen.outside.update(estimate.outside)
        return seen

    def _best_alternative(
        self,
        alternatives: list[tuple[str, float]],
        context: Mapping[str, Any],
        expected: tuple[str, str | None] | None,
    ) -> Seen:
        """Image mode: of the texts a photo's display may show (with their visual cost), the
        cheapest one the belief can read; among equally cheap ones (look-alikes such as
        ``5``/``S``), the one closest to the prediction. A look-alike the display rules explain
        whole beats a cheaper one they read only in part, within :data:`LOOK_ALIKE_COST`
        (``▶`` drawn small reads best as ``▸``, which no screen of the belief prints: the part
        read would say the run lamp is off). Unreadable if none can be read."""
        readable = []
        for text, cost in _with_symbol_sizes(alternatives):
            reading = self.reader.read(text, context)
            if not reading.unknown:
                readable.append((float(cost), choose(reading, context, expected)))
        if not readable:
            text = alternatives[0][0]
            return choose(self.reader.read(text, context), context, expected)
        cheapest = min(cost for cost, _ in readable)
        whole = [
            (cost, seen)
            for cost, seen in readable
            if not seen.partial and cost <= cheapest + LOOK_ALIKE_COST
        ]
        if whole:
            readable = whole
            cheapest = min(cost for cost, _ in readable)

        def closeness(seen: Seen) -> tuple[int, int]:
            kind, variable = expected or (None, None)
            on_screen = seen.screen_kind == kind and (kind != "focus" or seen.screen == variable)
            differing = sum(1 for name, value in seen.values.items() if context.get(name) != value)
            return (0 if on_screen else 1, differing + len(seen.outside))

        tied = [seen for cost, seen in readable if cost <= cheapest + 0.05]
        return min(tied, key=closeness)


SYMBOL_SIZES = str.maketrans({"▸": "▶", "►": "▶", "◂": "◀", "◄": "◀", "▴": "▲", "▾": "▼"})
"""One symbol drawn at two sizes (a status row's small ▸ is the run lamp's ▶): a photo cannot
tell which of the two a manual's or model's text uses."""


def _with_symbol_sizes(alternatives: list[tuple[str, float]]) -> list[tuple[str, float]]:
    """The photo's readings, each followed by itself with its arrows at the other size (a
    little dearer, so a display rule that prints the small one still wins)."""
    grown = []
    for text, cost in alternatives:
        grown.append((text, cost))
        other = text.translate(SYMBOL_SIZES)
        if other != text:
            grown.append((other, cost + 0.5))
    return grown


def choose(
    reading: Reading, context: Mapping[str, Any], expected: tuple[str, str | None] | None
) -> Seen:
    """The reading closest to the prediction, ties merged into candidates."""
    if reading.unknown:
        return Seen(reading.text, unknown=True, blank=reading.blank)

    def score(h: Hypothesis) -> tuple[int, int, int, int]:
        kind, variable = expected or (None, None)
        same_screen = h.screen.kind == kind and (kind != "focus" or h.screen.variable == variable)
        differing = sum(
            1
            for name in h.shown()
            if is_read(value := h.value(name)) and context.get(name) != value
        )
        return (0 if same_screen else 1, int(h.partial), len(h.outside), differing)

    ranked = sorted(reading.hypotheses, key=score)
    best = [h for h in ranked if score(h) == score(ranked[0])]
    seen = Seen(reading.text, blank=reading.blank, partial=best[0].partial)
    screens = {(h.screen.kind, h.screen.variable) for h in best}
    seen.screens = frozenset(screens)
    if len(screens) == 1:
        seen.screen_kind, seen.screen = screens.pop()
    names = sorted(set().union(*(h.shown() for h in best)))  # in an order no hash seed moves
    for name in names:
        options = {h.value(name) for h in best}
        lamp_sets = [h.lamps[name] for h in best if name in h.lamps]
        if len(options) == 1 and is_read(value := next(iter(options))):
            if value is None:
                seen.absent.add(name)
            elif any(name in h.outside for h in best):
                seen.outside[name] = value
            else:
                seen.values[name] = value
            continue
        allowed = {v for v in options if is_read(v)} | {v for s in lamp_sets for v in s}
        if name in context and context[name] in allowed:
            seen.values[name] = context[name]  # the belief's value is one of them: keep it
        elif allowed:
            seen.candidates[name] = frozenset(allowed)
    if seen.candidates and all(any(is_read(h.value(n)) for n in seen.candidates) for h in best):
        # every reading shows one of them at a value the belief does not hold
        seen.doubted = frozenset(seen.candidates)
    return seen


HOUR_UNITS = frozenset({"h", "hr", "hrs", "hour", "hours"})


def by_unit(model: ApplianceModel, seen: Seen, name: str | None) -> Seen | None:
    """The setting the press was to bring up, read by its unit where its screen was not found:
    the display prints one number in that setting's unit (``55°C  LOCK RED`` for a
    temperature whose screen the belief prints as ``TEMPERATURE 55°C``) and no other visible
    setting of the belief has that unit; a setting counted in hours also by one clock time
    (``0:30`` is 0.5 h) when the belief shows no time of its own. None when the reading stands
    as it is (the setting read, no unit, no such number, or more than one)."""
    spec = model.variables.get(name or "")
    if name is None or not isinstance(spec, NumericVariable) or not spec.unit:
        return None
    if seen.observed(name) not in (MISSING, None) or name in seen.candidates or seen.blank:
        return None
    unit = spec.unit.strip()
    if not unit or any(
        other != name
        and isinstance(o, NumericVariable)
        and o.visible
        and (o.unit or "").strip().casefold() == unit.casefold()
        for other, o in model.variables.items()
    ):
        return None
    found = re.findall(
        rf"(?<![\d.:])(-?\d+(?:\.\d+)?)\s?{re.escape(unit)}(?!\w)", seen.text, re.IGNORECASE
    )
    if (
        not found
        and unit.casefold() in HOUR_UNITS
        and not any(isinstance(o, TimeVariable) and o.visible for o in model.variables.values())
    ):
        # a setting counted in hours, shown as a clock (``DELAY 0:30``): the hours it shows —
        # unless the belief has a time of its own the same clock could be (``12:45`` on a
        # panel with a clock is the time of day, not a delay of 12.75 h)
        clocks = re.findall(r"(?<![\d.:])(\d{1,2}):([0-5]\d)(?![\d:])", seen.text)
        found = [f"{int(h) + int(m) / 60:g}" for h, m in clocks]
    if len(found) != 1:
        return None
    read = Seen(seen.text, screen=name, screen_kind="focus", partial=True)
    read.screens = frozenset({("focus", name)})
    try:
        read.values[name] = normalise(spec, found[0])
    except ValueProblem:
        try:
            read.outside[name] = parse_value(spec, found[0])
        except ValueProblem:
            return None
    return read
