"""A setting's range read anywhere in the manual: a specifications table ("| Set temperature
range | 40–100 °C |"), a programme table's time column, a sentence naming the setting. Apart
from evidence.py (what the sentences about a control say) because it searches the whole manual
by the setting's name, not the control's own context.
"""

from __future__ import annotations

import re

from apbot.read.labels import Label, words
from apbot.read.model_rows import own_model_row
from apbot.read.quantity_units import _quantity_unit
from apbot.read.shapes import _TIMER_WORDS, _fits
from apbot.read.text import Manual
from apbot.read.text_sections import surroundings
from apbot.read.values import Range, find_ranges


class AnywhereReader:
    """Ranges of a setting found by its name anywhere in the manual."""

    manual: Manual
    labels: dict[str, Label]

    def _called_timer(self, label: str) -> bool:
        """The key's legend row or a heading naming it calls it a timer ("| PRESET | Timer:
        hours until the bread is ready |", "## Ready-in timer (PRESET)"): its amount is a time."""
        if not label or label.upper() != label:
            return False
        named = re.compile(rf"\b{re.escape(label)}\b")
        for unit in self.manual.units:
            if named.search(unit.heading) and set(words(unit.heading)) & {"timer", "delay"}:
                return True
            legend = len(unit.cells) >= 2 and unit.cells[0].strip(" *`") == label
            if legend and set(words(" ".join(unit.cells[1:]))[:3]) & {"timer", "delay"}:
                return True
        return False

    def _said_in_rpm(self, name: str, label: str) -> bool:
        """A setting named only a speed is in rpm when its key, printed as on the panel, is
        said with rpm ("SPEED ▲ / ▼ change the speed by 10 rpm"); a motor's rpm in the data
        is no range of a speed the display counts in levels. A name saying rpm or spin is."""
        if set(words(name.replace("_", " "))) & {"rpm", "spin"}:
            return True
        printed = re.compile(rf"(?<!\w){re.escape(label)}(?!\w)") if label.strip() else None
        return printed is not None and any(
            printed.search(u.text) and re.search(r"\brpm\b", u.text, re.I)
            for u in self.manual.units
        )

    def _range_anywhere(self, name: str, label: str) -> tuple[Range, int] | None:
        """The first range in a sentence or table row naming the setting anywhere (a
        specifications table: "| Set temperature range | 40–100 °C |", a programme table's
        time column), its unit fitting the setting; advice ("suggested") is not a limit."""
        ws = {w for w in words(name.replace("_", " ")) + words(label) if len(w) >= 4}
        timed = not _quantity_unit(name) and self._called_timer(label)
        if not ws or not (_quantity_unit(name) or timed):
            return None
        if _quantity_unit(name) == "rpm" and not self._said_in_rpm(name, label):
            return None  # "choose one of the six speeds" beside "| Motor speed | 60 – 250 rpm |"
        fit = [name, "timer"] if timed else [name]
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
        if "time" in ws and not any("timer" in words(lab.text) for lab in self.labels.values()):
            ws.add("timer")  # no key is a timer: "Timer 0:01–12:00" in the specifications is this
        advice = {"suggested", "recommended", "typical", "advised", "usual", "ideal"}
        limits = re.compile(r"\brange\b|\badjustable\b|\bcan be set\b|\bsettable\b|\bbetween\b")
        best: tuple[int, Range, int] | None = None

        def consider(score: int, text: str, i: int) -> None:
            nonlocal best
            for r in find_ranges(text):
                if r.unit and _fits(r.unit, fit) and r.high > r.low:
                    if best is None or score > best[0]:
                        best = (score, r, i)
                    return

        for i, unit in enumerate(self.manual.units):
            uw = words(unit.text)
            if surroundings(unit.text):
                continue  # "an ambient temperature between 5 °C and 35 °C": the room's
            if unit.cells and unit.header and len(unit.header) == len(unit.cells):
                # a table row: the setting is named by the column's header
                for head, cell in zip(unit.header, unit.cells, strict=True):
                    hw = words(head)
                    if set(hw) & advice or not any(_same_word(h, w) for h in hw for w in ws):
                        continue
                    consider(1 + 2 * bool(limits.search(head)), cell, i)
                first = words(unit.cells[0])
                if any(_same_word(u, w) for u in first for w in ws) and not set(first) & advice:
                    # (a row comparing the models: its own model's cell, not a sister's)
                    own = own_model_row(unit, self.manual.lines, self.manual.units)
                    consider(1 + 2 * bool(limits.search(unit.cells[0])), own.text, i)
                continue
            if not any(_same_word(u, w) for u in uw for w in ws) or set(uw) & advice:
                continue
            if "clock" in uw and "clock" not in ws:
                continue  # "any time from 1:00 to 12:59": the clock's day, not a duration
            consider(2 * bool(limits.search(unit.text)), unit.text, i)
            nxt = self.manual.units[i + 1] if i + 1 < len(self.manual.units) else None
            if (
                nxt
                and not nxt.cells
                and nxt.heading == unit.heading
                and _GOES_ON_RE.match(nxt.text)
            ):
                # "The entry delay is … It can be set from 10 to 90 seconds.": the next
                # sentence says "it" of the setting just named
                consider(2 * bool(limits.search(nxt.text)), nxt.text, i + 1)
        return (best[1], best[2]) if best else None


# a sentence that goes on about the thing the one before named ("It can be set …")
_GOES_ON_RE = re.compile(r"^(?:It|This)\s+(?:is|can|may|goes|runs|ranges)\b")


def _same_word(word: str, name: str) -> bool:
    """A word of the text naming the setting: the same first five letters, or, for a name
    printed shortened to four letters (TEMP, FREQ), the word it shortens ("temperature")."""
    return word[:5] == name[:5] or (len(name) == 4 and word.startswith(name))
