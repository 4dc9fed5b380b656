"""One compiled screen matched against display text (base of the display reader).

A match turns the captured fields into values (:mod:`apbot.agent.reader_values`), checks the
lamps (:mod:`apbot.agent.reader_lamps`) and yields one :class:`Hypothesis`, whole or partial
(a screen found inside a longer text).
"""

from __future__ import annotations

from functools import cached_property
from typing import Any

from apbot.agent.name_spellings import ends_longer_name, known_words
from apbot.agent.reader_lamps import LampReading
from apbot.agent.readings import Hypothesis
from apbot.agent.screen_patterns import _Pattern
from apbot.model.display import ABSENT_TEXT


class ScreenMatching(LampReading):
    """Matches one screen's pattern against a display text."""

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
