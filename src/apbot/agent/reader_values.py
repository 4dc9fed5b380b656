"""A display field read as a value of the belief's domain (base of the display reader).

A captured field is a value, a value outside the believed domain (evidence the belief is wrong),
dashes for a setting shown blank, or digits being typed. Kept apart from the screen matching so
that one module says how a single field is understood, whatever screen printed it.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

from apbot.agent.name_spellings import spelt_otherwise
from apbot.agent.scale_codes import off_scale
from apbot.agent.screen_patterns import _DASHED_TIME, CompiledDisplay
from apbot.model.display import ABSENT_TEXT
from apbot.model.domain import Domain, ValueProblem, all_values, normalise, parse_value
from apbot.model.schema import DiscreteVariable, TimeVariable


class ValueReading(CompiledDisplay):
    """Reads one captured field in the domain the belief gives it."""

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
