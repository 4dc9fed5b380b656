"""A control's list of values settled: the list read near it weighed against lists found elsewhere,
a table column, "only" lists that say where a setting applies, the names of a range's pieces,
midpoints between a knob's marks, figures a lamp prints, and where the list starts and wraps.
Apart from evidence.py (reading the control's sentences) because it judges what was read there.
"""

from __future__ import annotations

import re

from apbot.read.evidence_checks import (
    _every_minute_top,
    _names_of_pieces,
    _part_of,
    _where_it_applies,
    _with_every,
    _with_midpoints,
    _without_only,
    between_marks,
    excluded_list,
)
from apbot.read.evidence_elsewhere import ElsewhereReader
from apbot.read.evidence_whose import (
    _named_only,
    _without_own_name,
)
from apbot.read.figure_names import figures_named
from apbot.read.labels import words
from apbot.read.printed_pairs import icon_led, printed_pair
from apbot.read.quantity_units import _quantity_units
from apbot.read.shapes import (
    CHOICE_WORDS,
    Evidence,
    _numeric_items,
)
from apbot.read.switch_on_starts import start_at_switch_on
from apbot.read.two_choices import two_choices
from apbot.read.values import (
    gap_pieces,
)
from apbot.read.values_elided import filled
from apbot.read.values_wraps import wrap_ends


class ValueChooser(ElsewhereReader):
    """The final list of a control's values, from the candidates its sentences gave."""

    def _chosen_values(
        self,
        tokens: list[str],
        ev: Evidence,
        best: list[str] | None,
        best_prio: float,
        candidates: list[list[str]],
        own_words: set[str],
        others: set[str],
        own: set[str],
        mentions: set[int],
        elsewhere: set[int],
    ) -> Evidence:
        """Settles ``ev``'s values (and their start, fill and wrap) from the best list read in
        the control's sentences and the ``candidates`` beside it."""
        units = self.manual.units
        best, best_prio = self._values_elsewhere(
            tokens, own_words, others, own, best, best_prio, ev
        )
        shown = units[ev.values_at].text if best and ev.values_at is not None else ""
        if best and re.search(r"\bonly\W*$", best[-1], re.I) and not _named_only(best[-1], shown):
            # "(STEW, JAM, BROTH only)": where the setting applies, not its values
            best = None if _where_it_applies(best, shown) else _without_only(best) or None
        if best and shown and excluded_list(best, shown):
            best = None  # "PRESET cannot be used on QUICK, STEAM or CAKE": the other menus
        choice = bool({w for t in tokens for w in words(t.replace("_", " "))} & CHOICE_WORDS)
        if best is None or (_numeric_items(best) and (len(best) < 3 or choice)):
            # two numbers are a range, not a list; a programme key's list is of names (but
            # codes it lists, "MENU 1 … MENU 15", stay codes beside a numbered chart)
            column = self._table_column(tokens, numbered=best is None or len(best) < 3)
            if column:
                best, ev.values_at = column, self._table_at
            elif (
                best is not None
                and len(best) < 3
                and not self._flips_between(ev.values_at)
                and not printed_pair(best, units, ev.values_at)
            ):
                best = None
        elif not _numeric_items(best):
            column = self._table_column(tokens)
            if column and _part_of(best, column):
                best, ev.values_at = column, self._table_at
        if best and len(ev.ranges) >= 2 and _names_of_pieces(best, units, ev.range_at):
            best = None  # "| Short | 0.5 – 10 hours | half an hour |": names of the range's pieces
        if best is None and not ev.ranges:
            runs = self._unit_runs(tokens)
            if runs is not None:  # the settings one by one: pieces of equal steps
                amounts, at = runs
                symbol = _quantity_units(tokens)[0]
                ev.ranges.extend(gap_pieces(amounts, symbol))
                ev.range_at = at
        if best is not None and _numeric_items(best) and len(best) >= 3:
            near = {
                j
                for i in mentions
                for j in range(i, min(i + 5, len(units)))
                if units[j].heading == units[i].heading
            }  # the paragraph about the knob: its marks, then how it clicks between them
            said = [units[i].text for i in sorted(near | set(self.context(tokens)))]
            if any(between_marks(t) for t in said):
                best = _with_midpoints(best)
            for t in said:  # "in the first ten minutes every minute has its own tick"
                top = _every_minute_top(t)
                if top and 2 <= top <= 30 and top == int(top):
                    best = _with_every(best, int(top))
                    break
        if best is not None and _numeric_items(best):
            for listed in candidates:  # "3000K → 4500K" and a chart "WARM  3000K": by name
                shows = figures_named(best, listed, units)
                if shows:
                    best, ev.shows = listed, shows
                    break
        if best is not None and ev.shows is None and (marked := icon_led(best)) is not None:
            best, ev.shows = marked  # "♪ tone → ≋ vibration → ϟ static": tone shown ♪
        if best is not None:
            best = _without_own_name(best, own)
            ev.values = best if _numeric_items(best) else [v.lower() for v in best]
            self._initial_from_values(ev, tokens)
        if ev.values and ev.values_at is not None:
            ev.values = filled(ev.values, units[ev.values_at].text)  # "-18 → ... → -23"
        if ev.initial is None and (ev.ranges or ev.values):
            start_at_switch_on(units, ev, own_words)  # "When switched on it runs at speed 3"
        if ev.ranges or not ev.values or _numeric_items(ev.values):
            # "after 23:45 comes 00:00", "after 15 back to 0": the ends of what was read
            about_it = [i for i in self.context(tokens) if i not in elsewhere or i in mentions]
            wrap_ends(ev, units, about_it)
        return ev

    def _flips_between(self, at: int | None) -> bool:
        """The list of two amounts was read where the key flips between them: two choices."""
        return at is not None and two_choices(self.manual.units[at].text)
