"""Which table holds a key's values, and which of its columns: the column under the key's
printed name in a row of key names, a programme table headed by the key's own word, a numbered
chart's programme column (never a legend of the panel's keys). Tables read as columns are their
own job, apart from the lists read in sentences (evidence_lists.py).
"""

from __future__ import annotations

import re

from apbot.read.drawn_pieces import drawn_piece_marks
from apbot.read.labels import Label, words
from apbot.read.shapes import CHOICE_WORDS, GROUP_NOUNS
from apbot.read.shapes_columns import _DISPLAY_HEAD_RE, _drawn_column, _next_table_column
from apbot.read.table_transposed import key_row_marks, sideways_choices
from apbot.read.text import Manual
from apbot.read.text_pages import OPEN_ENDS

# the head of a chart's first column numbering its rows ("No.", "Nr.", "#", "Prog. no.")
_NUMBER_HEAD_RE = re.compile(r"^\W*(?:(?:prog\w*\.?\s*)?(?:no|nr|n°|number)\.?|#)\W*$", re.I)
# the head of a first column listing a key's own steps ("| Level | Power | Suitable for |"):
# its rows are the key's values, each with what it gives, not things the setting is advised for
_LEVEL_HEAD_RE = re.compile(r"^\W*(?:levels?|settings?|positions?)\W*$", re.I)
_BRACKET_RE = re.compile(r"\s*\([^()]*\)\s*$")


class TableReader:
    """The tables after a unit naming a key, and a programme table's column of names."""

    manual: Manual
    labels: dict[str, Label]

    def _own_column(self, i: int, tokens: list[str]) -> int:
        """Which column of the table after unit ``i`` is the key's: one headed by the key's
        printed name when the header is a row of key names ("| TEMP. | SPIN | SOIL |") or
        another key's column leads it, else the first."""
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
        # "| Pouch | Document | Mode | Speed |" under "POUCH AND SPEED GUIDE": a table led by
        # another key's column (POUCH +/−), SPEED's column is the one its name heads
        named = [index for index, cell in enumerate(header) if cell in own]
        led = bool(
            set(words(header[0])) & (self._other_keys_words(tokens) - set(words(" ".join(own))))
        )
        return named[0] if named and led else 0

    def _guide_of_others(self, i: int, tokens: list[str]) -> bool:
        """Whether the table after unit ``i`` is a guide of other things: its header names the
        key in a later column only ("| Knife | Angle | Stages |" under "ANGLE AND STAGE
        GUIDE"), so each row is a knife, a food or a situation with the setting advised for
        it, and its first column holds no value of the key (a column numbering the rows, or
        printing each value as the display shows it, or headed "Level" or "Setting" as a list of
        the key's own steps, is left to the chart readers)."""
        units = self.manual.units
        k = i + 1
        if k >= len(units) or not units[k].cells or units[k].header:
            return False
        # ("| Bit | Task | Speed (display) |": a head's bracket says how the value is printed)
        header = [_BRACKET_RE.sub("", c).strip(" *.").upper() for c in units[k].cells]
        own = {self.labels[t].text.strip(" .").upper() for t in tokens if t in self.labels}
        lead = header[0]
        if (
            len(header) < 3
            or lead in own
            or _NUMBER_HEAD_RE.match(lead)
            or _LEVEL_HEAD_RE.match(lead)
            or _DISPLAY_HEAD_RE.match(lead)
            or _drawn_column(units, k + 1)  # "| Lamps | Colour |": lamps drawn, not a thing
        ):
            return False  # ("| Display | Mode |": each mode as shown, then what it does)
        return any(cell in own for cell in header[1:]) and self._own_column(i, tokens) == 0

    def _other_keys_words(self, tokens: list[str]) -> set[str]:
        """The words naming the panel's other keys (a table or a sentence they lead is theirs)."""
        return {w for t in self.labels if t not in tokens for w in words(t.replace("_", " "))}

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

    def _table_column(self, tokens: list[str], numbered: bool = True) -> list[str] | None:
        """The first column of a table headed by the control's own word (a programme table);
        with ``numbered``, also a numbered chart's programme column."""
        tw = {w for t in tokens for w in words(t.replace("_", " ")) if len(w) >= 4}
        tw |= {
            w for t in tokens if t in self.labels for w in words(self.labels[t].text) if len(w) >= 4
        }
        names = {" ".join(words(self.labels[t].text)) for t in tokens if t in self.labels}
        names.discard("")
        if not tw and not names:
            return None
        units = self.manual.units
        choice = bool(tw & CHOICE_WORDS)
        others = {" ".join(words(lab.text)) for t, lab in self.labels.items() if t not in tokens}
        for i, unit in enumerate(units):
            drawn = None if unit.cells else drawn_piece_marks(unit.text, tw, names, others)
            if drawn:  # "( ON/OFF ) | HEAT  COOL  WARM | SPEED": the key's place on the panel
                self._table_at = i
                return drawn
            below = i + 1 < len(units) and bool(units[i + 1].cells)
            below = below and units[i + 1].header == unit.cells
            marks = key_row_marks(unit.cells, tw, unit.header, below, names)
            if marks:  # "| SHADE | PALE | LIGHT | DARK |": the key's row of its printed marks
                self._table_at = i
                return marks
            if unit.cells and not unit.header:  # a header row
                chart = self._numbered_chart(i, tw, choice) if numbered else None
                if chart:
                    return chart
                if any(re.search(r"\d", c) for c in unit.cells[1:]):
                    continue  # "Power supply | 230 V": a row of data read as a header
                if re.search(r"\d:\d\d", unit.cells[0]):
                    continue  # "12:45   ((•))  ZONE | …": a drawn display showing a time
                hw = words(unit.cells[0])
                if choice and set(hw) & set(GROUP_NOUNS):
                    sideways = sideways_choices(units, i)
                    if sideways:  # "| Programme | Eco | Quick |" for MENU: the programmes
                        self._table_at = i
                        return sideways
                if hw and any(h[:6] == w[:6] for h in hw for w in tw):
                    column = _next_table_column(units, i - 1)
                    if column and self._key_legend([unit.cells[0], *column]):
                        continue  # "[ POPCORN ] [ TIME COOK ]" over "[ CLOCK ]": keys drawn
                    if column:
                        self._table_at = i
                        return column
        return None

    def _numbered_chart(self, i: int, tw: set[str], choice: bool) -> list[str] | None:
        """A chart whose header at unit ``i`` starts with a number column ("| No. | Programme |
        For | Time |", rows "| 1 | BASIC | …"): its second column, when headed by the key's own
        word, or by any programme word for a key that chooses a programme (MENU, PROG)."""
        units = self.manual.units
        cells = units[i].cells
        if len(cells) < 3 or re.search(r"\d", cells[1]):
            return None
        if not _NUMBER_HEAD_RE.match(cells[0]) and not self._counted_rows(i):
            return None
        hw = words(cells[1])
        if not any(h[:6] == w[:6] for h in hw for w in tw) and not (
            choice and set(hw) & set(GROUP_NOUNS)
        ):
            return None
        rows = [u for u in units[i + 1 : i + 4] if u.header == cells]
        if len(rows) < 2 or not all(re.fullmatch(r"\d{1,2}[.)]?", r.cells[0]) for r in rows):
            return None
        column = _next_table_column(units, i - 1, 1)
        if column and self._key_legend(column):
            return None  # "| 1 | MENU | … |", "| 2 | TIMER | … |": a legend of the panel's keys
        if column:
            self._table_at = i
        return column or None

    def _counted_rows(self, i: int) -> bool:
        """Whether the rows of the table headed at unit ``i`` are numbered one by one from 1
        in their first column ("| Knob pos. | Programme |" over "| 1 | … |", "| 2 | … |"): a
        number column whatever its head says; not steps to do, whose cells are sentences
        ("| Step | … |": "Empty the crock", "Turn to position 1")."""
        units = self.manual.units
        rows = [u.cells for u in units[i + 1 :] if u.header == units[i].cells and u.cells]
        firsts = [c[0] for c in rows]
        if len(firsts) < 3 or not all(re.fullmatch(r"\d{1,2}[.)]?", c) for c in firsts):
            return False
        said = [c for c in rows if len(c) > 1 and OPEN_ENDS & {w.lower() for w in c[1].split()}]
        if 2 * len(said) >= len(rows):
            return False
        return [int(c.rstrip(".)")) for c in firsts] == list(range(1, len(firsts) + 1))

    def _key_legend(self, cells: list[str]) -> bool:
        """Whether most cells of a column are the panel's own keys (printed labels or action
        names): a key legend says what each key does, it lists no values of one key."""
        keys = {lab.text.strip(" .").upper() for lab in self.labels.values() if lab.text}
        keys |= {t.upper().replace("_", " ") for t in self.labels}
        hits = sum(c.strip(" *.[]").upper() in keys for c in cells)
        return hits >= 2 and 2 * hits >= len(cells)
