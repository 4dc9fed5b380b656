"""A setting's range read past the single sentence: steps told over a few sentences ("up to 1 h by
10 min; after that by 30 min"), a chart of clicks and what each shows, a guide column of amounts,
and the bounds the sentences after the control's own say. Apart from evidence.py (the control's
sentences, one at a time) because each of these reads several units together, after that pass.
"""

from __future__ import annotations

from apbot.read.count_tables import chart_for, count_charts, sideways_charts
from apbot.read.evidence_checks import (
    _amount_column,
    about_another,
)
from apbot.read.evidence_elsewhere import ElsewhereReader
from apbot.read.shapes import (
    Evidence,
    _aside,
    _fits,
)
from apbot.read.values import (
    find_bounds,
)
from apbot.read.values_pieces import find_amount_pieces, find_two_steps


class RangeReader(ElsewhereReader):
    """Ranges of a control read across sentences, charts and guide columns near it."""

    def _ranges_across(
        self,
        tokens: list[str],
        ev: Evidence,
        context: list[int],
        mentions: set[int],
        others: set[str],
        own: set[str],
    ) -> None:
        """The ranges told across the control's sentences, a count chart or a guide column,
        read once its sentences one by one are read (into ``ev``)."""
        units = self.manual.units
        for i in sorted(self.context(tokens)):  # "up to 1 h by 10 min; after that by 30 min"
            window = []
            for k in range(i, min(i + 4, len(units))):
                if k not in mentions and about_another(units[k].text, others):
                    break  # "The cook time changes by 1 minute …" after the delay's range
                if not units[k].cells:
                    window.append(k)
            names = tuple(self.labels[t].text.lower() for t in tokens if t in self.labels)
            texts = [units[k].text for k in window]
            two = find_two_steps(texts, names) or find_amount_pieces(texts)
            if two and _fits(two[0][0].unit, tokens):
                ev.ranges, ev.range_at = two[0], window[two[1]]
                break
        charts = count_charts(units) + sideways_charts(units, self.manual.lines)
        chart = chart_for(
            charts, own, self._turns(tokens), self._turned(tokens), context
        )  # "| Clicks clockwise | Display |" "| 1 | 300 ml |": every setting, by example
        if chart and _fits(chart.pieces[0].unit, tokens):
            ev.ranges, ev.range_at = chart.pieces, chart.at
        if not ev.ranges:  # "Rough guide to power:" and a column of 100 % … 10 %
            for i in sorted(self.context(tokens)):
                guide = None if _aside(units, i) else _amount_column(units, i)
                if guide is not None and _fits(guide.unit, tokens):
                    ev.ranges, ev.range_at = [guide], i
                    break
        if not ev.ranges:
            for i in sorted(self.context(tokens)):  # the sentences that follow say the rest
                bounds = find_bounds([u.text for u in units[i : i + 4]])
                if bounds and _fits(bounds.unit, tokens):
                    if not bounds.step:  # the longest setting alone: if nothing better is read
                        ev.longest = ev.longest or (bounds, i)
                        continue
                    ev.ranges, ev.range_at = [bounds], i
                    ev.step = ev.step or (bounds.step, bounds.unit)
                    break

    def _turns(self, tokens: list[str]) -> bool:
        """One of these controls is a knob or dial (its turns are clicks)."""
        return any(
            i.skill.startswith("turn") and set(i.controls) & set(tokens)
            for i in getattr(self, "infos", [])
        )

    def _turned(self, tokens: list[str]) -> bool:
        """The panel has a knob or dial other than these controls (its turns are clicks)."""
        return any(
            i.skill.startswith("turn") and not set(i.controls) & set(tokens)
            for i in getattr(self, "infos", [])
        )
