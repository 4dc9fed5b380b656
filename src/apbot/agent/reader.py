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
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Any, Literal

from apbot.model.display import (
    ABSENT_TEXT,
    DEFAULT_SHOW,
    display_value,
    lamp_for,
    show_template,
)
from apbot.model.domain import (
    AnyVariable,
    Domain,
    ValueProblem,
    all_values,
    build_domain,
    case_domains,
    normalise,
    parse_value,
)
from apbot.model.schema import TEMPLATE_FIELD, ApplianceModel, DiscreteVariable, TimeVariable

ScreenKind = Literal["focus", "idle", "guard"]
_MAX_CACHE = 4096
_ABSENT = object()


@dataclass(frozen=True)
class Screen:
    """One thing the display can show: a variable being adjusted (``focus``), the idle screen,
    or a guard's text. ``fixed`` holds values the screen itself implies (the ``show`` entry of
    a value: ``RUN`` means running is on)."""

    kind: ScreenKind
    variable: str | None = None
    guard: int | None = None
    template: str = ""
    fixed: tuple[tuple[str, Any], ...] = ()

    @property
    def blank(self) -> bool:
        return not self.template.strip()

    def describe(self) -> str:
        if self.kind == "focus":
            return f"{self.variable} being adjusted"
        if self.kind == "idle":
            return "the idle screen"
        return f"guard {self.guard} ({self.template or 'dark'})"


@dataclass(frozen=True)
class Hypothesis:
    """One way the text fits the belief's display rules.

    ``values``: belief variable → canonical value in its (current) belief domain;
    ``outside``: variable → value of the right type that the belief's domain lacks;
    ``absent``: variables shown as ``--``; ``lamps``: indicator → the values its lamps allow
    (more than one when lamps cannot tell them apart); ``partial``: the screen was found inside
    a longer text.
    """

    screen: Screen
    values: dict[str, Any] = field(default_factory=dict)
    outside: dict[str, Any] = field(default_factory=dict)
    absent: frozenset[str] = frozenset()
    lamps: dict[str, frozenset[Any]] = field(default_factory=dict)
    partial: bool = False

    def shown(self) -> set[str]:
        """Every variable this reading says something about."""
        return set(self.values) | set(self.outside) | set(self.absent) | set(self.lamps)

    def value(self, name: str) -> Any:
        """The value read for ``name`` (``outside`` ones included); ``_ABSENT`` if none."""
        if name in self.values:
            return self.values[name]
        if name in self.outside:
            return self.outside[name]
        lamp = self.lamps.get(name)
        if lamp is not None and len(lamp) == 1:
            return next(iter(lamp))
        return None if name in self.absent else _ABSENT


@dataclass(frozen=True)
class Reading:
    """Everything the text could mean. No hypothesis at all: the text is unknown."""

    text: str
    hypotheses: tuple[Hypothesis, ...]

    @property
    def unknown(self) -> bool:
        return not self.hypotheses

    @property
    def blank(self) -> bool:
        return not self.text.strip()

    def candidates(self, name: str) -> set[Any]:
        """Every value some hypothesis reads for ``name`` (None for ``--``)."""
        found: set[Any] = set()
        for hypothesis in self.hypotheses:
            value = hypothesis.value(name)
            if value is not _ABSENT:
                found.add(value)
            elif name in hypothesis.lamps:
                found |= set(hypothesis.lamps[name])
        return found


def is_read(value: Any) -> bool:
    """Whether :meth:`Hypothesis.value` found a value (None included: shown as ``--``)."""
    return value is not _ABSENT


# --- compiling the belief's display rules ------------------------------------------------------


@dataclass(frozen=True)
class _Pattern:
    screen: Screen
    regex: re.Pattern[str]
    fields: tuple[tuple[str, str], ...]  # (group, variable)
    search: re.Pattern[str] | None  # the main text alone, for a partial match


class DisplayReader:
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
        if not found and text.strip():  # a word the belief does not know
            found = [h for p in self._loose if (h := self._match(p, text, parents, False))]
        return Reading(text, tuple(_unique(found)))

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
        if match is None:
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
        lamps: dict[str, frozenset[Any]] = {}
        if not partial and not self._dark(screen):
            lit = match.group("_lamps") or ""
            allowed_by_lamps = self._lamps(lit, screen.variable)
            if allowed_by_lamps is None:
                return None
            lamps = allowed_by_lamps
        elif not self._dark(screen):  # lamps among words the belief does not know
            rest = whole[: match.start()] + "  " + whole[match.end() :] if whole else ""
            beside, rest = self._beside(rest, screen.variable, parents)
            lamps = self._lamps_among(rest, screen.variable)
            for name, value in beside.items():
                lamps.setdefault(name, frozenset({value}))
        if not self._dark(screen):
            lamps.update(self._switched_by_label(screen, absent))
        for name, allowed in lamps.items():  # a value the screen printed wins over its lamp
            if name in values and values[name] not in allowed:
                return None
        return Hypothesis(screen, values, outside, frozenset(absent), lamps, partial)

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
        entry = getattr(spec, "entry", None)
        if entry is not None and entry.shows == "typed" and re.fullmatch(r"[\d:]+", text):
            return "typing", None  # digits on their way to a value: they tell nothing yet
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

    # --- compiled once ---------------------------------------------------------------------

    @cached_property
    def _parent_names(self) -> tuple[str, ...]:
        return tuple(sorted({s.depends_on for s in self._specs.values() if s.depends_on}))

    @cached_property
    def _own_domains(self) -> dict[str, Domain | None]:
        return {
            n: build_domain(s) if s.depends_on is None else None for n, s in self._specs.items()
        }

    @cached_property
    def _case_domains(self) -> dict[str, dict[str, Domain]]:
        return {n: case_domains(s) for n, s in self._specs.items() if s.depends_on}

    @cached_property
    def _union_domains(self) -> dict[str, Domain]:
        union: dict[str, Domain] = {}
        for name, cases in self._case_domains.items():
            values = tuple(dict.fromkeys(v for d in cases.values() for v in d.values))
            kind = next(iter(cases.values())).kind if cases else "discrete"
            union[name] = Domain(kind, values, 0, False)
        return union

    @cached_property
    def _lamp_table(self) -> dict[str, list[tuple[Any, str]]]:
        table: dict[str, list[tuple[Any, str]]] = {}
        for name in self.belief.display.indicators:
            spec = self._specs[name]
            values = tuple(all_values(spec))
            table[name] = [(v, lamp_for(spec, name, v, values)) for v in values]
            if spec.depends_on:  # a setting this programme lacks leaves its lamp unlit too
                table[name].append((None, lamp_for(spec, name, None, values)))
        return table

    @cached_property
    def _switches(self) -> frozenset[tuple[str, str]]:
        """(switch, setting) pairs of one feature: a step toggles the switch, a later step
        adjusts the setting (a finish-time function switched on, then its time set)."""
        pairs = set()
        for steps in self.belief.features.values():
            for index, step in enumerate(steps):
                if step.variable is None or step.effect != "toggle":
                    continue
                pairs |= {(step.variable, s.variable) for s in steps[index + 1 :] if s.variable}
        return frozenset(pairs)

    @cached_property
    def _last_words(self) -> dict[str, str]:
        """Per setting with a label of several words, its last word where it is no word of
        any other label (a panel too narrow for ``DRY TIME`` prints ``TIME``; with a ``COOK
        TIME`` beside it, ``TIME`` would say nothing)."""
        labels = {n: s.display_label(n).split() for n, s in self._specs.items() if s.visible}
        found = {}
        for name, words in labels.items():
            last = words[-1] if len(words) > 1 else ""
            if len(last) < 3 or not last.isalpha():
                continue
            others = [w.casefold() for n, ws in labels.items() if n != name for w in ws]
            if last.casefold() not in others:
                found[name] = last
        return found

    @cached_property
    def _lamp_shortened(self) -> dict[str, str]:
        """A one-word lamp as the panel may shorten it to its first letters (``ROT`` for
        ``ROTATE``; at least three, as for labels), by the lamp it can only be (case-folded).
        Never spelt out longer: ``rotisserie`` on a display is no ``ROT`` lamp."""
        full = {_squash(t) for rows in self._lamp_table.values() for _, t in rows if t}
        shortened: dict[str, set[str]] = {}
        for text in full:
            if text.isalpha():
                for end in range(3, len(text)):
                    shortened.setdefault(text[:end], set()).add(text)
        return {s: next(iter(t)) for s, t in shortened.items() if len(t) == 1 and s not in full}

    @cached_property
    def _lamp_words(self) -> re.Pattern[str]:
        texts = sorted(
            {t for rows in self._lamp_table.values() for _, t in rows if t}
            | set(self._lamp_shortened),
            key=_by_length,
        )
        if not texts:
            return _regex(r"(?!x)x")
        return _regex("|".join(_literal(t) for t in reversed(texts)), re.IGNORECASE)

    @cached_property
    def _screens(self) -> list[Screen]:
        screens: list[Screen] = []
        model = self.belief
        for name, spec in self._specs.items():
            for template, value in _focus_templates(spec):
                fixed = () if value is _ABSENT else ((name, value),)
                screens.append(
                    Screen("focus", name, template=template if spec.visible else "", fixed=fixed)
                )
        screens.append(Screen("idle", template=model.display.idle))
        for index, guard in enumerate(model.guards):
            if guard.display or guard.hide:
                screens.append(Screen("guard", guard=index, template=guard.display))
        return screens

    @cached_property
    def _patterns(self) -> list[_Pattern]:
        return [self._compile(screen, screen.variable, loose=False) for screen in self._screens]

    @cached_property
    def _loose(self) -> list[_Pattern]:
        """Patterns whose word fields take any words: for a value the belief lacks (only on
        screens with text of their own around the field)."""
        loose = []
        for screen in self._screens:
            own = screen.template.replace("{label}", "label" if screen.variable else "")
            if not TEMPLATE_FIELD.sub("", own).strip():
                continue  # a bare "{value}" would read any text at all as a word
            if self._worded(screen):
                continue  # every value has its own word: this screen only ever prints "--"
            names = [
                screen.variable if n == "value" else n
                for n in TEMPLATE_FIELD.findall(screen.template)
            ]
            if any(
                isinstance(self._specs.get(n or ""), DiscreteVariable)
                and n not in dict(screen.fixed)
                for n in names
            ):
                loose.append(self._compile(screen, screen.variable, loose=True))
        return loose

    def _worded(self, screen: Screen) -> bool:
        """The general screen of a setting printed by a word per value (a ``show`` map that
        covers every value): it exists only for ``--`` in a programme without the setting."""
        spec = self._specs.get(screen.variable or "")
        if spec is None or screen.fixed or not isinstance(spec.show, dict):
            return False
        return all(str(v) in spec.show for v in all_values(spec))

    def _compile(self, screen: Screen, focus: str | None, loose: bool) -> _Pattern:
        parts: list[str] = []
        fields: list[tuple[str, str]] = []
        position = 0
        template = screen.template.strip()
        label = self._specs[focus].display_label(focus) if focus else ""
        for match in TEMPLATE_FIELD.finditer(template):
            parts.append(_literal(template[position : match.start()]))
            position = match.end()
            name = match.group(1)
            if name == "label":
                parts.append(_label_pattern(label, self._last_words.get(focus or "")))
                continue
            if name == "value":
                if focus is None:
                    parts.append(r"\S+")
                    continue
                name = focus
            if name not in self._specs:
                parts.append(_literal(match.group(0)))
                continue
            fixed = dict(screen.fixed)
            if name in fixed:  # the screen belongs to one value: print it literally
                parts.append(_literal(display_value(self._specs[name], fixed[name])))
                continue
            group = f"f{len(fields)}"
            fields.append((group, name))
            parts.append(f"(?P<{group}>{self._value_pattern(name, loose)})")
        parts.append(_literal(template[position:]))
        main = "".join(parts)
        lamps = self._lamp_words.pattern
        if self._dark(screen):  # the panel shows the guard's text and nothing else
            regex = rf"\s*{main}(?P<_lamps>)\s*"
            search = None
        elif main:
            regex = rf"\s*{main}(?P<_lamps>(?:\s+(?:{lamps}))*)\s*"
            # found inside a longer text, not inside a word or a number (1 is no reading of
            # a 1-4 lamp, nor 12 of 12/24)
            search = _regex(rf"(?<![\w:.%\-/]){main}(?![\w:.%\-/])", re.IGNORECASE)
        else:
            regex = rf"\s*(?P<_lamps>(?:{lamps})(?:\s+(?:{lamps}))*)?\s*"
            search = None
        return _Pattern(screen, _regex(regex, re.IGNORECASE), tuple(fields), search)

    def _dark(self, screen: Screen) -> bool:
        return screen.kind == "guard" and self.belief.guards[screen.guard or 0].hide

    def _value_pattern(self, name: str, loose: bool = False) -> str:
        """What a printed value of ``name`` can look like: its known renderings, or any
        number/time of its kind (a value the belief lacks must still be readable)."""
        spec = self._specs[name]
        # a repair rebuilds the model but leaves most variables as they were
        key = (type(spec).__name__, spec.model_dump_json(), loose)
        pattern = _VALUE_PATTERNS.get(key)
        if pattern is None:
            if len(_VALUE_PATTERNS) >= 4096:
                _VALUE_PATTERNS.clear()
            pattern = _VALUE_PATTERNS[key] = self._value_alternatives(spec, loose)
        return pattern

    @staticmethod
    def _value_alternatives(spec: AnyVariable, loose: bool) -> str:
        known = sorted(
            {display_value(spec, v) for v in all_values(spec)} | {ABSENT_TEXT}, key=_by_length
        )
        alternatives = [_literal(k) for k in reversed(known)]
        if isinstance(spec, DiscreteVariable) and loose:
            alternatives.append(r"\S+(?: \S+)*?")
        elif isinstance(spec, TimeVariable):
            alternatives.append(_DASHED_TIME.pattern)
            alternatives.append(r"\d+(?::\d{1,2}){0,2}(?:\s?(?:h|hr|hrs|min|mins|s|sec))?")
        elif not isinstance(spec, DiscreteVariable):
            unit = rf"(?:\s?{re.escape(spec.unit)})?" if spec.unit else ""
            alternatives.append(rf"[-+]?\d+(?:[.,]\d+)?{unit}")
        return "|".join(alternatives)


_DASHED_TIME = re.compile(r"-{1,2}(?::-{2}){1,2}")
"""A time printed as dashes in its clock's places (``--:--``, ``-:--:--``): a time that is not
set, shown blank like ``--`` (a finish time switched off, a delay not yet entered)."""

# value patterns by variable kind, definition and looseness
_VALUE_PATTERNS: dict[tuple[str, str, bool], str] = {}


def _focus_templates(spec: AnyVariable) -> list[tuple[str, Any]]:
    """The templates a variable is shown through, each with the value it belongs to: one per
    ``show`` entry, then the general one (value ``_ABSENT``) for the values without one."""
    if not isinstance(spec.show, dict):
        return [(show_template(spec, None), _ABSENT)]
    values = list(all_values(spec))
    found: list[tuple[str, Any]] = [
        (spec.show[str(value)], value) for value in values if str(value) in spec.show
    ]
    if any(str(v) not in spec.show for v in values) or spec.depends_on is not None:
        found.append((DEFAULT_SHOW, _ABSENT))
    return found


def _label_pattern(label: str, last: str | None = None) -> str:
    """A setting's label as the display may print it: as written, or shortened or spelt out
    from its first three letters (``TEMP`` for ``TEMPERATURE``, ``WATER`` for ``WATE``) —
    displays abbreviate, and manuals copy their labels inexactly. ``last``: the label's last
    word, which the display may print alone (``TIME`` for ``DRY TIME``)."""
    first = label.split()[0] if label.split() else ""
    alone = f"|{re.escape(last)}" if last else ""
    if len(first) < 3 or not first[:3].isalpha():
        return rf"(?:{_literal(label)}{alone})" if alone else _literal(label)
    return rf"(?:{_literal(label)}|{re.escape(first[:3])}[^\W\d_]*{alone})"


def _literal(text: str) -> str:
    """A template's literal text as a pattern: any run of spaces matches any run of spaces."""
    return r"\s+".join(re.escape(part) for part in re.split(r"\s+", text)) if text else ""


@lru_cache(maxsize=8192)
def _regex(pattern: str, flags: int = 0) -> re.Pattern[str]:
    """A compiled pattern, kept across readers: every repair makes a new belief and a new
    reader whose screens are mostly the old ones, and ``re``'s own cache (512 patterns) is
    too small for a benchmark's worth of them."""
    return re.compile(pattern, flags)


def _squash(text: str) -> str:
    return re.sub(r"\s+", "", text).casefold()


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


def _by_length(text: str) -> tuple[int, str]:
    """Sort key: shortest first, then alphabetical, so a set's hash order never shows."""
    return len(text), text
