"""Assemble an appliance model from what the manual says about each control.

Each action is given a *role* from its name and the sentences that mention its control: power,
start, stop, lock, a stepping pair (▲/▼, +/−), a digit, a dial, or a setting key. A setting key's
sentences decide what it sets: a value list it cycles, an on/off toggle, a range it steps or that
the stepping pair / keypad enters after it. Keys the manual only lists together (programme pads)
become one variable with a go-to value each. Where the manual is silent the reader picks the
guess the closed loop repairs most cheaply — a cyclic ``next`` over a small domain — and says so.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, field
from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.labels import Label, words
from apbot.read.report import Note
from apbot.read.text import Manual, Unit
from apbot.read.values import (
    EACH_PRESS_RE,
    ON_OFF_RE,
    Range,
    anchored_lists,
    bare_list,
    caps_run,
    cell_list,
    find_bounds,
    find_initial,
    find_list,
    find_number_run,
    find_ranges,
    find_step,
    quantity_run,
    seconds,
)

LAMP_LIST_RE = re.compile(
    r"^\W*(?:the\s+)?(?:\w+\s+){0,2}(?:lamps?|indicators?|symbols?|icons?|LEDs?|lights)\b"
    r"(?:\s*\([^)]*\))?\s*:",
    re.IGNORECASE,
)
UP_WORDS = {"up", "plus", "more", "increase", "inc", "higher", "add", "right", "next", "forward"}
DOWN_WORDS = {"down", "minus", "less", "decrease", "dec", "lower", "left", "prev", "previous"}
POWER_TOKENS = {"power", "on_off", "onoff", "on", "power_on_off", "standby"}
STOP_WORDS = {"stop", "cancel", "clear", "reset", "off", "end"}
GENERIC_DIALS = {"dial", "knob", "select", "selector", "jog", "wheel", "control"}
SETTING_NOUNS = (
    "temperature", "humidity", "timer", "time", "delay", "level", "power", "speed", "volume",
    "weight", "programme", "program", "mode", "setting", "heat", "strength", "size",
)  # fmt: skip
CHOICE_WORDS = {"programme", "program", "menu", "mode", "function", "cycle", "course", "dial",
                "knob", "selector", "select"}  # fmt: skip
GROUP_NOUNS = ("programme", "program", "menu", "mode", "function", "cycle", "course", "preset")
RUNNING_RE = re.compile(
    r"\b(?:while|during|when)\b[^.]*\b(?:running|cooking|operat\w*|works?|working|heating|"
    r"washing|in progress|runs)\b[^.]*\b(?:only|ignored|not respond|do not work|disabled|no effect"
    r"|locked|inactive)\b|\bonly\b[^.]*\bwork\w*\b[^.]*\bwhile\b",
    re.IGNORECASE,
)


ORDER_RE = re.compile(r"\bin (?:this|the following|that) order\b", re.I)


@dataclass
class Evidence:
    values: list[str] | None = None
    values_at: int | None = None
    ranges: list[Range] = field(default_factory=list)
    range_at: int | None = None
    step: tuple[float, str] | None = None
    step_at: int | None = None
    toggle_at: int | None = None
    each_press_at: int | None = None
    initial: Any = None
    initial_at: int | None = None
    keypad_at: int | None = None  # a sentence of its context speaks of the number keys
    longest: tuple[Range, int] | None = None  # "the longest setting is 13 hours", alone


class Builder:
    """Collects variables, features, guards and notes; ``data()`` gives the model as plain data."""

    def __init__(self, manual: Manual, infos: list[ActionInfo], labels: dict[str, Label]):
        self.manual = manual
        self.infos = infos
        self.labels = labels
        self.variables: dict[str, dict[str, Any]] = {}
        self.features: dict[str, list[dict[str, Any]]] = {}
        self.guards: list[dict[str, Any]] = []
        self.notes: list[Note] = []
        self.indicators: list[str] = []
        self._evidence: dict[tuple[str, ...], Evidence] = {}

    # --- notes ------------------------------------------------------------------------------

    def note(self, subject: str, what: str, unit: int | None = None) -> None:
        if unit is None:
            self.notes.append(Note(subject, what, guess=True))
        else:
            line = self.manual.units[unit].line
            self.notes.append(Note(subject, what, line, self.manual.quote(line)))

    # --- evidence ---------------------------------------------------------------------------

    def context(self, tokens: list[str]) -> list[int]:
        """Units mentioning the controls, each followed by the next two of its section (and a
        table the sentence points to)."""
        seen: list[int] = []
        units = self.manual.units
        for token in tokens:
            for i in self.labels[token].mentions:
                for j in range(i, min(i + 3, len(units))):
                    if j > i and (
                        units[j].heading != units[i].heading or units[j].text == units[j].heading
                    ):
                        break
                    if j not in seen:
                        seen.append(j)
                    if re.search(r"\btable\b", units[j].text, re.I):
                        k = j + 1
                        while k < len(units) and not units[k].cells and k < j + 3:
                            k += 1
                        while k < len(units) and units[k].cells:
                            if k not in seen:
                                seen.append(k)
                            k += 1
        for token in tokens:
            tw = [w for w in words(token.replace("_", " ")) if len(w) >= 4]
            for i, unit in enumerate(units):
                if unit.text != unit.heading or not tw:
                    continue
                hw = words(unit.heading)
                if any(
                    _same_word(h, t) for t in tw for h in hw if len(h) >= 4
                ):  # ("Cookware" is no heading of COOK: a word, not a prefix)
                    if i not in seen:
                        seen.append(i)  # the heading itself: bullets below it list values
                    for j in range(i + 1, min(i + 6, len(units))):
                        if units[j].heading != unit.heading:
                            break
                        if j not in seen:
                            seen.append(j)
        return seen

    def evidence(self, tokens: list[str]) -> Evidence:
        """What the manual says about the controls (cached: roles ask more than once)."""
        key = tuple(tokens)
        if key not in self._evidence:
            self._evidence[key] = self._read_evidence(tokens)
        return self._evidence[key]

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
        elsewhere = {i for t, lab in self.labels.items() if t not in tokens for i in lab.mentions}
        other_labels = [
            lab.text
            for t, lab in self.labels.items()
            if t not in tokens and lab.text and lab.text.upper() == lab.text
        ]
        other_keys = {_cell_key(lab) for lab in other_labels} - {_cell_key(o) for o in own}
        for i in self.context(tokens):
            text = units[i].text
            unit = units[i]
            if i in elsewhere and i not in mentions and not unit.cells:
                continue  # a sentence about another key says nothing about this one
            if unit.cells and i not in mentions and _cell_key(unit.cells[0]) in other_keys:
                continue  # a key table's row about another key ("| SIZE | S, M or L |")
            if unit.cells and unit.header and unit.cells[0].upper() in own:
                head = unit.header[0].lower()
                if not re.search(r"key|button|control|pad|dial|knob|symbol|name", head):
                    continue  # a row describing the value the key names, not the key's setting
            quiet = _aside(units, i) or _header_row(units, i)
            lists = [] if quiet else self._lists(i, i in mentions, tokens)
            for items, prio in lists:
                if _keyish(items, others, own):
                    continue  # a list of keys ("DELAY, then + / −"), not of values
                lamps = LAMP_LIST_RE.match(text)
                if lamps and not set(words(lamps.group(0))) & {
                    w for t in tokens for w in words(t.replace("_", " "))
                }:
                    continue  # "Lamps (top row): FAN HI, FAN LO, 2H…": what lights, not values
                    # ("Mode lamps: NORMAL CONT. …" are the mode key's values)
                if _numeric_items(items) and len(items) < 3:
                    continue
                if prio > best_prio:
                    best, best_prio, ev.values_at = items, prio, i
            ranges = [
                r
                for r in find_ranges(_without_advice(unit))
                if _fits(r.unit, tokens) and not _keypad(r, text)
            ]
            if ev.keypad_at is None and _KEYPAD_WORDS.search(text):
                ev.keypad_at = i
            if ranges and unit.cells and len(ranges) == 1 and ranges[0].step is None:
                row_step = _row_step(unit.cells, ranges[0].unit)
                if row_step:
                    ranges = [Range(ranges[0].low, ranges[0].high, ranges[0].unit, row_step)]
            if ranges and not ev.ranges:
                # "one minute per click up to one hour, and in coarser steps after that, up to
                # 3 hours": the same range told twice, the wider is the whole of it
                same = [r for r in ranges if r.low == ranges[0].low and r.unit == ranges[0].unit]
                ev.ranges, ev.range_at = [max(same, key=lambda r: r.high)], i
            elif ranges and ev.ranges and ranges[0].unit == ev.ranges[-1].unit:
                last = ev.ranges[-1]
                if abs(ranges[0].low - last.high) < 1e-9 and ranges[0].high > last.high:
                    ev.ranges.append(ranges[0])  # the next piece of a piecewise range
            if ev.step is None:
                step = find_step(text)
                if step:
                    ev.step, ev.step_at = step, i
            if (
                ev.toggle_at is None
                and ON_OFF_RE.search(_without(text, other_labels))
                and not self._two_key_hold(text, tokens)
            ):
                ev.toggle_at = i  # (another key's name, ON/OFF in a panel drawing, is no toggle)
            if ev.each_press_at is None and EACH_PRESS_RE.search(text):
                ev.each_press_at = i
            if ev.initial is None:
                init = find_initial(text)
                if init:
                    ev.initial, ev.initial_at = init, i
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
        own_words = {w for t in tokens for w in words(t.replace("_", " ")) if len(w) >= 3}
        if best_prio < 2.0 and own_words:  # "Mode lamps (left to right): NORMAL CONT. FAN"
            for i, unit in enumerate(units):
                lamps = LAMP_LIST_RE.match(unit.text)
                if lamps and set(words(lamps.group(0))) & own_words:
                    rest = unit.text[lamps.end() :]
                    for after in units[i + 1 : i + 8]:  # "CONT." ended a "sentence" mid-line
                        if after.line != unit.line:
                            break
                        rest += "   " + after.text
                    found = bare_list(rest)
                    if found:
                        best, best_prio, ev.values_at = found, 2.0, i
                        break
        if best_prio < 1.85:  # "Drying-time settings available: 10 · 20 · 30 · 60 min."
            for i, unit in enumerate(units):
                led = None if _aside(units, i) else self._led_list(unit, tokens)
                if led and not _keyish(led, others, own):
                    best, best_prio, ev.values_at = led, 1.85, i
                    break
        if best_prio < 1.8:  # lists tied to the setting's own word anywhere in the manual
            for t in tokens:
                for w in [x for x in words(t.replace("_", " ")) if len(x) >= 4][:1]:
                    for i, unit in enumerate(units):
                        anchored = [] if _aside(units, i) else anchored_lists(unit.text, w)
                        if anchored and _keyish(anchored[0], others, own):
                            continue
                        if anchored and best_prio < 1.8:
                            best, best_prio, ev.values_at = anchored[0], 1.8, i
        for t in tokens:
            label = self.labels[t].text if t in self.labels else ""
            if not label or best_prio >= 2.5 or not re.search(r"[A-Z]", label):
                continue
            printed = re.fullmatch(r"([A-Z][A-Z ]*?)\s+([A-Z0-9]{1,6}(?:/[A-Z0-9]{1,6})+)", label)
            if printed and t in self.labels and self.labels[t].line is not None:
                # the key's printed name carries its values: "FAN HI/LO"
                best, best_prio = printed.group(2).split("/"), 2.5
                ev.values_at = self.labels[t].mentions[0] if self.labels[t].mentions else None
                continue
            pattern = re.compile(
                rf"\b{re.escape(label)}\s+([A-Z0-9]{{1,6}}(?:/[A-Z0-9]{{1,6}})+)\b"
            )
            for i, unit in enumerate(units):
                m = pattern.search(unit.text)
                if m:  # "FAN HI/LO": the panel prints the values next to the name
                    best, best_prio, ev.values_at = m.group(1).split("/"), 2.5, i
                    break
        choice = bool({w for t in tokens for w in words(t.replace("_", " "))} & CHOICE_WORDS)
        if best is None or (_numeric_items(best) and (len(best) < 3 or choice)):
            # two numbers are a range, not a list; a programme key's list is of names
            column = self._table_column(tokens)
            if column:
                best, ev.values_at = column, self._table_at
            elif best is not None and len(best) < 3:
                best = None
        if best is None and not ev.ranges:
            runs = self._unit_runs(tokens)
            if runs is not None:  # the settings one by one: pieces of equal steps
                amounts, at = runs
                symbol = next(q for q in (_quantity_unit(t) for t in tokens) if q)
                for lo, hi in itertools.pairwise(amounts):
                    gap = round(hi - lo, 6)
                    if ev.ranges and ev.ranges[-1].step == gap:
                        ev.ranges[-1] = Range(ev.ranges[-1].low, hi, symbol, gap)
                    else:
                        ev.ranges.append(Range(lo, hi, symbol, gap))
                ev.range_at = at
        if best is not None:
            ev.values = best if _numeric_items(best) else [v.lower() for v in best]
            self._initial_from_values(ev, tokens)
        return ev

    def _two_key_hold(self, text: str, tokens: list[str]) -> bool:
        """Whether a sentence tells of holding two keys together, one of them this one, when
        the panel has that two-key hold ("press and hold SPIN and STEAM for 3 seconds: CL
        appears; hold them again to switch it off"): its on/off is the hold's, not the key's."""
        if len(tokens) != 1 or not re.search(r"\bhold", text, re.IGNORECASE):
            return False
        for info in self.infos:
            if len(info.controls) > 1 and tokens[0] in info.controls:
                names = [self.labels[c].text for c in info.controls if c in self.labels]
                if len(names) == len(info.controls) and all(n and n in text for n in names):
                    return True
        return False

    def _unit_runs(self, tokens: list[str]) -> tuple[list[float], int] | None:
        """For a quantity (watts, volume, weight, spin) of which nothing else is read: the
        numbers a table headed by its unit lists in runs joined by middle dots ("Output
        settings (W) … 500 · 600 · 700 … 1500 100 W Medium 1600 · 1700 …"), all runs of that
        table together, in order."""
        unit = next((u for u in (_quantity_unit(t) for t in tokens) if u in QUANTITY_FAMILIES), "")
        if not unit:
            return None
        family = "|".join(re.escape(u) for u in sorted(QUANTITY_FAMILIES[unit], key=len))
        headed = re.compile(rf"\((?:{family})\)", re.IGNORECASE)
        units = self.manual.units
        for i, u in enumerate(units):
            if u.header or _aside(units, i) or not headed.search(u.text):
                continue
            table = [u]
            for row in units[i + 1 :]:  # a header row: its rows too
                if not u.cells or row.header != u.cells:
                    break
                table.append(row)
            numbers: list[float] = []
            text = " ".join(row.text for row in table)  # a run may go on in the next row
            for run in RUN_RE.finditer(text):
                numbers += [float(x.replace(",", ".")) for x in re.split(r"\s*[·•|]\s*", run[0])]
            values = sorted(set(numbers))
            if len(values) >= 3:
                return values, i
        return None

    def _lists(self, i: int, mention: bool, tokens: list[str]) -> list[tuple[list[str], float]]:
        """Candidate value lists at unit ``i`` with a priority (arrows beat prose, prose in the
        sentence naming the key beats prose nearby, a table the sentence introduces...)."""
        units = self.manual.units
        unit = units[i]
        text = unit.text
        out: list[tuple[list[str], float]] = []
        found = find_list(text)
        if found:
            out.append((found[0], 3.0 if found[1] == "arrows" else 2.0 if mention else 1.0))
        else:
            own = {self.labels[t].text.upper() for t in tokens if t in self.labels}
            keys = {lab.text.upper() for lab in self.labels.values() if lab.text}
            span = self._own_span(text, tokens) if mention else text
            run = caps_run(span, own | keys)
            if run and (mention or len(run) >= 4):
                out.append((run, 1.9 if mention else 1.6))
            amounts = quantity_run(span) if mention else None
            if amounts:
                out.append((amounts, 1.9))
        legend = self._legend_cells(unit, tokens)
        if legend is not None:  # the panel's printing: only the cells beside the own name
            return [(legend, 2.4)] if legend and mention else []
        run = None
        for span in self._own_spans(text, tokens) if mention else [text]:
            run = find_number_run(span)  # "°C and RPM stop. °C is marked 20 30 40; RPM is …"
            if run:
                break
        if run:
            out.append((run, 2.2 if mention else 1.2))
        if text.rstrip().endswith(":") and i + 1 < len(units) and not units[i + 1].cells:
            after = bare_list(units[i + 1].text)  # "Printed round the knob:" then the marks
            # a long line is a list only when it is all short names ("OFF · Cottons · Eco …")
            if after and (len(units[i + 1].text) <= 120 or _all_names(after, units[i + 1].text)):
                out.append((after, 2.6))
        if ORDER_RE.search(text) and not text.rstrip().endswith((":", "order")):
            # "arranged round the knob in this order, clockwise." and the table a line or two on
            for k in range(i + 1, min(i + 4, len(units))):
                if units[k].cells:
                    column = _next_table_column(units, k - 1, self._own_column(k - 1, tokens))
                    if column and (mention or self._header_names(k - 1, tokens)):
                        out.append((column, 2.5))
                    break
        if text.rstrip().endswith((":", "order")) or text == unit.heading:
            bullets = _bullet_items(units, i, lead=2 if text == unit.heading else 0)
            if bullets:
                out.append((bullets, 1.5))
            index = self._own_column(i, tokens)
            column = _next_table_column(units, i, index) or (
                [] if index else _quantity_column(units, i)
            )
            if column:
                # a heading that only shares a word with the key ("Recipe: basic white loaf"
                # for LOAF) introduces a table about something else unless its header says so
                related = mention or text != unit.heading or self._header_names(i, tokens)
                out.append((column, 2.5 if related else 1.2))
        return out

    def _legend_cells(self, unit: Unit, tokens: list[str]) -> list[str] | None:
        """A line of the panel's printing laid out with wide spaces ("PROGRAM   OFF   AUTO   UV
        DRY   STORE     TIME  - / +     START"): the cells after the control's own name, up
        to the next control's name, are the positions printed beside it (empty: none). None
        when the unit is no such line."""
        if unit.cells and unit.header:
            return None  # a table's row, not its first line
        parts = unit.cells or tuple(re.split(r"\s{2,}|\t", unit.text.strip()))
        cells = [c.strip(" *[]") for c in parts]
        if len(cells) < 4 or any(len(c) > 20 or c != c.upper() for c in cells):
            return None
        own = {self.labels[t].text.upper() for t in tokens if t in self.labels}
        keys = {lab.text.upper() for lab in self.labels.values() if lab.text}
        keys |= {t.upper().replace("_", " ") for t in self.labels}  # "HOURS" for HOURS knob
        if sum(c.upper() in keys for c in cells) < 2:
            return None
        for k, cell in enumerate(cells):
            if cell.upper() not in own:
                continue
            items: list[str] = []
            for after in cells[k + 1 :]:
                if after.upper() in keys or not re.search(r"[A-Z0-9]", after):
                    break
                items.append(after)
            if len(items) >= 3:
                return items
        return []

    def _led_list(self, unit: Unit, tokens: list[str]) -> list[str] | None:
        """A list after a colon in a sentence that starts by naming the setting ("Drying-time
        settings available: …" for DRY TIME, "Timer steps: …" for TIMER), or in the next cell
        of a table row that does (a specifications table: "| Water levels | 22, 26 … 58 L |")."""
        if len(unit.cells) >= 2:
            if not self._names_setting(words(unit.cells[0]), tokens):
                return None
            items = cell_list(unit.cells[1])
            return items if items and len(items) >= 3 else None
        m = re.match(r"\s*([^:.;]{3,50}):\s*(.+)", unit.text)
        if not m or not self._names_setting(words(m.group(1)), tokens):
            return None
        found = find_list(unit.text)
        items = found[0] if found else bare_list(m.group(2))
        return items if items and len(items) >= 3 else None

    def _names_setting(self, lead: list[str], tokens: list[str]) -> bool:
        """Whether words start by naming the control's setting (by its action word or its printed
        label; "Water levels" names WATER LEVEL)."""
        names = [words(t.replace("_", " ")) for t in tokens]
        names += [words(self.labels[t].text) for t in tokens if t in self.labels]
        return any(
            name
            and len(name) <= len(lead)
            and all(lw.startswith(nw) and len(nw) >= 3 for nw, lw in zip(name, lead, strict=False))
            for name in names
        )

    def _own_spans(self, text: str, tokens: list[str]) -> list[str]:
        """:meth:`_own_span` from each place the key's label stands in the sentence."""
        own = [self.labels[t].text for t in tokens if t in self.labels and self.labels[t].text]
        starts = sorted({m.start() for lab in own for m in re.finditer(re.escape(lab), text)})
        if len(starts) <= 1:
            return [self._own_span(text, tokens)]
        return [self._own_span(text[k:], tokens) for k in starts]

    def _own_span(self, text: str, tokens: list[str]) -> str:
        """The part of a sentence about the key: from its label to the next other key's label
        ("below TEMP. a row printed 20 30 40, and below SPIN a row printed 400 800")."""
        own = [self.labels[t].text for t in tokens if t in self.labels and self.labels[t].text]
        starts = [text.find(lab) for lab in own if lab and text.find(lab) >= 0]
        if not starts:
            return text
        start = min(starts)
        others = [
            lab.text
            for t, lab in self.labels.items()
            if t not in tokens
            and lab.text
            and lab.text not in own
            and not any(lab.text in o for o in own)
        ]
        end = len(text)
        for lab in others:
            k = text.find(lab, start + 1)
            if k > start:
                end = min(end, k)
        return text[start:end]

    def _own_column(self, i: int, tokens: list[str]) -> int:
        """Which column of the table after unit ``i`` is the key's: one headed by the key's
        printed name when the header is a row of key names ("| TEMP. | SPIN | SOIL |"), else
        the first."""
        units = self.manual.units
        k = i + 1
        if k >= len(units) or not units[k].cells or units[k].header:
            return 0
        header = [c.strip(" *.").upper() for c in units[k].cells]
        keys = {lab.text.strip(" .").upper() for lab in self.labels.values() if lab.text}
        own = {self.labels[t].text.strip(" .").upper() for t in tokens if t in self.labels}
        if len(header) >= 2 and sum(h in keys for h in header) >= 2:
            for index, cell in enumerate(header):
                if cell in own:
                    return index
        return 0

    def _header_names(self, i: int, tokens: list[str]) -> bool:
        """Whether the header of the table after unit ``i`` names the key's word."""
        units = self.manual.units
        k = i + 1
        if k >= len(units) or not units[k].cells:
            return False
        header = units[k].header or units[k].cells
        tw = {w[:5] for t in tokens for w in words(t.replace("_", " ")) if len(w) >= 3}
        if any(t in self.labels for t in tokens):
            tw |= {w[:5] for t in tokens if t in self.labels for w in words(self.labels[t].text)}
        return any(w[:5] in tw for cell in header for w in words(cell) if len(w) >= 3)

    _table_at: int | None = None

    def _table_column(self, tokens: list[str]) -> list[str] | None:
        """The first column of a table headed by the control's own word (a programme table)."""
        tw = {w for t in tokens for w in words(t.replace("_", " ")) if len(w) >= 4}
        tw |= {
            w for t in tokens if t in self.labels for w in words(self.labels[t].text) if len(w) >= 4
        }
        if not tw:
            return None
        units = self.manual.units
        for i, unit in enumerate(units):
            if unit.cells and not unit.header:  # a header row
                hw = words(unit.cells[0])
                if hw and any(h[:6] == w[:6] for h in hw for w in tw):
                    column = _next_table_column(units, i - 1)
                    if column:
                        self._table_at = i
                        return column
        return None

    def _initial_from_values(self, ev: Evidence, tokens: list[str]) -> None:
        if ev.initial is not None or not ev.values:
            return
        for i in self.context(tokens):
            m = re.search(
                r"\b(?:starts?|default|factory|initially|normally)\b(.*)",
                self.manual.units[i].text,
                re.I,
            )
            if m:
                for v in ev.values:
                    if re.search(rf"\b{re.escape(v)}\b", m.group(1), re.I):
                        ev.initial, ev.initial_at = v, i
                        return

    # --- variables --------------------------------------------------------------------------

    def unique(self, name: str, taken: dict[str, Any]) -> str:
        base = re.sub(r"[^a-z0-9_]+", "_", name.lower()).strip("_") or "setting"
        if not base[0].isalpha():
            base = "v_" + base
        out, k = base, 2
        while out in taken:
            out, k = f"{base}_{k}", k + 1
        return out

    def add_discrete(self, name: str, values: list[str], label: str, ev: Evidence | None) -> str:
        name = self.unique(name, self.variables)
        values = _dedupe([_value_text(v) for v in values if _value_text(v)])
        own = re.fullmatch(r"(.*?)\s+([A-Z0-9]{1,6}(?:/[A-Z0-9]{1,6})+)", label)
        if own and [p.lower() for p in own.group(2).split("/")] == values:
            label = own.group(1)  # the display names the setting, not the printed choices
        spec: dict[str, Any] = {"type": "discrete", "values": values, "label": label}
        if ev is not None and ev.initial in values:
            spec["initial"] = ev.initial
            self.note(f"variables.{name}.initial", f"starts at {ev.initial}", ev.initial_at)
        self.variables[name] = spec
        return name

    def add_toggle(self, name: str, label: str, at: int | None, first: str = "off") -> str:
        name = self.unique(name, self.variables)
        self.variables[name] = {
            "type": "discrete",
            "values": ["off", "on"] if first == "off" else ["on", "off"],
            "label": label,
        }
        self.note(f"variables.{name}", "an on/off setting", at)
        lamp = self.lamp_unit(label)
        if lamp is not None:  # only a lamp the manual names: a wrong lamp misleads the reading
            self.indicators.append(name)
            self.note(f"display.indicators.{name}", "a lamp shows it", lamp)
        return name

    def lamp_unit(self, label: str) -> int | None:
        """A sentence saying the label lights up on the panel (a lamp, symbol or indicator)."""
        if not label:
            return None
        pattern = re.compile(rf"(?<![A-Za-z0-9]){re.escape(label)}(?![A-Za-z0-9])")
        cue = re.compile(
            r"\b(?:display|screen|appears?|shows?|shown)\b",  # text on the display, not a lamp
            re.IGNORECASE,
        )
        for i, unit in enumerate(self.manual.units):
            if pattern.search(unit.text) and cue.search(unit.text):
                return i
        return None

    def add_number(self, name: str, label: str, ev: Evidence, cyclic: bool) -> str:
        """A numeric or time variable from the ranges and steps read (guessed where absent)."""
        if set(words(name.replace("_", " "))) & CHOICE_WORDS:  # a programme is not an amount
            ev = Evidence(**{**ev.__dict__, "ranges": [r for r in ev.ranges if not r.unit]})
        if not ev.ranges and set(words(name.replace("_", " "))) & CHOICE_WORDS:
            # a programme/mode selector the manual lists no values for: a few placeholder
            # choices the loop replaces with what the display shows (a number would stop it)
            var = self.add_discrete(name, ["1", "2", "3", "4", "5"], label, None)
            self.note(f"variables.{var}.values", "placeholders: the manual lists no choices")
            return var
        name = self.unique(name, self.variables)
        subject = f"variables.{name}"
        ranges = list(ev.ranges)
        clock = "clock" in words(name.replace("_", " "))
        if clock and any(r.unit not in ("s", "h") for r in ranges):
            ranges = []  # a clock's range is the day, whatever numbers stand nearby
        if ranges:
            shown = ", ".join(f"{r.low:g}–{r.high:g}" for r in ranges)
            self.note(subject, f"range {shown} {ranges[0].unit}", ev.range_at)
        elif clock:
            twelve = any(
                re.search(r"\b12[- ]?h(?:ou)?r|\bAM\b|\bPM\b", u.text) for u in self.manual.units
            )
            low, high = (3600, 12 * 3600 + 59 * 60) if twelve else (0, 23 * 3600 + 59 * 60)
            self.note(subject, "a clock: the time of day (its range is the clock's, not read)")
            ranges = [Range(low, high, "s", 60)]
        elif (found := self._range_anywhere(name, label)) is not None:
            ranges = [found[0]]
            r0 = found[0]
            self.note(
                subject, f"range {r0.low:g}–{r0.high:g} {r0.unit} (named elsewhere)", found[1]
            )
        elif ev.longest is not None:
            ranges = [ev.longest[0]]
            r0 = ev.longest[0]
            self.note(
                subject, f"range {r0.low:g}–{r0.high:g} {r0.unit} (its longest)", ev.longest[1]
            )
        else:
            unit = ev.step[1] if ev.step else _unit_from_words(name)
            low, high = {"": (0, 10), "h": (0, 12), "min": (1, 60), "°C": (30, 100)}.get(
                unit, (0, 100)
            )
            self.note(subject, f"range {low:g}–{high:g} {unit} (the manual gives none)")
            ranges = [Range(low, high, unit)]
        unit = ranges[0].unit or (ev.step[1] if ev.step else "") or _unit_from_words(name)
        finer = bool(ev.step and ev.step[1] in ("s", "min") and unit == "h")  # 0–3 h by 1 min
        as_time = ranges[0].unit == "s" or unit in ("s", "min") or finer
        factor = 1 if ranges[0].unit == "s" else seconds(1, unit) if as_time else 1

        def base_step(r: Range) -> float | None:
            """The step in the variable's base unit (seconds for a time)."""
            if r.step:
                return r.step * factor
            if not ev.step:
                return None
            value, step_unit = ev.step
            if as_time and step_unit in ("s", "min", "h"):
                return float(seconds(value, step_unit))
            if step_unit in ("", unit) or not as_time:
                return value * factor
            return None

        pieces: list[list[float]] = []
        for index, r in enumerate(ranges):
            lo, hi = r.low * factor, r.high * factor
            st = base_step(r)
            if st:
                self.note(
                    f"{subject}.step",
                    f"step {st / factor:g} {unit}",
                    ev.step_at if not r.step else ev.range_at,
                )
            else:
                st = _guess_step(r.high - r.low, unit) * factor
                if as_time and st < 60 and lo % 60 == 0 and hi % 60 == 0 and hi - lo >= 600:
                    st = 60.0  # a clock-written range ("0:20 – 1:30") steps in minutes
                self.note(f"{subject}.step", f"step {st / factor:g} {unit} (the manual gives none)")
            if as_time:
                st = max(1.0, float(round(st)))
            if pieces:
                lo = max(lo, pieces[-1][1])
            count = int((hi - lo) / st + 1e-9)
            if count > 5000:
                st = (hi - lo) / 5000 if not as_time else float(-(-(hi - lo) // 5000))
                count = int((hi - lo) / st + 1e-9)
            hi = lo + count * st
            if hi <= lo:
                if index:
                    continue
                hi = lo + st
            pieces.append([lo, hi, st])
        spec: dict[str, Any]
        if as_time:
            spec = {
                "type": "time",
                "ranges": [[_hms(int(lo)), _hms(int(hi)), int(st)] for lo, hi, st in pieces],
                "format": "h:mm"
                if pieces[-1][1] >= 3600 and all(p[2] % 60 == 0 for p in pieces)
                else "mm:ss",
                "label": label,
            }
        else:
            spec = {
                "type": "numeric",
                "ranges": [[_tidy(lo), _tidy(hi), _tidy(st)] for lo, hi, st in pieces],
                "unit": unit,
                "label": label,
            }
            if ev.initial and isinstance(ev.initial, tuple):
                value = ev.initial[0]
                for lo, hi, st in pieces:
                    off = (value - lo) / st
                    if lo <= value <= hi and abs(off - round(off)) < 1e-9:
                        spec["initial"] = _tidy(value)
                        self.note(f"{subject}.initial", f"starts at {value:g}", ev.initial_at)
                        break
        if cyclic:
            spec["wrap"] = True
            self.note(f"{subject}.wrap", "stepping past the end wraps around (each press adds)")
        self.variables[name] = spec
        return name

    def _range_anywhere(self, name: str, label: str) -> tuple[Range, int] | None:
        """The first range in a sentence or table row naming the setting anywhere (a
        specifications table: "| Set temperature range | 40–100 °C |", a programme table's
        time column), its unit fitting the setting; advice ("suggested") is not a limit."""
        ws = {w for w in words(name.replace("_", " ")) + words(label) if len(w) >= 4}
        if not ws or not _quantity_unit(name):
            return None
        if label and label.upper() == label and ws & (_TIMER_WORDS | {"time"}):
            # what the key's own sentences call its time ("TIMER  Push to set the Delay
            # Start timer"): a specification may name only that ("Delay start: up to 15 h")
            ws |= {
                w
                for u in self.manual.units
                if re.search(rf"\b{re.escape(label)}\b", u.text)
                for w in words(u.text)
                if w in _TIMER_WORDS
            }
        advice = {"suggested", "recommended", "typical", "advised", "usual", "ideal"}
        limits = re.compile(r"\brange\b|\badjustable\b|\bcan be set\b|\bsettable\b|\bbetween\b")
        best: tuple[int, Range, int] | None = None

        def consider(score: int, text: str, i: int) -> None:
            nonlocal best
            for r in find_ranges(text):
                if r.unit and _fits(r.unit, [name]) and r.high > r.low:
                    if best is None or score > best[0]:
                        best = (score, r, i)
                    return

        for i, unit in enumerate(self.manual.units):
            uw = words(unit.text)
            if unit.cells and unit.header and len(unit.header) == len(unit.cells):
                # a table row: the setting is named by the column's header
                for head, cell in zip(unit.header, unit.cells, strict=True):
                    hw = words(head)
                    if set(hw) & advice or not any(h[:5] == w[:5] for h in hw for w in ws):
                        continue
                    consider(1 + 2 * bool(limits.search(head)), cell, i)
                first = words(unit.cells[0])
                if any(u[:5] == w[:5] for u in first for w in ws) and not set(first) & advice:
                    consider(1 + 2 * bool(limits.search(unit.cells[0])), unit.text, i)
                continue
            if not any(u[:5] == w[:5] for u in uw for w in ws) or set(uw) & advice:
                continue
            if "clock" in uw and "clock" not in ws:
                continue  # "any time from 1:00 to 12:59": the clock's day, not a duration
            consider(2 * bool(limits.search(unit.text)), unit.text, i)
        return (best[1], best[2]) if best else None

    # --- the whole model --------------------------------------------------------------------

    def feature(self, name: str, steps: list[dict[str, Any]]) -> None:
        self.features[self.unique(name, self.features)] = steps


_TIMER_WORDS = frozenset({"timer", "delay", "preset", "reserve", "finish"})


def _all_names(items: list[str], text: str) -> bool:
    """Five or more short names that make up the whole line."""
    covered = sum(len(v) for v in items)
    return len(items) >= 5 and max(map(len, items)) <= 24 and covered >= 0.7 * len(text)


def _keyish(items: list[str], others: set[str], own: set[str]) -> bool:
    """A list naming two or more keys (other keys, the key itself, symbols such as + and −)."""
    named = sum(
        v.lower() in others or v.upper() in own or not re.search(r"[^\W_]", v) for v in items
    )
    return named >= 2


def _without(text: str, labels: list[str]) -> str:
    """The text with these key names (printed in capitals) taken out."""
    for label in labels:
        if re.search(r"[A-Z]", label):
            text = text.replace(label, " ")
    return text


_KEYPAD_WORDS = re.compile(r"\b(?:numbers?|numeric|digits?|keypad|numerals?)\b", re.IGNORECASE)


def _cell_key(cell: str) -> str:
    """A table cell as a key's printed name compares (no markup, case or end dots)."""
    return re.sub(r"[*_`]+", "", cell).strip(" .:").upper()


def _keypad(r: Range, text: str) -> bool:
    """ "0 – 9: number keys" (or "keys 0-9", "0–9 buttons") names the keypad, not a setting's
    range."""
    if r.unit or r.low != 0 or r.high != 9:
        return False
    return bool(
        _KEYPAD_WORDS.search(text)
        or re.search(r"\b(?:keys|buttons|pads)\s+0\s*(?:-|–|—|to)\s*9\b", text, re.I)
        or re.search(r"\b0\s*(?:-|–|—|to)\s*9\s+(?:keys|buttons|pads)\b", text, re.I)
    )


def _numeric_items(items: list[str]) -> bool:
    """Every item is a number, perhaps with a short unit ("40", "35 %", "2h")."""
    return bool(items) and all(
        re.fullmatch(r"\s*\d+(?:[.,]\d+)?\s*(?:[^\s\d]{0,4}|[A-Za-z]{1,8})\s*", i) for i in items
    )


def _row_step(cells: tuple[str, ...], unit: str) -> float | None:
    """A table row's step: a cell that is one quantity ("half an hour", "5 min", "1 h")."""
    from apbot.model.values import parse_quantity

    for cell in cells[1:]:
        if find_ranges(cell):
            continue
        step = find_step(cell)
        if step:
            return step[0]
        q = parse_quantity(cell.strip().lower().replace("an hour", "1 hour"))
        if q and q[1] == "time" and q[0] > 0:
            base = {"s": 1, "min": 60, "h": 3600}.get(unit, 0)
            return q[0] / base if base else None
    return None


RUN_RE = re.compile(r"\d+(?:[.,]\d+)?(?:\s*[·•]\s*(?:\|\s*)?\d+(?:[.,]\d+)?){2,}")
ASIDE_HEADING = re.compile(
    r"\b(?:safety|safeguards?|warnings?|cautions?|precautions?|trouble-?\s?shooting|faults?"
    r"|fault finding|problems?|error codes?|cleaning|care|maintenance|warranty|guarantee"
    r"|disposal|customer)\b",
    re.IGNORECASE,
)
EXAMPLE_RE = re.compile(r"^\s*(?:examples?|e\.\s?g\.|for (?:example|instance))\b", re.IGNORECASE)


ADVICE_WORDS = frozenset({"suggested", "recommended", "typical", "advised", "usual", "ideal"})


def _without_advice(unit: Unit) -> str:
    """A unit's text without the cells of columns headed as advice ("Suggested °C": what suits
    a food, not the limits of the setting)."""
    if not unit.cells or len(unit.header) != len(unit.cells):
        return unit.text
    return " | ".join(
        cell
        for head, cell in zip(unit.header, unit.cells, strict=True)
        if not set(words(head)) & ADVICE_WORDS
    )


def _same_word(a: str, b: str) -> bool:
    """The same word, or one word inflected ("timer"/"timers", "programme"/"programmes",
    "temperature"/"temp"), not merely sharing a start ("cook"/"cookware")."""
    short, long = sorted((a, b), key=len)
    if long.startswith(short[:6]) and len(short) >= 6:
        return True
    rest = long[len(short) :] if long.startswith(short) else None
    abbreviation = short in ("temp", "prog", "func", "prep")
    return rest is not None and (rest in ("", "s", "es", "ing", "ed", "er", "ers") or abbreviation)


def _header_row(units: list[Unit], i: int) -> bool:
    """A table's header row (rows follow under it): the names of its columns, not values."""
    unit = units[i]
    return (
        bool(unit.cells)
        and not unit.header
        and i + 1 < len(units)
        and units[i + 1].header == unit.cells
        and sum(c.upper() == c for c in unit.cells) < len(unit.cells)  # not a row of key names
        and all(len(c) <= 24 for c in unit.cells)  # not two columns of prose side by side
    )


def _aside(units: list[Unit], i: int) -> bool:
    """A unit that names values in passing, never a setting's list of them: a worked example
    ("Example: it is 9 pm. You choose BASIC, 2.0 LB."), or a sentence under a safety,
    troubleshooting, care or warranty heading ("Select UV, DRY or STORE" as a remedy). Ranges
    are still read there."""
    unit = units[i]
    if EXAMPLE_RE.match(unit.text):
        return True
    before = units[i - 1] if i else None
    if (
        before is not None
        and EXAMPLE_RE.match(before.text)
        and not unit.bullet
        and not unit.cells
        and unit.line - before.line <= 1
    ):
        return True  # the example's next sentence
    return bool(unit.heading) and bool(ASIDE_HEADING.search(unit.heading))


def _fits(unit: str, tokens: list[str]) -> bool:
    """A range's unit can belong to the control: no minutes for a temperature, no degrees for a
    timer, no watts for a volume (the sentence after a key often gives a neighbouring
    setting's range)."""
    expected = {_quantity_unit(t) for t in tokens} - {""}
    if not expected or not unit:
        return True
    timeish = {"s", "min", "h"}
    if expected & {"°C"}:
        return unit in ("°C", "°F", "")
    if expected & {"min"}:
        return unit in timeish
    if expected & {"%"}:
        return unit == "%"
    for canonical, family in QUANTITY_FAMILIES.items():
        if canonical in expected:
            return unit in family
    return True


def _next_table_column(units: list[Unit], i: int, column: int = 0) -> list[str]:
    """The cells of one column (the first by default) of the table that starts right after
    unit ``i`` (header skipped)."""
    k = i + 1
    if k < len(units) and units[k].cells and not units[k].header:
        k += 1  # the header row
    items: list[str] = []
    numbers = 0
    while k < len(units) and units[k].cells and units[k].header:
        if column >= len(units[k].cells):
            k += 1
            continue
        cell = re.sub(r"^\s*\d{1,2}[.)]?\s+(?=\D)", "", units[k].cells[column]).strip(" *")
        if find_ranges(cell) or not re.search(r"[A-Za-z]", cell):
            numbers += 1
        if cell and len(cell) <= 24 and cell not in items:
            items.append(cell)
        k += 1
    if numbers * 2 > len(items):
        return []  # a column of ranges or bare numbers is not a list of names
    return items if len(items) >= 2 else []


FRACTIONS = {"½": ".5", "¼": ".25", "¾": ".75"}


def _quantity_column(units: list[Unit], i: int) -> list[str]:
    """A table column of durations after unit ``i`` ("| `60` | 1 hour |"), as minutes; a cell
    saying there is none ("no hold", "off", "--") is 0. Empty unless most cells are durations."""
    from apbot.model.values import parse_quantity

    rows: list[tuple[str, ...]] = []
    k = i + 1
    if k < len(units) and units[k].cells and not units[k].header:
        k += 1
    while k < len(units) and units[k].cells and units[k].header:
        rows.append(units[k].cells)
        k += 1
    if len(rows) < 3:
        return []
    width = min(len(r) for r in rows)
    for column in range(width - 1, -1, -1):
        items: list[str] = []
        for row in rows:
            cell = row[column].strip(" *`").lower()
            for frac, dec in FRACTIONS.items():
                cell = re.sub(rf"(\d)\s*{frac}", rf"\g<1>{dec}", cell).replace(frac, "0" + dec)
            q = parse_quantity(re.sub(r"\(.*?\)", "", cell).strip())
            if q and q[1] == "time":
                items.append(f"{q[0] / 60:g} min")
            elif re.match(r"^(?:no\b|none|off\b|-+$|–|—)", cell):
                items.append("0 min")
            else:
                break
        else:
            if sum(i != "0 min" for i in items) >= 2:
                return _dedupe(items)
    return []


def _bullet_items(units: list[Unit], i: int, lead: int = 0) -> list[str]:
    """The terms of the bullets after unit ``i`` ("- AUTO — dries until…"); a bullet may run
    to more sentences, and ``lead`` sentences may stand between ``i`` and the first bullet."""
    items: list[str] = []
    k = i + 1
    while lead and k < len(units) and not units[k].bullet and k <= i + lead:
        k += 1
    gap = 0
    while k < len(units) and len(items) < 16:
        u = units[k]
        k += 1
        if not u.bullet:
            if not items or u.heading != units[i].heading or gap >= 3 or u.cells:
                break
            gap += 1  # another sentence of the same bullet
            continue
        gap = 0
        m = re.match(r"^([A-Z0-9][A-Za-z0-9 +/&'-]{0,22}?)\s*(?::|—|–|-|=)\s", u.text)
        if not m:
            break
        items.append(m.group(1).strip())
    return items if len(items) >= 2 else []


def _dedupe(items: list[str]) -> list[str]:
    out: list[str] = []
    for item in items:
        if item not in out:
            out.append(item)
    return out


def _value_text(value: str) -> str:
    text = re.sub(r"\s+", " ", value.strip().lower())
    return text.strip(" .,;:")


def _unit_from_words(name: str) -> str:
    ws = set(words(name.replace("_", " ")))
    if ws & {"temp", "temperature", "heat"}:
        return "°C"
    if ws & {"humidity", "percent"}:
        return "%"
    if ws & {"time", "timer", "delay", "duration", "cook"}:
        return "min"
    return ""


QUANTITY_FAMILIES = {  # a setting named for a quantity takes a range in one of its units
    "ml": frozenset({"ml", "l", "cl", "dl", "cups", "cup"}),
    "g": frozenset({"g", "kg", "lb", "lbs"}),
    "W": frozenset({"W", "kw"}),
    "rpm": frozenset({"rpm"}),
}
QUANTITY_WORDS = {
    "volume": "ml", "amount": "ml", "capacity": "ml", "water": "ml", "weight": "g",
    "watt": "W", "watts": "W", "wattage": "W", "output": "W", "spin": "rpm", "rpm": "rpm",
}  # fmt: skip


def _quantity_unit(name: str) -> str:
    """:func:`_unit_from_words`, and for a quantity its unit (volume → ml, weight → g, watts →
    W, spin → rpm): a range must be in that unit's family to belong to the setting."""
    unit = _unit_from_words(name)
    if unit:
        return unit
    for w in words(name.replace("_", " ")):
        if w in QUANTITY_WORDS:
            return QUANTITY_WORDS[w]
    return ""


def _guess_step(span: float, unit: str) -> float:
    if unit == "%":
        return 5
    if unit in ("°C", "°F"):
        return 5 if span > 40 else 1
    if unit in ("min", "s", "h"):
        return 1
    for step in (1, 5, 10, 50, 100, 500, 1000):
        if span / step <= 40:
            return step
    return max(1.0, span / 40)


def _tidy(x: float) -> float | int:
    return int(x) if float(x).is_integer() else round(float(x), 4)


def _hms(total: int) -> str:
    return f"{total // 3600:02d}:{total % 3600 // 60:02d}:{total % 60:02d}"


def adjuster_direction(info: ActionInfo) -> tuple[str, str] | None:
    """(base, "up"|"down") for a stepping key: ``temp_up`` → (temp, up), ``minus`` → ("", down)."""
    if info.skill != "press" or info.digit is not None:
        return None
    parts = info.token.split("_")
    for i, part in enumerate(parts):
        core = re.sub(r"\d+$", "", part)
        suffix = part[len(core) :]
        if core in UP_WORDS or core in DOWN_WORDS:
            base = "_".join(parts[:i] + parts[i + 1 :]) + suffix
            if core == "add" and (base or not suffix):
                continue  # add30, add_in: not a stepping key
            return base, "up" if core in UP_WORDS else "down"
    return None
