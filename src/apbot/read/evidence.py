"""What the manual says about a control: values, ranges, steps, toggles, each with the unit
it came from (the builder asks once per control and keeps the answer). Second looks at a list
or table are in evidence_checks.py; a setting's range found anywhere, in evidence_anywhere.py;
whose a sentence, row or list is, in evidence_whose.py; its values written away from its own
sentences, in evidence_elsewhere.py; ranges read across several sentences, a chart or a guide
column, in evidence_ranges.py; the list of values settled from what was read, in
evidence_values.py.
"""

from __future__ import annotations

import re
from functools import lru_cache

from apbot.read.abutting_ranges import abutting
from apbot.read.chart_cells import own_cells, row_names, without_names
from apbot.read.code_spans import code_span, led_span
from apbot.read.cycle_mentions import named_in_cycle_only
from apbot.read.end_stops import end_stops
from apbot.read.evidence_anywhere import AnywhereReader
from apbot.read.evidence_checks import (
    _where_it_applies,
    _without_only,
)
from apbot.read.evidence_lists import own_legend_items
from apbot.read.evidence_ranges import RangeReader
from apbot.read.evidence_values import ValueChooser
from apbot.read.evidence_whose import (
    _KEY_HEAD,
    _after_own,
    _fitting_step,
    _foreign_units,
    _item_run,
    _named_only,
    _presses_another,
    _with_items,
    _with_rows,
    lead_cell,
    names_another,
)
from apbot.read.label_levels import label_levels
from apbot.read.labels import unit_only_mention, words
from apbot.read.model_rows import own_model_row
from apbot.read.named_bands import counted_name, named_bands
from apbot.read.own_press_ranges import own_press_range_wins
from apbot.read.shapes import (
    _KEYPAD_WORDS,
    DOWN_WORDS,
    LAMP_LIST_RE,
    UP_WORDS,
    Evidence,
    _aside,
    _cell_key,
    _fits,
    _keyish,
    _keypad,
    _numeric_items,
    _without,
    _without_advice,
    comes_round,
    is_wait,
)
from apbot.read.shapes_columns import (
    _header_row,
    _row_step,
    _rows_span,
)
from apbot.read.table_spans import column_span, own_range_row
from apbot.read.text_sections import other_model, surroundings
from apbot.read.two_choices import two_choices
from apbot.read.value_lists import named_list
from apbot.read.value_steps import find_initial, find_step
from apbot.read.values import (
    EACH_PRESS_RE,
    NUM,
    ON_OFF_RE,
    Range,
    find_ranges,
    find_shown_hmm,
    seconds,
)
from apbot.read.values_scales import beyond, scale_pieces, spans_read
from apbot.read.values_stated import stated_unit_span, stated_unit_step
from apbot.read.values_stepped import find_arrow_pieces, find_stepped_pieces


class EvidenceReader(ValueChooser, RangeReader, AnywhereReader):
    """Evidence about controls: values, ranges, steps and toggles, with where each was read."""

    _evidence: dict[tuple[str, ...], Evidence]

    def evidence(self, tokens: list[str]) -> Evidence:
        """What the manual says about the controls (cached: roles ask more than once)."""
        key = tuple(tokens)
        if key not in self._evidence:
            self._evidence[key] = self._read_evidence(tokens)
        return self._evidence[key]

    def _only_pair_named(self, i: int, tokens: list[str]) -> bool:
        """Whether the keys unit ``i`` names, this one aside, are all the stepping pair ("Press
        + to set it:" then its steps span by span): then its steps are this key's, while under
        "Press DELAY to set …:" they are DELAY's."""
        return all(
            set(t.split("_")) & (UP_WORDS | DOWN_WORDS)
            for t, lab in self.labels.items()
            if t not in tokens and i in lab.mentions
        )

    def _read_evidence(self, tokens: list[str]) -> Evidence:
        ev = Evidence()
        units = self.manual.units
        others = {
            lab.text.lower() for t, lab in self.labels.items() if t not in tokens and lab.line
        }
        own = {self.labels[t].text.upper() for t in tokens if t in self.labels}
        mentions = {i for t in tokens if t in self.labels for i in self.labels[t].mentions}
        best: list[str] | None = None
        best_prio = 0.0
        candidates: list[list[str]] = []  # every list read for the key, for names of figures
        elsewhere = {
            i
            for t, lab in self.labels.items()
            if t not in tokens
            for i in lab.mentions
            if not unit_only_mention(lab, units[i].text)  # "… in 5 °F steps": not TEMP's
            and not named_in_cycle_only(lab.text, units[i].text)  # "LIGHT → DARK → LIGHT"
        }
        steps = self._pair_steps(tokens, mentions)  # "Press ▲ or ▼ to set …" after its step
        elsewhere, mentions = elsewhere - steps, mentions | steps
        other_labels = [
            lab.text
            for t, lab in self.labels.items()
            if t not in tokens and lab.text and lab.text.upper() == lab.text
        ]
        other_keys = {_cell_key(lab) for lab in other_labels} - {_cell_key(o) for o in own}
        other_words = {
            w
            for t in self.labels
            if t not in tokens
            for w in [x for x in words(t.replace("_", " ")) if len(x) >= 4][:1]
        }
        context = self.context(tokens)
        own_labels = [self.labels[t].text for t in tokens if t in self.labels]
        own_words = {w for t in tokens for w in words(t.replace("_", " ")) if len(w) >= 3}
        own_words |= {w for o in own for w in words(o) if len(w) >= 3}
        chart_names = row_names(units)
        scaled: list[Range] = []  # the pieces of a scale, once read
        for i in [*context, *sorted(steps - set(context))]:  # (a step further down: its own)
            text = units[i].text
            unit = units[i]
            item = unit.bullet and unit.step is None  # (an item's spans are its lead's)
            told = text if item else _with_rows(units, i) if unit.cells else _with_items(units, i)
            if item and not find_stepped_pieces(text):
                run, lead = _item_run(units, i)  # "- 1 to 10 min in 1-min clicks," "- then …"
                if len(find_stepped_pieces(run)) >= 2 and not (
                    lead >= 0 and _presses_another(units[lead].text, other_labels, own)
                ):
                    told = run  # (not under "Press DELAY to set …:", DELAY's own items)
            pieced = (
                len(find_stepped_pieces(told)) >= 2  # its steps, item by item, pressing
                and self._only_pair_named(i, tokens)  # the pair, not another key's setting
            )
            if (
                i in elsewhere
                and i not in mentions
                and not unit.cells
                and not pieced
                and not _named_range(text, own_words)
            ):
                continue  # a sentence about another key says nothing about this one
            if i not in mentions and other_model(units, i):
                continue  # "Model XY-300 only: …": another model's keys and their values
            if i not in mentions and any(named_list(text, w) for w in other_words):
                continue  # "The menu names printed on the panel: …" near KEEP WARM: MENU's
            if unit.cells and i not in mentions and names_another(unit.cells, other_keys):
                continue  # a key table's row about another key ("| SIZE | S, M or L |")
            if (
                unit.cells
                and unit.header
                and i not in mentions
                and _KEY_HEAD.search(unit.header[_lead_index(unit.cells)])
            ):
                continue  # the next row of a key table: another key's, even one not on this panel
                # (after a column that numbers the rows: "| No. | Key / part | Touch |")
            if unit.cells and unit.header and unit.cells[0].upper() in own:
                head = unit.header[0].lower()
                if not re.search(r"key|button|control|pad|dial|knob|symbol|name", head):
                    continue  # a row describing the value the key names, not the key's setting
            quiet = _aside(units, i) or _header_row(units, i)
            # "| MODE | AUTO → SLEEP | with TIMER, 3 s: lock |": MODE's row, whatever it names
            theirs = bool(unit.cells) and names_another(unit.cells, other_keys)
            lists = [] if quiet or theirs else self._lists(i, i in mentions, tokens)
            for items, prio in lists:
                if _keyish(items, others, own, text) or _foreign_units(items, tokens):
                    continue  # a list of keys ("DELAY, then + / −"), not of values
                if (
                    len(items) >= 3
                    and any(v.upper().strip(" .") in own for v in items)
                    and not (items[0].upper().strip(" .") in own and comes_round(items, text))
                ):
                    continue  # "NORMAL → CONT. → FAN" near FAN: a list with a mode named FAN
                    # (a key printed with its first value, the list coming round to it, is
                    # that list's key: "hPa → inHg → mmHg → hPa" for the hPa key)
                lamps = LAMP_LIST_RE.match(text)
                if lamps and not set(words(lamps.group(0))) & {
                    w for t in tokens for w in words(t.replace("_", " "))
                }:
                    continue  # "Lamps (top row): FAN HI, FAN LO, 2H…": what lights, not values
                    # ("Mode lamps: NORMAL CONT. …" are the mode key's values)
                if _numeric_items(items) and len(items) < 3 and not two_choices(text):
                    continue  # (two amounts a key flips between are its two choices)
                named = _named_only(items[-1], text)  # "… → COOL ONLY →": a name
                if not named and _where_it_applies(items, text):
                    continue  # "(PORRIDGE, STEAM, SOUP only)": where it applies, not its values
                items = items if named else _without_only(items)  # "SOFT or FIRM only": values
                if not items:
                    continue
                candidates.append(items)
                if prio > best_prio:
                    best, best_prio, ev.values_at = items, prio, i
            waiting = i not in mentions and is_wait(text)  # "Leave for one to two hours."
            waiting = waiting or surroundings(text)  # "at an ambient 5 to 35 °C": the room's
            waiting = waiting or two_choices(text)  # "toggles between 1.5 lb and 2.0 lb": two
            waiting = waiting or named_bands(text)  # "Largo 40–60 · Adagio 66–76": a chart's
            waiting = waiting or counted_name(text)  # "VOICE 1-2-3-4": a name, no 1–4
            ranges = [
                r
                for r in find_ranges(
                    ""
                    if waiting
                    else without_names(
                        _without_advice(
                            own_cells(own_model_row(unit, self.manual.lines, units), own_words)
                        ),
                        chart_names,
                    )
                )
                if _fits(r.unit, tokens) and not _keypad(r, text)
            ]
            stops = (
                None if waiting or ranges else end_stops(text)
            )  # "Nothing happens beyond 1 or 8"
            if stops and _fits(stops.unit, tokens) and ev.range_at not in mentions:
                ev.ranges, ev.range_at = [stops], i
            if not ranges and i in steps and not waiting and (coded := code_span(text)):
                ranges = [coded]  # "Press ▲ / ▼: CA 1 … CA 5" after this key's own step
            levels = [lv for o in own if i in mentions and (lv := label_levels(text, o))]
            if not ranges and len(levels) == 1:
                ranges = levels  # "LIGHT 1 dimmest  LIGHT 2 dim  LIGHT 3 …": the key's own
                ev.each_press_at = i if ev.each_press_at is None else ev.each_press_at  # steps
            if ev.keypad_at is None and _KEYPAD_WORDS.search(text):
                ev.keypad_at = i
            if ranges and unit.cells and len(ranges) == 1 and ranges[0].step is None:
                row_step = _row_step(unit.cells, ranges[0].unit)
                if row_step:
                    ranges = [Range(ranges[0].low, ranges[0].high, ranges[0].unit, row_step)]
            if unit.cells:  # "| 1 – 2 |" then "| 3 – 4 |" … "| 9 – 10 |": groups of one setting
                ranges = [_rows_span(units, i, r) for r in ranges]
                if len(ranges) == 1:  # "| Situation | Mode | Pressure |": the whole column's
                    ranges = [column_span(units, i, ranges[0], own_words)]
            if (
                ranges
                and ev.range_at not in (None, i)
                and own_range_row(unit, own_words)
                and not own_range_row(units[ev.range_at], own_words)
            ):
                ev.ranges, ev.range_at = [], None  # the setting's own row of a range table
            pieces = find_stepped_pieces(told) if not ev.ranges else []
            arrows = find_arrow_pieces(text)  # "1 h → … → 12 h one hour per press 12 h → …"
            if arrows and _fits("s", tokens) and _covers(arrows, ev.ranges):
                pieces, ev.ranges = arrows, []
            # "Available temperatures (°C):" then "160 ── 180 ── 200 ── 210 ── …": uneven stops
            scale = scale_pieces(units, i)
            if scale and _fits(scale[0].unit, tokens) and spans_read(scale, ev.ranges):
                pieces, ev.ranges, scaled = scale, [], scale
            wider = beyond(scaled, ranges) if scaled and ev.ranges is scaled else None
            if wider:  # "Suggested times (min):" 8 | 12 | … 25, then "1 to 60 minutes"
                ev.ranges, ev.range_at = [wider], i
            if pieces and _fits(pieces[0].unit, tokens):  # "0:30 – 12:00 30 min 12:00 – 24:00 1 h"
                ev.ranges, ev.range_at = pieces, i
            elif ranges and not ev.ranges:
                # "one minute per click up to one hour, and in coarser steps after that, up to
                # 3 hours": the same range told twice, the wider is the whole of it
                same = [r for r in ranges if r.low == ranges[0].low and r.unit == ranges[0].unit]
                ev.ranges, ev.range_at = [abutting(max(same, key=lambda r: r.high), ranges)], i
            elif ranges and ev.ranges and ranges[0].unit == ev.ranges[-1].unit:
                last = ev.ranges[-1]
                if abs(ranges[0].low - last.high) < 1e-9 and ranges[0].high > last.high:
                    ev.ranges.append(ranges[0])  # the next piece of a piecewise range
                elif len(ev.ranges) == 1 and ev.range_at == i - 1:  # "… 128 to 9999 are long"
                    ev.ranges = [abutting(last, ranges[:1])]
            if ev.step is None:
                step = _fitting_step(text, tokens)
                if step:
                    ev.step, ev.step_at = step, i
            if (
                ev.toggle_at is None
                and not quiet  # ("The hob deactivates." under Troubleshooting)
                # ("[3] FOG – fog on / off [5] BURST – …" run together: FOG's, not BURST's)
                and ON_OFF_RE.search(_without(own_legend_items(text, own_labels), other_labels))
                and not two_choices(text)  # "toggles between 1.5 lb and 2.0 lb": no on/off
                and not self._two_key_hold(text, tokens)
            ):
                ev.toggle_at = i  # (another key's name, ON/OFF in a panel drawing, is no toggle)
            pressed = EACH_PRESS_RE.search(text)
            if pressed and pressed.group("further") and not find_ranges(text):
                pressed = None  # "each further press … in this order:" leads a list, no amount
            if pressed and "click" in pressed.group(0).lower() and self._turned(tokens):
                pressed = None  # "every click changes the time": a dial's clicks, not a key's
            if pressed and _presses_another(text, other_labels, own):
                pressed = None  # "Touch + to raise … with each touch": the pair's presses
            elif (
                pressed
                and pressed.start() < 3
                and i > 0
                and units[i - 1].line == unit.line
                and not unit.cells
                and _presses_another(_after_own(units[i - 1].text, own), other_labels, own)
            ):
                pressed = None  # "Press ▲ or ▼. Each press moves the time …": the pair's
                # (also "Press HOURS, then press ▲ or ▼. Each press …": the last pressed)
            if ev.each_press_at is None and not quiet and pressed:
                ev.each_press_at = i
            if ev.shown_hmm is None and (minutes := find_shown_hmm(text)):  # ("2:00": no minutes)
                ev.shown_hmm = (minutes, i)
            if ev.initial is None:
                init = find_initial(text)
                if init:
                    ev.initial, ev.initial_at = init, i
        self._ranges_across(tokens, ev, context, mentions, others, own)
        own_words = {w for t in tokens for w in words(t.replace("_", " ")) if len(w) >= 3}
        if ev.step is None and own_words:  # "The delay is set in half-hour units.", anywhere
            subject = re.compile(rf"^(?:the\s+)?(?:{'|'.join(map(re.escape, own_words))})\b", re.I)
            for i, unit in enumerate(units):
                step = None if unit.cells or not subject.match(unit.text) else find_step(unit.text)
                if step:
                    ev.step, ev.step_at = step, i
                    break
        if not ev.ranges or ev.range_at not in mentions:
            led = led_span(units, mentions, own_words)  # "Setting the address (1 … 512):"
            if led is not None:
                ev.ranges, ev.range_at = [led[0]], led[1]
        if not ev.ranges:  # "The range is 30 BPM to 280 BPM": a unit no pattern knows
            spans = [(r, i) for i in context if (r := stated_unit_span(units[i])) is not None]
            if spans:
                ev.ranges, ev.range_at = [spans[0][0]], spans[0][1]
                if ev.step is None and (by := stated_unit_step(units, context, spans[0][1])):
                    ev.step, ev.step_at = (by[0], ""), by[1]  # "changes the tempo by 1 BPM"
        if own_press_range_wins(ev, mentions):  # ("each further press adds one second, …")
            best, best_prio, ev.values_at = None, 0.0, None
        return self._chosen_values(
            tokens, ev, best, best_prio, candidates, own_words, others, own, mentions, elsewhere
        )


def _named_range(text: str, own_words: set[str]) -> bool:
    """The setting's own noun right before a range ("HOT has the speeds 1 to 5" near COLD):
    the range is this setting's, whatever key the sentence also names."""
    if not own_words or not any(c.isdigit() for c in text):
        return False
    return bool(_range_after(tuple(sorted(own_words))).search(text))


@lru_cache(maxsize=256)
def _range_after(own_words: tuple[str, ...]) -> re.Pattern[str]:
    nouns = "|".join(map(re.escape, own_words))
    return re.compile(rf"\b(?:{nouns})s?\s+{NUM}\s*(?:to|–|-)\s*{NUM}\b", re.I)


def _lead_index(cells: tuple[str, ...]) -> int:
    """The column of a row's :func:`lead_cell` (1 when a first column only numbers the rows)."""
    lead = lead_cell(cells)
    return next(k for k, cell in enumerate(cells) if cell is lead)


def _covers(pieces: list[Range], ranges: list[Range]) -> bool:
    """Whether pieces read later span at least what was read before (none, or one range that
    lies inside them: "1 – 12 h" beside "1 h → … → 12 h, 12 h → … → 24 h")."""
    if not ranges:
        return True
    if any(r.unit not in ("s", "min", "h") for r in ranges):
        return False
    low = min(seconds(r.low, r.unit) for r in ranges)
    high = max(seconds(r.high, r.unit) for r in ranges)
    return pieces[0].low <= low and high <= pieces[-1].high and len(pieces) > len(ranges)
