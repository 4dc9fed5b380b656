"""The display reader: display text → values in the belief's own names.

A robot in front of a panel sees only what the display shows. The belief model says how the
display prints things (``apbot.model.display``): a variable being adjusted through its ``show``
template or label, the idle screen, a guard's message, lamps for indicators, values in their
notation (``h:mm``, ``40%``, ``PL7``, ``--``). The reader inverts exactly those rules: it turns
every *screen* the belief can show into a pattern, matches the text against all of them, and
returns every reading that fits (:class:`Hypothesis`) — so an ambiguous display stays a set of
candidates for the closed loop to decide with later presses.

Three outcomes are kept apart, because they mean different things to the closed loop:

* a reading that fits (perhaps with values the belief's domain lacks: ``outside``, the
  evidence that the belief is wrong);
* a *blank* display, which fits the screens that print nothing (switched off, an unlit idle
  screen) — the reader says which;
* text that fits no screen at all: **unknown**. It is evidence to weigh (the belief's display
  rules may be wrong, or the display shows something transient such as ``00:00:80`` while
  digits are typed), never the same as a dark display.

When nothing fits exactly, the reader tries each screen inside the text (a display that shows
the neighbouring step's value too) and marks such readings ``partial``.

The screens and readings themselves live in :mod:`apbot.agent.readings` (re-exported here),
the patterns compiled from the belief in :mod:`apbot.agent.screen_patterns`.

>>> from apbot.examples import load_example
>>> reader = DisplayReader(load_example("microwave_keypad"))
>>> [(h.screen.variable, h.values) for h in reader.read("PL7").hypotheses]
[('power_level', {'power_level': 7})]
>>> reader.read("PL12").hypotheses[0].outside
{'power_level': 12}
>>> reader.read("HELLO WORLD").unknown
True
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from functools import cached_property
from typing import Any

from apbot.agent.name_spellings import ends_longer_name, known_words, spelt_otherwise
from apbot.agent.readings import Hypothesis, Reading, Screen, ScreenKind, is_read
from apbot.agent.scale_codes import off_scale
from apbot.agent.screen_patterns import (
    _DASHED_TIME,
    CompiledDisplay,
    _Pattern,
    _regex,
    _squash,
)
from apbot.agent.value_words import spells_value
from apbot.model.display import ABSENT_TEXT, display_value
from apbot.model.domain import Domain, ValueProblem, all_values, normalise, parse_value
from apbot.model.schema import TEMPLATE_FIELD, ApplianceModel, DiscreteVariable, TimeVariable

__all__ = ["DisplayReader", "Hypothesis", "Reading", "Screen", "ScreenKind", "is_read"]

_MAX_CACHE = 4096
_GAP = re.compile(r"\s{2,}")  # between the parts of a display that prints several


class DisplayReader(CompiledDisplay):
    """Reads display text against one belief model (rebuild it after a repair)."""

    def __init__(self, belief: ApplianceModel) -> None:
        self.belief = belief
        self._specs = dict(belief.variables)
        self._cache: dict[tuple[str, tuple[tuple[str, Any], ...]], Reading] = {}

    # --- public --------------------------------------------------------------------------

    def read(self, text: str, context: Mapping[str, Any] | None = None) -> Reading:
        """Every reading of ``text`` that fits the belief's display rules.

        ``context``: the believed values, so that a programme-dependent setting is read in the
        current programme's domain (a programme shown in the same text takes precedence).
        """
        parents = tuple(
            (name, context.get(name)) for name in self._parent_names if context is not None
        )
        key = (text, parents)
        cached = self._cache.get(key)
        if cached is not None:
            return cached
        reading = self._read(text, dict(parents))
        if len(self._cache) >= _MAX_CACHE:
            self._cache.clear()
        self._cache[key] = reading
        return reading

    def lamp_texts(self) -> set[str]:
        """Every text a lamp of the belief can show (case-folded)."""
        return {t.casefold() for rows in self._lamp_table.values() for _, t in rows if t}

    def screens(self) -> list[Screen]:
        """Every screen the belief can show."""
        return [p.screen for p in self._patterns]

    def render(self, screen: Screen, values: Mapping[str, Any]) -> str:
        """The main text of ``screen`` with these values (for tests and explanations)."""
        spec = self._specs.get(screen.variable or "")
        template = screen.template

        def fill(match: re.Match[str]) -> str:
            name = match.group(1)
            if name == "value":
                name = screen.variable or ""
            if name == "label" and spec is not None:
                return spec.display_label(screen.variable or "")
            return display_value(self._specs[name], values.get(name))

        return TEMPLATE_FIELD.sub(fill, template).strip()

    # --- reading -------------------------------------------------------------------------

    def _read(self, text: str, parents: dict[str, Any]) -> Reading:
        found = [h for p in self._patterns if (h := self._match(p, text, parents, False))]
        if not found and text.strip():  # more on the display than the belief prints
            main = self._without_lamps(text)
            found = [
                h
                for p in self._patterns
                if p.search is not None and (h := self._match(p, main, parents, True, text))
            ]
            if found and not self._head_read(text.strip()):
                found += [h for h in self._loose_head(text.strip(), parents) if self._shortens(h)]
        if not found and text.strip():  # a word the belief does not know
            found = [h for p in self._loose if (h := self._match(p, text, parents, False))]
        if not found and text.strip():
            found = self._loose_head(text.strip(), parents)
        return Reading(text, tuple(_unique(found)))

    def _loose_head(self, text: str, parents: dict[str, Any]) -> list[Hypothesis]:
        """A word the belief does not know in the first part of a display that prints other
        parts beside it, apart by a wide gap (``MODE continuous  TIMER 2 h``): panels print
        their main screen first and the rest after it, so the first part is read alone (a
        partial reading) as it would be with nothing beside it."""
        gap = _GAP.search(text)
        if gap is None:
            return []
        head, tail = text[: gap.start()], text[gap.end() :]
        found = [
            h
            for p in self._loose
            if p.search is not None
            and p.search.fullmatch(head)
            and (h := self._match(p, head, parents, True, text))
        ]
        # (not a status word, ``HEAT ON``, a lamp's; nor when the next part is another such
        # reading, ``HEAT boost  FAN turbo``: which one is the main screen is a guess)
        status = {"on", "off"}
        if any(
            str(v).casefold() in status or self._lamp_words.fullmatch(str(v))
            for h in found
            for v in h.outside.values()
        ):
            return []
        if found and self._loose_reading(_GAP.split(tail)[0], parents):
            return []
        return found

    def _head_read(self, text: str) -> bool:
        """Whether the first part of a display that prints several (``FAN HI  W 2d``) is a
        screen the belief prints: when it is not, a reading found only among the other parts
        (the water's ``W 2d``) leaves the main screen unread, and its word the belief does
        not know (``HI``) is evidence worth reading as well (:meth:`_loose_head`)."""
        gap = _GAP.search(text)
        if gap is None:
            return True
        head = text[: gap.start()]
        return any(p.search is not None and p.search.fullmatch(head) for p in self._patterns)

    def _shortens(self, hypothesis: Hypothesis) -> bool:
        """Whether every word the belief does not know in ``hypothesis`` spells one of its
        setting's values short (``HI`` for high): read beside another screen, only such a word
        is surely that setting's; others (``ORANGE`` for a heat level) are left unread, for
        the walk to learn as the parts they are, not as new values the goal cannot name."""
        return all(
            isinstance(spec := self._specs[name], DiscreteVariable)
            and any(spells_value(str(word), value) for value in all_values(spec))
            for name, word in hypothesis.outside.items()
        )

    def _loose_reading(self, part: str, parents: dict[str, Any]) -> bool:
        """Whether ``part`` reads as a setting's screen with a word the belief does not know."""
        return any(
            p.search is not None
            and p.search.fullmatch(part)
            and (h := self._match(p, part, parents, True, part))
            and h.outside
            for p in self._loose
        )

    def _without_lamps(self, text: str) -> str:
        """The text without the lamps the belief knows at its end (a lamp alone is no reading
        of the main display)."""
        trailing = _regex(rf"\s+(?:{self._lamp_words.pattern})\s*$", re.IGNORECASE)
        while (match := trailing.search(text)) is not None and match.start() > 0:
            text = text[: match.start()]
        return text

    def _match(
        self,
        pattern: _Pattern,
        text: str,
        parents: dict[str, Any],
        partial: bool,
        whole: str = "",
    ) -> Hypothesis | None:
        regex = pattern.search if partial else pattern.regex
        assert regex is not None
        match = regex.search(text) if partial else regex.fullmatch(text)
        if match is None or (partial and _inside_marks(text, *match.span())):
            return None
        screen = pattern.screen
        values: dict[str, Any] = dict(screen.fixed)
        outside: dict[str, Any] = {}
        absent: set[str] = set()
        # parents first: a setting is read in the domain of the programme shown with it
        fields = sorted(pattern.fields, key=lambda f: self._specs[f[1]].depends_on is not None)
        for group, name in fields:
            raw = match.group(group)
            outcome = self._interpret(name, raw, {**parents, **values})
            if outcome is None:
                return None
            kind, value = outcome
            if kind == "value":
                if name in values and values[name] != value:
                    return None  # one screen, two readings of one variable
                values[name] = value
            elif kind == "outside":
                outside[name] = value
            elif kind == "absent":
                if partial and raw.strip() != ABSENT_TEXT:
                    return None  # a time in dashes beside other text: a lamp's, not the screen
                absent.add(name)
        if partial and self._other_value_beside(values, text[: match.start()], text[match.end() :]):
            return None
        if partial and ends_longer_name(text[: match.start()], values, self._known_words):
            return None
        lamps: dict[str, frozenset[Any]] = {}
        if not partial and not self._dark(screen):
            lit = match.group("_lamps") or ""
            allowed_by_lamps = self._lamps(lit, screen.variable)
            if allowed_by_lamps is None or self._own_lamp_denies(lit, screen.variable, values):
                return None
            lamps = allowed_by_lamps
        elif not self._dark(screen):  # lamps among words the belief does not know
            rest = whole[: match.start()] + "  " + whole[match.end() :] if whole else ""
            beside, rest = self._beside(rest, screen.variable, parents)
            if self._own_lamp_denies(rest, screen.variable, values):
                return None
            lamps = self._lamps_among(rest, screen.variable)
            for name, value in beside.items():
                lamps.setdefault(name, frozenset({value}))
        if not self._dark(screen):
            lamps.update(self._switched_by_label(screen, absent))
        for name, allowed in lamps.items():  # a value the screen printed wins over its lamp
            if name in values and values[name] not in allowed:
                return None
        return Hypothesis(screen, values, outside, frozenset(absent), lamps, partial)

    @cached_property
    def _known_words(self) -> set[str]:
        return known_words(self.belief) | self.lamp_texts()

    def _interpret(self, name: str, raw: str, known: Mapping[str, Any]) -> tuple[str, Any] | None:
        """A captured field as ("value", v), ("outside", v), ("absent", None), ("typing",
        None) for digits shown as typed that are no value of the domain, or None."""
        spec = self._specs[name]
        text = raw.strip()
        if text == ABSENT_TEXT or (isinstance(spec, TimeVariable) and _DASHED_TIME.fullmatch(text)):
            return "absent", None
        domain = self._domain(name, known)
        if domain is not None:
            try:
                return "value", normalise(spec, text, domain)
            except ValueProblem:
                pass
            if isinstance(spec, DiscreteVariable):
                spelt = spelt_otherwise(text, domain.values)
                if spelt is not None:
                    return "value", spelt
        entry = getattr(spec, "entry", None)
        if entry is not None and entry.shows == "typed" and re.fullmatch(r"[\d:]+", text):
            return "typing", None  # digits on their way to a value: they tell nothing yet
        if isinstance(spec, DiscreteVariable) and off_scale(all_values(spec), text):
            return None  # words of another screen, not a value of a scale with codes
        try:
            value = parse_value(spec, text)
        except ValueProblem:
            return None
        return "outside", value

    def _domain(self, name: str, known: Mapping[str, Any]) -> Domain | None:
        spec = self._specs[name]
        if spec.depends_on is None:
            return self._own_domains[name]
        parent = known.get(spec.depends_on)
        cases = self._case_domains[name]
        if parent is None:
            return self._union_domains[name]
        return cases.get(str(parent))

    def _lamps(self, lit: str, focus: str | None) -> dict[str, frozenset[Any]] | None:
        """Indicator values allowed by the lit lamps (None: text that is no lamp)."""
        texts = self._lamp_words.findall(lit) if lit.strip() else []
        if lit.strip() and _squash("".join(texts)) != _squash(lit):
            return None
        on = {self._lamp_shortened.get(_squash(t), _squash(t)) for t in texts}
        allowed: dict[str, frozenset[Any]] = {}
        for name, by_value in self._lamp_table.items():
            if name == focus:
                continue  # the main display shows it; its lamp is not lit separately
            lit_values = [v for v, t in by_value if t and _squash(t) in on]
            unlit = [v for v, t in by_value if not t]
            chosen = lit_values or unlit
            if chosen and len(chosen) < len(by_value):
                allowed[name] = frozenset(chosen)
        return allowed

    def _beside(
        self, rest: str, focus: str | None, parents: dict[str, Any]
    ) -> tuple[dict[str, Any], str]:
        """Other settings printed by their own labelled screen (``CRUST medium``) in the text
        around a screen found inside it: a panel that shows several settings side by side
        shows each as it would alone (a value of the belief's domain, found once). Also the
        text without them: their words are no lamps (``light`` of ``CRUST light``)."""
        found: dict[str, list[Any]] = {}
        spans: list[tuple[int, int]] = []
        for pattern in self._patterns:
            other = pattern.screen
            if (
                other.kind != "focus"
                or other.variable in (None, focus)
                or other.fixed
                or pattern.search is None
                or "{label}" not in other.template
                or len(pattern.fields) != 1
            ):
                continue
            ((group, name),) = pattern.fields
            for match in pattern.search.finditer(rest):
                outcome = self._interpret(name, match.group(group), parents)
                if outcome is not None and outcome[0] == "value":
                    found.setdefault(name, []).append(outcome[1])
                    spans.append(match.span())
        for start, end in sorted(spans, reverse=True):
            rest = rest[:start] + " " * (end - start) + rest[end:]
        return {name: values[0] for name, values in found.items() if len(set(values)) == 1}, rest

    def _switched_by_label(self, screen: Screen, absent: set[str]) -> dict[str, frozenset[Any]]:
        """On/off lamps whose lit text is the label this screen printed for its setting (``READY
        AT`` is both a finish-time switch's lamp and the finish time's label): the words are
        the setting's, so they tell the lamp by the value after them: a value shown means the
        switch is on, dashes (``READY AT --:--``) that it is off."""
        name = screen.variable
        if screen.kind != "focus" or name is None or "{label}" not in screen.template:
            return {}
        label = _squash(self._specs[name].display_label(name))
        switched: dict[str, frozenset[Any]] = {}
        for other, by_value in self._lamp_table.items():
            if (other, name) not in self._switches:
                continue  # a lamp of some other part of the panel that happens to share words
            lit = [(v, t) for v, t in by_value if t]
            unlit = [v for v, t in by_value if not t]
            if len(lit) == 1 and len(unlit) == 1 and _squash(lit[0][1]) == label:
                switched[other] = frozenset(unlit if name in absent else [lit[0][0]])
        return switched

    def _lamps_among(self, rest: str, focus: str | None) -> dict[str, frozenset[Any]]:
        """Indicator values allowed by the lamp words found as whole words in ``rest`` (the
        text around a screen found inside it): a lamp whose words are nowhere on a lit
        display is unlit, whatever else the display shows that the belief cannot print."""
        blanked = _regex(
            rf"(?<!\w)(?:{self._lamp_words.pattern})\s+(?:{_DASHED_TIME.pattern}|--)(?![\w:-])",
            re.IGNORECASE,
        )
        rest = blanked.sub("  ", rest)  # a label before dashes is a setting shown blank
        whole_words = _regex(rf"(?<!\w)(?:{self._lamp_words.pattern})(?!\w)", re.IGNORECASE)
        found = " ".join(whole_words.findall(rest))
        allowed = self._lamps(found, focus)
        return allowed or {}


def _inside_marks(text: str, start: int, end: int) -> bool:
    """Whether a match found inside a longer text is only a piece of a run of marks there
    (``~`` of ``~~``, ``▮▮▮`` of ``▮▮▮▯``): a count shown in marks is read whole, the longest
    match — one wave lit is not two. A run: the same mark again, or marks outside ASCII."""
    if start >= end:
        return False
    return (start > 0 and _marks(text[start - 1], text[start])) or (
        end < len(text) and _marks(text[end - 1], text[end])
    )


def _marks(a: str, b: str) -> bool:
    """Two neighbouring characters of one run of marks (no letters, digits or spaces)."""
    if not all(c.strip() and not c.isalnum() for c in (a, b)):
        return False
    return a == b or (not a.isascii() and not b.isascii())


def _unique(found: list[Hypothesis]) -> list[Hypothesis]:
    seen: set[tuple[Any, ...]] = set()
    result = []
    for h in found:
        key = (
            h.screen,
            tuple(sorted(h.values.items(), key=str)),
            tuple(sorted(h.outside.items(), key=str)),
            h.absent,
            tuple(sorted(h.lamps.items(), key=str)),
        )
        if key not in seen:
            seen.add(key)
            result.append(h)
    return result
