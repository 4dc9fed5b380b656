"""Where a control's values are written: its context (the units naming it and what follows),
and the lists, legends, table columns and runs of numbers in them, each with a priority. Which
table column holds the values is in evidence_tables.py; the context itself (which units are about
the control) and the start said among its values are in evidence_context.py."""

from __future__ import annotations

import itertools
import re

from apbot.model.values import NUMBER_WORDS
from apbot.read.evidence_context import ContextReader
from apbot.read.labels import words
from apbot.read.list_lines import wrapped_list
from apbot.read.model_columns import compares_models
from apbot.read.noun_columns import noun_column
from apbot.read.number_runs import find_number_run
from apbot.read.quantity_units import QUANTITY_FAMILIES, _quantity_units
from apbot.read.shapes import (
    ORDER_RE,
    RUN_RE,
    TABLE_POINTER_RE,
    _all_names,
    _aside,
)
from apbot.read.shapes_columns import (
    PRESSES_RE,
    _bullet_items,
    _next_table_column,
    _quantity_column,
)
from apbot.read.step_rows import step_size_row
from apbot.read.text import Unit
from apbot.read.value_gaps import find_progression
from apbot.read.value_lists import (
    bare_list,
    caps_run,
    cell_list,
    find_list,
    quantity_run,
)
from apbot.read.value_runs_back import wrapped_run
from apbot.read.values import number

_TYPING_WORDS = frozenset({"type", "typed", "typing", "digits", "keystrokes", "keyed"})
_KEY_WORDS = frozenset({"key", "keys", "button", "buttons", "number", "numbers"})
_PRESS_WORDS = frozenset({"press", "pressed", "touch", "touched", "enter", "entered", "input"})


_COUNTED_RE = re.compile(  # "has seven positions", "with 12 settings" (read by ``number``)
    r"\b(?:has|have|with)\s+(\d{1,2}|"
    + "|".join(w for w, n in NUMBER_WORDS.items() if n < 20 and w not in ("a", "an", "single"))
    + r")\s+(?:positions|settings|marks|stops|detents|steps)\b",
    re.I,
)


def _keyed_examples(units: list[Unit], i: int) -> bool:
    """The table after unit ``i`` shows what to type for some values ("| You type | Display |
    Cooking time |"): examples of entering a value on the keypad, not the values there are."""
    k = i + 1
    if k >= len(units) or not units[k].cells:
        return False
    header = units[k].header or units[k].cells
    return any(
        set(words(cell)) & _TYPING_WORDS
        or (set(words(cell)) & _KEY_WORDS and set(words(cell)) & _PRESS_WORDS)  # "Keys pressed"
        for cell in header
    )


# a legend item's own marker ("[A] Status line: …", "(B) Timer lamp", "Ⓒ Field"): items of a
# display's legend run together in one paragraph, each about its own part of the panel
_LEGEND_MARK = re.compile(r"(?:^|\s)(?:\[[A-Z0-9]{1,2}\]|\([A-Z]\)|[Ⓐ-Ⓩ①-⑳])\s")


def own_legend_items(text: str, labels: list[str]) -> str:
    """Of a paragraph of legend items ("[A] Status line: READY, ARMED … [B] Bell symbol CHIME:
    the chime is on."), only the items that name the key: the list in [A] is not CHIME's."""
    marks = list(_LEGEND_MARK.finditer(text))
    if len(marks) < 2:
        return text
    cuts = [m.start() for m in marks] + [len(text)]
    items = [text[a:b] for a, b in itertools.pairwise(cuts)]
    named = [
        item
        for item in items
        if any(re.search(rf"(?<!\w){re.escape(lab)}(?!\w)", item) for lab in labels if lab)
    ]
    return " ".join(named) if named else text


class ListReader(ContextReader):
    """The manual's units about the controls, and the value lists they hold."""

    def _unit_runs(self, tokens: list[str]) -> tuple[list[float], int] | None:
        """For a quantity (watts, volume, weight, spin) of which nothing else is read: the
        numbers a table headed by its unit lists in runs joined by middle dots ("Output
        settings (W) … 500 · 600 · 700 … 1500 100 W Medium 1600 · 1700 …"), all runs of that
        table together, in order."""
        unit = next((u for u in _quantity_units(tokens) if u in QUANTITY_FAMILIES), "")
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
        if step_size_row(unit):
            return []  # "| Wheel increments | 5 / 10 / 25 µL |": the steps' sizes, no values
        text = self._own_model_row(unit)
        if mention:
            text = own_legend_items(text, [self.labels[t].text for t in tokens if t in self.labels])
        out: list[tuple[list[str], float]] = []
        found = find_list(text)
        if found and found[1] == "arrows" and mention and self._arrows_of_another(text, tokens):
            found = None  # "COLOUR x2 · TIMER x4 (30 → 45 → 60)": TIMER's steps, not COLOUR's
        if found:
            out.append((found[0], 3.0 if found[1] == "arrows" else 2.0 if mention else 1.0))
        else:
            own = {self.labels[t].text.upper() for t in tokens if t in self.labels}
            keys = {lab.text.upper() for lab in self.labels.values() if lab.text}
            span = self._own_span(text, tokens) if mention else text
            run = caps_run(span, own | keys)
            if text == unit.heading:
                run = None  # "CALL TONES, ROGER BEEP, HANDS-FREE": a heading lists topics
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
        if (
            text.rstrip().endswith(":")
            and i + 1 < len(units)
            and _lone_line(units, i + 1)
            and (mention or not self._about_another(text, tokens))
        ):
            after = wrapped_list(self.manual, i + 1)  # "Printed round the knob:", the marks
            # a long line is a list only when it is all short names ("OFF · Cottons · Eco …")
            if after and (len(units[i + 1].text) <= 120 or _all_names(after, units[i + 1].text)):
                out.append((after, 2.6))
        said = {m for t in tokens if t in self.labels for m in self.labels[t].mentions}
        progression = find_progression(text)
        named = re.search(r"\b([A-Z]{2,12}) \d+(?:\.\d+)?,\s*\1 \d", text)
        own_labels = {self.labels[t].text.upper() for t in tokens if t in self.labels}
        if named and not any(lab.split()[:1] == [named.group(1)] for lab in own_labels):
            progression = None  # "MENU 1, MENU 2 … MENU 15" lists MENU's codes, not this key's
        if progression and len(progression) >= 3:  # "one click each, 50, 55, 60 ... 95, 100"
            near = mention or i - 1 in said  # (in the key's sentence or the one after it)
            out.append((progression, 2.7 if near else 2.3))  # (beats the printed marks)
        back = wrapped_run(text) if mention or {i - 1, i - 2} & said else None
        if back:  # "each press adds one: 5, 6, 7, 8, 9, then back to 3"
            out.append((back, 2.7))
        counted = _COUNTED_RE.search(text)
        n = number(counted.group(1)) if counted and mention else None
        if n:  # "The knob has seven positions." and the row of them drawn ("zero": no list)
            for k in range(i + 1, min(i + 3, len(units))):
                after = None if units[k].cells else bare_list(units[k].text)
                if after and len(after) == n:
                    out.append((after, 2.6))
                    break
        through = noun_column(units, i) if mention else None
        if through:  # "Press VOX to step through the levels" and the table's Level column
            out.append((through, 2.5))
        pointer = (mention or i - 1 in said) and TABLE_POINTER_RE.search(text)  # (its paragraph)
        if (ORDER_RE.search(text) or pointer) and not text.rstrip().endswith((":", "order")):
            # "arranged round the knob in this order, clockwise." and the table a line or two on
            for k in range(i + 1, min(i + 7, len(units))):
                if units[k].heading != unit.heading:
                    break
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
            if (
                _keyed_examples(units, i)
                or self._guide_of_others(i, tokens)
                or (index == 0 and i + 1 < len(units) and compares_models(units[i + 1].cells))
            ):
                column = []  # "| You type | Display | Cooking time |": worked examples; a
                # guide's rows ("| Knife | Angle |"): knives, each with the angle advised; a
                # comparison's ("| | RK-30 | RK-50 |"): what the models differ in
            if not column and text == unit.heading:
                column = self._counted_chart(i)
            if column:
                # a heading that only shares a word with the key ("Recipe: basic white loaf"
                # for LOAF) introduces a table about something else unless its header says so
                related = mention or text != unit.heading or self._header_names(i, tokens)
                out.append((column, 2.5 if related else 1.2))
        return out

    def _counted_chart(self, i: int) -> list[str]:
        """Under the key's own heading ("AUTO COOK CHART"), a sentence or two on, a table whose
        first column counts the touches ("Touches | Menu | Quantity"): its next column is what
        each touch selects."""
        units = self.manual.units
        for k in range(i + 1, min(i + 5, len(units))):
            if units[k].heading != units[i].heading:
                break
            if units[k].cells:
                if not units[k].header and PRESSES_RE.match(units[k].cells[0]):
                    return _next_table_column(units, k - 1)
                break
        return []

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

    def _key_named(self, unit: Unit | None, tokens: list[str]) -> bool:
        """Whether the sentence prints the key's own name."""
        labels = [self.labels[t].text for t in tokens if t in self.labels and self.labels[t].text]
        return unit is not None and any(
            re.search(rf"(?<!\w){re.escape(label)}(?!\w)", unit.text) for label in labels
        )

    def _led_list(
        self, unit: Unit, tokens: list[str], before: Unit | None = None
    ) -> list[str] | None:
        """A list after a colon in a sentence that starts by naming the setting ("Drying-time
        settings available: …" for DRY TIME, "Timer steps: …" for TIMER), or in the next cell
        of a table row that does (a specifications table: "| Water levels | 22, 26 … 58 L |")."""
        if len(unit.cells) >= 2:
            if not self._names_setting(words(unit.cells[0]), tokens) or step_size_row(unit):
                return None  # ("| Wheel increments | 5 / 10 / 25 µL |": steps, no values)
            cells = self._own_model_row(unit).split(" | ")[1:]
            for cell in cells:  # "| SIZE | Loaf size | 1.0 LB, 1.5 LB, 2.0 LB |"
                items = cell_list(cell)
                if items and len(items) >= 3:
                    return items
            return None
        m = re.match(r"\s*([^:.;]{3,50}):(?!\d)\s*(.+)", unit.text)  # ("TIMER 0:10": a time)
        if not m:
            return None
        # "FREQ: selects how often to water. Options are: daily, …": choices said right after
        # the sentence naming the key, in the same line, are that key's
        generic = bool(_CHOICES_LEAD.fullmatch(m.group(1).strip())) and self._key_named(
            before, tokens
        )
        if not generic and not self._names_setting(words(m.group(1)), tokens):
            return None
        found = find_list(unit.text)
        items = found[0] if found else bare_list(m.group(2))
        return items if items and len(items) >= 3 else None


# a lead naming no setting, only that choices follow: "Options are:", "The choices are:"
_CHOICES_LEAD = re.compile(
    r"(?:the\s+)?(?:available\s+)?(?:options|choices|settings|positions)(?:\s+(?:are|available))?",
    re.I,
)


def _lone_line(units: list[Unit], k: int) -> bool:
    """Unit ``k`` stands alone: no table, or a table of that one row ("The marks round the
    knob:" then "WARM | BAKE | BROIL | TOAST"), which is a row of names, not a header."""
    if not units[k].cells:
        return True
    return not units[k].header and (k + 1 == len(units) or units[k + 1].header != units[k].cells)
