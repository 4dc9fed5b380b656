"""What the manual says about a control: values, ranges, steps, toggles, each with the unit
it came from (the builder asks once per control and keeps the answer)."""

from __future__ import annotations

import itertools
import math
import re

from apbot.read.evidence_lists import ListReader
from apbot.read.labels import words
from apbot.read.shapes import (
    _KEYPAD_WORDS,
    _TIMER_WORDS,
    CHOICE_WORDS,
    LAMP_LIST_RE,
    Evidence,
    _aside,
    _cell_key,
    _fits,
    _header_row,
    _keyish,
    _keypad,
    _numeric_items,
    _quantity_unit,
    _quantity_units,
    _row_step,
    _rows_span,
    _without,
    _without_advice,
)
from apbot.read.text import Unit
from apbot.read.value_lists import anchored_lists, bare_list, named_list
from apbot.read.values import (
    EACH_PRESS_RE,
    ON_OFF_RE,
    UNIT,
    Range,
    find_bounds,
    find_initial,
    find_ranges,
    find_step,
    find_stepped_pieces,
    find_two_steps,
    number,
    unit_name,
)


class EvidenceReader(ListReader):
    """Evidence about controls: values, ranges, steps and toggles, with where each was read."""

    _evidence: dict[tuple[str, ...], Evidence]

    def evidence(self, tokens: list[str]) -> Evidence:
        """What the manual says about the controls (cached: roles ask more than once)."""
        key = tuple(tokens)
        if key not in self._evidence:
            self._evidence[key] = self._read_evidence(tokens)
        return self._evidence[key]

    def _turned(self, tokens: list[str]) -> bool:
        """The panel has a knob or dial other than these controls (its turns are clicks)."""
        return any(
            i.skill.startswith("turn") and not set(i.controls) & set(tokens)
            for i in getattr(self, "infos", [])
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
        elsewhere = {i for t, lab in self.labels.items() if t not in tokens for i in lab.mentions}
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
        for i in self.context(tokens):
            text = units[i].text
            unit = units[i]
            if i in elsewhere and i not in mentions and not unit.cells:
                continue  # a sentence about another key says nothing about this one
            if i not in mentions and any(named_list(text, w) for w in other_words):
                continue  # "The menu names printed on the panel: …" near KEEP WARM: MENU's
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
                if _where_it_applies(items, text):
                    continue  # "(PORRIDGE, STEAM, SOUP only)": where it applies, not its values
                items = _without_only(items)  # "Selects SOFT or FIRM only": the values
                if not items:
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
            if unit.cells:  # "| 1 – 2 |" then "| 3 – 4 |" … "| 9 – 10 |": groups of one setting
                ranges = [_rows_span(units, i, r) for r in ranges]
            pieces = find_stepped_pieces(text) if ranges and not ev.ranges else []
            if pieces and _fits("s", tokens):  # "0:30 – 12:00 30 minutes 12:00 – 24:00 1 hour"
                ev.ranges, ev.range_at = pieces, i
            elif ranges and not ev.ranges:
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
                and not quiet  # ("The hob deactivates." under Troubleshooting)
                and ON_OFF_RE.search(_without(text, other_labels))
                and not self._two_key_hold(text, tokens)
            ):
                ev.toggle_at = i  # (another key's name, ON/OFF in a panel drawing, is no toggle)
            pressed = EACH_PRESS_RE.search(text)
            if pressed and "click" in pressed.group(0).lower() and self._turned(tokens):
                pressed = None  # "every click changes the time": a dial's clicks, not a key's
            if ev.each_press_at is None and not quiet and pressed:
                ev.each_press_at = i
            if ev.initial is None:
                init = find_initial(text)
                if init:
                    ev.initial, ev.initial_at = init, i
        for i in sorted(self.context(tokens)):  # "up to 1 h by 10 min; after that by 30 min"
            window = [k for k in range(i, min(i + 4, len(units))) if not units[k].cells]
            names = tuple(self.labels[t].text.lower() for t in tokens if t in self.labels)
            two = find_two_steps([units[k].text for k in window], names)
            if two and _fits(two[0][0].unit, tokens):
                ev.ranges, ev.range_at = two[0], window[two[1]]
                break
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
        own_words = {w for t in tokens for w in words(t.replace("_", " ")) if len(w) >= 3}
        if ev.step is None and own_words:  # "The delay is set in half-hour units.", anywhere
            subject = re.compile(rf"^(?:the\s+)?(?:{'|'.join(map(re.escape, own_words))})\b", re.I)
            for i, unit in enumerate(units):
                step = None if unit.cells or not subject.match(unit.text) else find_step(unit.text)
                if step:
                    ev.step, ev.step_at = step, i
                    break
        if best_prio < 2.0 and own_words:  # "Mode lamps (left to right): NORMAL CONT. FAN"
            for i, unit in enumerate(units):
                lamps = LAMP_LIST_RE.match(unit.text)
                lamp_words = (
                    {w[:4] for w in words(lamps.group(0)) if len(w) >= 4} if lamps else set()
                )
                if lamps and lamp_words & {w[:4] for w in own_words if len(w) >= 4}:
                    # ("Keep-warm temperature lamps:" for TEMP SELECT: temp ~ temperature)
                    rest = unit.text[lamps.end() :]
                    for after in units[i + 1 : i + 8]:  # "CONT." ended a "sentence" mid-line
                        if after.line != unit.line:
                            break
                        rest += "   " + after.text
                    found = bare_list(rest)
                    if found:
                        best, best_prio, ev.values_at = found, 2.0, i
                        break
        alone = [t for t in tokens if t in ("knob", "dial")]
        if best_prio < 2.6 and alone and sum(t.endswith(alone[0]) for t in self.labels) == 1:
            # the panel's one knob: "The knob has seven positions." and the row drawn after it
            the = re.compile(rf"\bthe {alone[0]}\b", re.I)
            for i, unit in enumerate(units):
                if the.search(unit.text) and not _aside(units, i):
                    counted = [c for c in self._lists(i, True, tokens) if c[1] == 2.6]
                    if counted and self.labels[alone[0]].line is not None:
                        best, best_prio, ev.values_at = counted[0][0], 2.6, i
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
                if m and m.group(1).lower() in others:
                    continue  # "TIME START/PAUSE" on a panel drawing: the next key's name
                if m:  # "FAN HI/LO": the panel prints the values next to the name
                    best, best_prio, ev.values_at = m.group(1).split("/"), 2.5, i
                    break
        if best and re.search(r"\bonly\W*$", best[-1], re.I):
            # "(STEW, JAM, BROTH only)": where the setting applies, not its values
            shown = units[ev.values_at].text if ev.values_at is not None else ""
            best = None if _where_it_applies(best, shown) else _without_only(best) or None
        choice = bool({w for t in tokens for w in words(t.replace("_", " "))} & CHOICE_WORDS)
        if best is None or (_numeric_items(best) and (len(best) < 3 or choice)):
            # two numbers are a range, not a list; a programme key's list is of names
            column = self._table_column(tokens)
            if column:
                best, ev.values_at = column, self._table_at
            elif best is not None and len(best) < 3:
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
                for lo, hi in itertools.pairwise(amounts):
                    gap = round(hi - lo, 6)
                    if ev.ranges and ev.ranges[-1].step == gap:
                        ev.ranges[-1] = Range(ev.ranges[-1].low, hi, symbol, gap)
                    else:
                        ev.ranges.append(Range(lo, hi, symbol, gap))
                ev.range_at = at
        if best is not None and _numeric_items(best) and len(best) >= 3:
            near = {
                j
                for i in mentions
                for j in range(i, min(i + 5, len(units)))
                if units[j].heading == units[i].heading
            }  # the paragraph about the knob: its marks, then how it clicks between them
            said = [units[i].text for i in sorted(near | set(self.context(tokens)))]
            if any(_BETWEEN_RE.search(t) for t in said):
                best = _with_midpoints(best)
            for t in said:  # "in the first ten minutes every minute has its own tick"
                top = _every_minute_top(t)
                if top and 2 <= top <= 30 and top == int(top):
                    best = _with_every(best, int(top))
                    break
        if best is not None:
            ev.values = best if _numeric_items(best) else [v.lower() for v in best]
            self._initial_from_values(ev, tokens)
        return ev

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

    def _range_anywhere(self, name: str, label: str) -> tuple[Range, int] | None:
        """The first range in a sentence or table row naming the setting anywhere (a
        specifications table: "| Set temperature range | 40–100 °C |", a programme table's
        time column), its unit fitting the setting; advice ("suggested") is not a limit."""
        ws = {w for w in words(name.replace("_", " ")) + words(label) if len(w) >= 4}
        timed = not _quantity_unit(name) and self._called_timer(label)
        if not ws or not (_quantity_unit(name) or timed):
            return None
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


_AMOUNT_CELL_RE = re.compile(rf"\s*\**\s*(\d+(?:[.,]\d+)?)\s*({UNIT})\s*\**\s*$", re.I)


def _amount_column(units: list[Unit], i: int) -> Range | None:
    """A table a sentence ending in ":" introduces whose first column is amounts in one unit
    other than time ("| 100 % | Water |", "| 70 % | Reheating |"): settings given as examples,
    so the range runs from the least to the most, in the largest step that meets them all."""
    text = units[i].text.rstrip()
    caption = len(text.split()) <= 6 and not text.endswith((".", "!", "?"))  # "Power table"
    if not text.endswith(":") and text != units[i].heading and not caption:
        return None  # (a sentence ending in ":", a heading or a caption over the table)
    k = i + 1
    if k < len(units) and units[k].cells and not units[k].header:
        k += 1  # the header row
    amounts: list[float] = []
    unit = None
    while k < len(units) and units[k].cells and units[k].header:
        m = _AMOUNT_CELL_RE.fullmatch(units[k].cells[0])
        if not m:
            return None
        this = unit_name(m.group(2))
        if unit not in (None, this) or this in ("", "s", "min", "h"):
            return None
        unit = this
        amounts.append(float(m.group(1).replace(",", ".")))
        k += 1
    if len(amounts) < 3 or unit is None:
        return None
    step = 0.0
    for a in amounts:
        step = math.gcd(round(step * 10), round(a * 10)) / 10
    if step <= 0:
        return None
    return Range(min(amounts), max(amounts), unit, step)


_APPLIES_BEFORE_RE = re.compile(  # "(", "for", "with the menus", "for these programmes only:"
    r"(?:\(|\b(?:for|with|in|during|on|under)\b(?:\s+(?:the|all|these|those|following))*"
    r"(?:\s+[a-z]+)?(?:\s+only)?\s*:?)\s*$",
    re.I,
)


def _where_it_applies(items: list[str], text: str) -> bool:
    """A list the word "only" closes or leads, after "for"/"with"/"(": the programmes where a
    setting applies ("(STEW, JAM only)", "only for WHITE and BROWN"), not the setting's own
    values ("Selects SOFT, REGULAR or FIRM only")."""
    tail = re.sub(r"\W*\bonly\W*$", "", items[-1], flags=re.I)
    closed = tail != items[-1] or bool(re.search(rf"{re.escape(tail)}\W{{0,3}}only\b", text, re.I))
    first = re.search(rf"(?<!\w){re.escape(items[0].strip())}(?!\w)", text, re.I)
    if first is None:
        return closed  # (where the list stands is unknown: as the words say)
    before = text[max(0, first.start() - 60) : first.start()]
    led = bool(re.search(r"\bonly\b[^.;]{0,40}$", before))
    return (closed or led) and bool(_APPLIES_BEFORE_RE.search(before))


def _names_of_pieces(items: list[str], units: list[Unit], at: int | None) -> bool:
    """The list is the first cells of the table rows the range's pieces were read from."""
    if at is None or not units[at].cells:
        return False
    rows = units[at : at + len(items)]
    heads = [u.cells[0].strip(" *").lower() for u in rows if u.cells]
    return heads == [v.strip(" *").lower() for v in items]


def _part_of(items: list[str], column: list[str]) -> bool:
    """A few names a sentence gives in passing ("OFF sits between Spin/Drain and Cottons"),
    each a name or a slash-part of a name in the longer first column of the control's own
    chart: the chart lists them all."""
    names = {c.strip(" *").lower() for c in column}
    parts = names | {p.strip() for c in names for p in c.split("/")}
    return len(column) > len(items) and all(v.strip(" *").lower() in parts for v in items)


def _without_only(items: list[str]) -> list[str]:
    """The list with a closing "only" taken off its last item ("FIRM only" -> "FIRM")."""
    last = re.sub(r"\W*\bonly\W*$", "", items[-1], flags=re.I)
    return [*items[:-1], last] if last else items[:-1]


# "the knob clicks between the markings", "a detent halfway between two printed numbers"
_BETWEEN_RE = re.compile(
    r"\b(?:clicks?|detents?|stops?|notch(?:es)?|settings?|set)\b[^.;]{0,40}\b(?:between|halfway)\b"
    r"[^.;]{0,30}\b(?:markings?|marks|numbers|figures)\b",
    re.I,
)


def _with_midpoints(items: list[str]) -> list[str]:
    """Printed marks with a setting halfway between each two (200 250 … → 200 225 250 …)."""
    parsed = [re.match(r"\s*(\d+(?:[.,]\d+)?)\s*(.*)", v) for v in items]
    if not all(parsed):
        return items
    nums = [float(m.group(1).replace(",", ".")) for m in parsed if m]
    if any(b <= a for a, b in itertools.pairwise(nums)):
        return items
    unit = next((m.group(2) for m in parsed if m and m.group(2)), "")
    out: list[float] = []
    for a, b in itertools.pairwise(nums):
        out += [a, (a + b) / 2]
    out.append(nums[-1])
    return [f"{v:g}" + (f" {unit}" if unit else "") for v in out]


# a scale marked minute by minute up to some bound: "every minute up to 10 min", "1-minute
# steps below 10 minutes", "each minute is marked for the first ten minutes"
_EVERY_MINUTE_RE = re.compile(
    r"\b(?:every|each|single)\s+minute\b|\bminute by minute\b|\bsingle minutes\b"
    r"|\b(?:1|one)[\s-]?min(?:ute)?\s+(?:steps?|increments?|ticks?|marks?|clicks?|divisions?)\b",
    re.I,
)
_MINUTE_BOUND_RE = re.compile(
    r"\b(?:first|up to|below|under|until|till|to)\s+(?:the\s+)?(?:first\s+)?"
    r"(\d{1,2}|[a-z]+)\s*(?:minutes|mins?)\b",
    re.I,
)
_SENTENCE_END_RE = re.compile(r"(?<=[.;!?])\s+")


def _every_minute_top(text: str) -> float | None:
    """The bound of a run of one-minute settings a sentence describes, else None."""
    for sentence in _SENTENCE_END_RE.split(text):
        fine = _EVERY_MINUTE_RE.search(sentence)
        if fine is None:
            continue
        for bound in _MINUTE_BOUND_RE.finditer(sentence):
            if bound.start() >= fine.end() or bound.end() <= fine.start():
                top = number(bound.group(1))
                if top is not None:
                    return top
    return None


def _with_every(items: list[str], top: int) -> list[str]:
    """Marks in minutes with every whole minute up to ``top`` added."""
    parsed = [re.match(r"\s*(\d+)\s*(.*)", v) for v in items]
    if not all(parsed):
        return items
    nums = sorted({int(m.group(1)) for m in parsed if m} | set(range(top + 1)))
    unit = next((m.group(2) for m in parsed if m and m.group(2)), "")
    return [f"{v}" + (f" {unit}" if unit else "") for v in nums]
