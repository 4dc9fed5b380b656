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
the patterns compiled from the belief in :mod:`apbot.agent.screen_patterns`; one screen matched
against the text in :mod:`apbot.agent.reader_match`, its lamps in :mod:`apbot.agent.reader_lamps`
and its fields' values in :mod:`apbot.agent.reader_values`.

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
from typing import Any

from apbot.agent.reader_match import ScreenMatching
from apbot.agent.readings import Hypothesis, Reading, Screen, ScreenKind, is_read
from apbot.agent.value_words import spells_value
from apbot.model.display import display_value
from apbot.model.domain import all_values
from apbot.model.schema import TEMPLATE_FIELD, ApplianceModel, DiscreteVariable

__all__ = ["DisplayReader", "Hypothesis", "Reading", "Screen", "ScreenKind", "is_read"]

_MAX_CACHE = 4096
_GAP = re.compile(r"\s{2,}")  # between the parts of a display that prints several


class DisplayReader(ScreenMatching):
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
