"""Lamps and side screens around a display's main screen (base of the display reader).

A panel lights indicator lamps beside its main text and may print other settings' own labelled
screens next to it. These methods tell which indicator values the lit (and unlit) lamps allow,
so that the screen matching only has to ask them.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.agent.reader_values import ValueReading
from apbot.agent.readings import Screen
from apbot.agent.screen_patterns import _DASHED_TIME, _regex, _squash


class LampReading(ValueReading):
    """Indicator values allowed by the lamps a display shows."""

    def lamp_texts(self) -> set[str]:
        """Every text a lamp of the belief can show (case-folded)."""
        return {t.casefold() for rows in self._lamp_table.values() for _, t in rows if t}

    def _without_lamps(self, text: str) -> str:
        """The text without the lamps the belief knows at its end (a lamp alone is no reading
        of the main display)."""
        trailing = _regex(rf"\s+(?:{self._lamp_words.pattern})\s*$", re.IGNORECASE)
        while (match := trailing.search(text)) is not None and match.start() > 0:
            text = text[: match.start()]
        return text

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
