"""The belief's display rules compiled once into patterns, for :mod:`apbot.agent.reader`.

Every screen the belief can show becomes a regular expression (its template with each value
field replaced by the value's known renderings and its notation's shapes, its label as a
panel may shorten it, the lamps that may be lit after it), and the tables the reader
consults (domains per programme, lamps per value, switch/setting pairs) are built here once
per belief. Split from the reader so that it keeps the one job of matching text against
them; :class:`CompiledDisplay` is the reader's base class, so the moved code runs as before.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property, lru_cache
from typing import Any

from apbot.agent.readings import _ABSENT, Screen
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
    all_values,
    build_domain,
    case_domains,
)
from apbot.model.schema import TEMPLATE_FIELD, ApplianceModel, DiscreteVariable, TimeVariable


@dataclass(frozen=True)
class _Pattern:
    screen: Screen
    regex: re.Pattern[str]
    fields: tuple[tuple[str, str], ...]  # (group, variable)
    search: re.Pattern[str] | None  # the main text alone, for a partial match


class CompiledDisplay:
    """The compiled screens and tables of one belief (base of the display reader)."""

    belief: ApplianceModel
    _specs: dict[str, AnyVariable]

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

    def _own_lamp_denies(self, text: str, focus: str | None, read: Mapping[str, Any]) -> bool:
        """Whether ``text`` lights the lamp of the setting being shown (``focus``) for none
        of the values the screen read for it: ``LOCK`` beside a lock whose off screen is
        blank says the lock is on, so that screen is not what the display shows."""
        if focus is None or focus not in read or focus not in self._lamp_table:
            return False
        words = _regex(rf"(?<!\w)(?:{self._lamp_words.pattern})(?!\w)", re.IGNORECASE)
        on = {_squash(t) for t in words.findall(text)}
        on = {self._lamp_shortened.get(t, t) for t in on}
        lit = [v for v, t in self._lamp_table[focus] if t and _squash(t) in on]
        return bool(lit) and read[focus] not in lit

    def _other_value_beside(self, values: dict[str, Any], before: str, after: str) -> bool:
        """Whether a choice read inside a longer text has another of its own values printed
        right beside it (``UPPER LOWER``: both plates, not the upper one): a screen that prints
        several of them, which no one value's screen explains. Lists of three or more only."""
        words = {w.casefold() for w in (before.split()[-1:] + after.split()[:1])}  # next to it
        for name, value in values.items():
            spec = self._specs.get(name)
            if not isinstance(spec, DiscreteVariable):
                continue
            choices = all_values(spec)
            if len(choices) < 3:
                continue  # a switch's "off" is a word of many lamps (AUTO OFF)
            for other in choices:
                printed = display_value(spec, other).casefold()
                if other != value and printed.isalpha() and len(printed) > 1 and printed in words:
                    return True
        return False

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
    # never shortened where it is printed whole: AUTO OFF is the label, not AUT + the value OFF
    whole = rf"(?!{_literal(label)}(?!\w)){re.escape(first[:3])}[^\W\d_]*"
    return rf"(?:{_literal(label)}|{whole}{alone})"


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


def _by_length(text: str) -> tuple[int, str]:
    """Sort key: shortest first, then alphabetical, so a set's hash order never shows."""
    return len(text), text
