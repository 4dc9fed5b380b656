"""Manual text → units: cleaned sentences and table rows, each with the line it came from.

Manuals arrive as Markdown, plain text, or text a vision model flattened out of a PDF (broken
lines, page headers, bullet glyphs, emoji, pipe tables). Everything later works on *units*: a
sentence of running text (joined across broken lines) or one table row split into cells, so a
rule never depends on where the converter happened to break a line.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

from apbot.read.errors import ReaderError
from apbot.read.text_boxes import unbox
from apbot.read.text_callouts import item_text, lettered_items
from apbot.read.text_chars import _KEEP, _clean_chars, default_marks
from apbot.read.text_html import html_tables, tables_apart
from apbot.read.text_icons import _put, name_icons, named_beside
from apbot.read.text_pages import (
    _furniture,
    _page_breaks,
    _page_title,
    _plain_heading,
    _reading_order,
    _running_titles,
    _unfinished,
    contents_lines,
)
from apbot.read.text_quoted_keys import name_quoted_keys
from apbot.read.text_rows import GRID_RULE, wrapped_cells
from apbot.read.text_sections import drop_boilerplate, drop_tagged_models
from apbot.read.text_sign_keys import name_signed_keys
from apbot.read.text_tables import _row_charts, _space_tables, _strip_markup

MAX_MANUAL_CHARS = 400_000  # ten times the longest real manual we expect; larger is not a manual

_BULLETS = "•●○◦▪▫■□►▶➤➢✓✔✗✘–—·*-"
_CALLOUTS_RE = re.compile(r"[①-⑳❶-❿➀-➉]")
# a callout number leads a legend's item as a bullet does ("① ⏻ - lamp on / off"), and so does
# a bracketed capital letter before a key's printed name or sign ("(A) ⏻ Power", "(B) MIST —
# mist output"; "(a) the lid" in a sentence is no item)
# ... and so does a step written out: "Step 2  Touch SET." ("Step 2:", "STEP 2.")
_BULLET_RE = re.compile(
    rf"^\s*(?:[{re.escape(_BULLETS)}]|\d{{1,2}}[.)]|\(\d{{1,2}}\)|[①-⑳❶-❿➀-➉]"
    # (a small letter too, and two together for a pair of keys: "(a) °C/°F …", "(f)(g) ▲ ▼ …")
    r"|\([A-Za-z]\)(?:\([A-Za-z]\))*(?=\s+(?:[A-Z]{2}|[^\w\s]|[a-z]{1,3}[A-Z]|\S{1,8}\s{2}))"
    # (a capital in square brackets before a short name or sign set off by a wide gap, a
    # legend in columns: "[B] FN     timing method"; and two marks joined by "+" for a pair
    # held together, "(A)+(B) held together …")
    r"|\[[A-Z]\](?=\s+[^a-z\s]\S{0,7}\s{2})"
    r"|(?:\([A-Z]\)|\[[A-Z]\])(?:\s*\+\s*(?:\([A-Z]\)|\[[A-Z]\]))+"
    r"|(?:Step|STEP)\s+\d{1,2}\s*[:.)]?)\s+"
)
_NUMBERED_RE = re.compile(r"^\s*(?:(?:Step|STEP)\s+)?(\d{1,2})(?:[.)]|(?<=\d)\s*:|(?=\s))\s+")
_TABLE_RULE = re.compile(r"^\s*\|?\s*:?-{2,}:?\s*(\|\s*:?-{2,}:?\s*)*\|?\s*$")
# (not inside a run of numbers: "50, 55, 60 ... 95, 100")
_SENTENCE_END = re.compile(r"(?<=[.!?])(?<!\d \.\.\.)(?<!\d\.\.\.)\s+(?=[A-Z0-9\"'(*])")


@dataclass(frozen=True)
class Unit:
    """One sentence or table row. ``line`` is 1-based in the original text."""

    line: int
    text: str
    cells: tuple[str, ...] = ()  # a table row's cells (``text`` joins them with " | ")
    header: tuple[str, ...] = ()  # the header row of the table this row belongs to
    bullet: bool = False  # the sentence starts a bullet or numbered item
    step: int | None = None  # the number of a numbered step
    heading: str = ""  # the nearest heading above


def _header_lines(units: list[Unit], header: tuple[str, ...]) -> tuple[str, ...]:
    """A pipe table's header written on two or more lines above its rule ("| Programme |
    Max. spin |" then "| | (rpm) |"): one header row, the lines joined cell by cell, so the
    second line is no data row. Returns the table's header."""
    k = len(units)
    while k > 0 and header and units[k - 1].header == header:
        k -= 1
    if not header or k == 0 or k == len(units) or units[k - 1].cells != header:
        return header
    lines = [units[k - 1].cells, *(u.cells for u in units[k:])]
    width = max(len(cells) for cells in lines)
    merged = tuple(
        " ".join(c[i] for c in lines if i < len(c) and c[i]).strip() for i in range(width)
    )
    first = units[k - 1]
    del units[k - 1 :]
    units.append(Unit(first.line, " | ".join(merged), merged, (), heading=first.heading))
    return merged


@dataclass
class Manual:
    """The cleaned manual: its units and the raw lines (for quoting in the report)."""

    units: list[Unit]
    lines: list[str] = field(default_factory=list)
    glyph_lines: list[str] = field(default_factory=list)  # the lines before glyphs are dropped

    def quote(self, line: int) -> str:
        if 1 <= line <= len(self.lines):
            return self.lines[line - 1].strip()[:160]
        return ""


def check_text(text: object) -> None:
    """Raise :class:`ReaderError` for input that is no text, or too long to be a manual."""
    if not isinstance(text, str):
        raise ReaderError(f"a manual is text, got {type(text).__name__}")
    if len(text) > MAX_MANUAL_CHARS:
        raise ReaderError(
            f"the manual has {len(text):,} characters; the reader accepts at most "
            f"{MAX_MANUAL_CHARS:,}"
        )


def parse_manual(text: str, keys: Sequence[str] = ()) -> Manual:
    """Split a manual into units; raise :class:`ReaderError` for input that is not text.
    ``keys``: the words of the panel's keys, which tell a range's model its own paragraphs."""
    check_text(text)
    text = text.replace("\r\n", "\n").replace("\r", "\n").replace("\f", "\n\f\n")
    text = name_icons(unbox(text), _KEEP)  # "touch ❄" → "touch COLDER" when a legend names it
    text = name_signed_keys(text, keys, _KEEP)  # "❋ — fan speed" → "FAN — fan speed" (``fan``)
    text = name_quoted_keys(text, keys)  # "Press the 'Shape' key" → "Press the SHAPE key"
    glyphs = text.split("\n")  # (a level shown as segments, "▮▮▯", is read from these)
    text = re.sub(r" ?❄ ?", " ❄ ", text)  # one space each side, not two
    text = named_beside(text, _KEEP | default_marks(text))  # "☀ HOT": HOT
    # the snowflake is a cold setting: named COLD, the width it adds taken out of the next wide
    # gap, so a chart drawn with spaces keeps its columns (a wrapped cell stays under its own)
    text = _clean_chars(
        "\n".join(_put(x, "❄", "COLD") if "❄" in x else x for x in text.split("\n"))
    )
    lines = text.split("\n")
    contents = contents_lines(lines)  # a table of contents: titles, not text about the keys
    text = "\n".join("" if i in contents else line for i, line in enumerate(lines))
    # a line a dot leader joins to its word in capitals ("RUN ........ heating and feeding"): a
    # display word or key and its meaning (not an amount's row, "0:00 to 0:30 …. 1 minute")
    leadered = {
        k + 1
        for k, line in enumerate(text.split("\n"))
        if _LEADER_RE.search(line) and re.match(r"\s*[A-Z][A-Z]+\b", line)
    }
    text = _LEADER_RE.sub("    ", text)  # "Timer ........ 0:00 - 99:59": a gap between columns
    original = text.split("\n")
    raw_lines, line_numbers = tables_apart(*_reading_order(original))
    units: list[Unit] = []
    heading = ""
    header: tuple[str, ...] = ()
    ruled: tuple[str, ...] = ()  # the header of the table whose rule has been read
    led = True  # the table's header line starts with a bar
    para: list[tuple[int, str]] = []
    para_bullet = False
    para_step: int | None = None
    para_indent = -1  # how far the paragraph's first line is set in (-1: a bullet, a unit)

    def flush() -> None:
        nonlocal para, para_bullet, para_step, para_indent
        offsets: list[tuple[int, int]] = []  # (character offset in the paragraph, line)
        acc = 0
        for line_no, piece in para:
            offsets.append((acc, line_no))
            acc += len(piece) + 1
        joined = " ".join(piece for _, piece in para)
        pos = 0
        for k, sentence in enumerate(_SENTENCE_END.split(joined)):
            found = joined.find(sentence, pos)
            pos = found + len(sentence) if found >= 0 else pos
            sentence = re.sub(r"(\w)- (\w)", r"\1\2", sentence.strip())  # broken hyphenation
            if not sentence:
                continue
            line_no = max((ln for off, ln in offsets if off <= max(found, 0)), default=0)
            units.append(
                Unit(
                    line_no,
                    sentence,
                    bullet=para_bullet and k == 0,
                    step=para_step if k == 0 else None,
                    heading=heading,
                )
            )
        para = []
        para_bullet = False
        para_step = None
        para_indent = -1

    fenced = False
    furniture = _furniture(raw_lines) | _running_titles(raw_lines)
    passed = _page_breaks(raw_lines, furniture)
    spaced = _space_tables(raw_lines, passed | furniture)
    sideways = _row_charts(raw_lines)
    lettered = lettered_items(raw_lines)  # a legend's lettered items, each a unit
    markup = html_tables(raw_lines)
    previous, last = "", 0
    rule_above, said_last = False, ""
    for position, raw in enumerate(raw_lines, start=1):
        number = line_numbers[position - 1]
        if position - 1 in passed or position - 1 in furniture:
            continue
        # after a page break passed over, a line in capitals may start a new section
        rule_above = rule_above or position > last + 1  # a page break passed over
        before, previous = ("" if position > last + 1 else previous), raw.strip()
        last = position
        if position - 1 in sideways:  # a chart printed sideways: turned upright
            flush()
            chart = sideways[position - 1]
            for row in chart:
                rows_header = chart[0] if row is not chart[0] else ()
                units.append(Unit(number, " | ".join(row), row, rows_header, heading=heading))
            continue
        if position - 1 in markup.starts:
            flush()
            header = ()  # a table of its own, not rows of a pipe table above
        if position - 1 in markup.rows:
            flush()
            for cells, heads in markup.rows[position - 1]:
                if heads or not header:
                    header = cells
                    units.append(Unit(number, " | ".join(cells), cells, (), heading=heading))
                else:
                    units.append(Unit(number, " | ".join(cells), cells, header, heading=heading))
            continue
        if position - 1 in markup.skipped:
            continue
        if position in spaced:
            flush()
            cells, is_header = spaced[position]
            if is_header is None:  # a legend's first row: a table without a header
                header = ()
            if is_header:
                header = cells
                units.append(Unit(number, " | ".join(cells), cells, (), heading=heading))
            elif cells:
                units.append(Unit(number, " | ".join(cells), cells, header, heading=heading))
            continue
        if raw.strip().startswith("```"):
            flush()
            fenced = not fenced
            continue
        if fenced:  # a drawing of the panel: each line on its own, never joined into prose
            if raw.strip():
                units.append(Unit(number, raw.strip(), heading=heading))
            continue
        line = _strip_markup(raw).rstrip()
        stripped = line.strip()
        if not stripped or re.fullmatch(r"[-=_*~`#]{3,}", stripped):
            flush()
            header = ()
            rule_above = rule_above or bool(raw.strip())  # (blank lines after the rule too)
            continue
        page_top, rule_above = rule_above, False  # the first line of a page
        # ... unless the page before stopped mid-sentence ("…, then" | "Press START")
        page_top = page_top and not _unfinished(said_last)
        if re.search(r"[a-z]", stripped):  # prose, not a footer's "HT-20  4"
            said_last = stripped
        plain = (
            not stripped.startswith(("#", "-", "*", ">"))
            and (not before or re.search(r"[.!?:]$", before) or _plain_heading(before))
            and _plain_heading(stripped)
        ) or (page_top and _page_title(stripped))
        if stripped.startswith("#") or plain:
            flush()
            header = ()
            heading = stripped.lstrip("#").strip()
            units.append(Unit(number, heading, heading=heading))
            continue
        if header and GRID_RULE.match(stripped):  # "-----+-----": the table's rule all the same
            flush()
            if header != ruled:
                header = ruled = _header_lines(units, header)
            continue
        if "|" in stripped and stripped.count("|") >= 2:
            flush()
            if _TABLE_RULE.match(stripped):
                if header and header != ruled:  # the rows above a table's first rule: header
                    header = ruled = _header_lines(units, header)
                continue
            cells = tuple(c.strip() for c in stripped.strip("|").split("|"))
            if not header:
                header, led = cells, stripped.startswith("|")
                units.append(Unit(number, " | ".join(cells), cells, (), heading=heading))
                continue
            if stripped.startswith("|") and not led:  # a table without outer bars: its first
                cells = ("", *cells)  # cell left empty ("      |    | rice")
            above = units[-1] if units and units[-1].header == header else None
            joined = wrapped_cells(above.cells, cells) if above is not None else None
            if above is not None and joined is not None:  # a row's wrapped ends: that row
                units[-1] = Unit(above.line, " | ".join(joined), joined, header, heading=heading)
            else:
                units.append(Unit(number, " | ".join(cells), cells, header, heading=heading))
            continue
        header = ()
        bullet = _BULLET_RE.match(line)
        if bullet and len(_CALLOUTS_RE.findall(line)) > 1:
            bullet = None  # "① PROGRAM knob · ② °C knob · …": the drawing's parts on one line
        if position - 1 in lettered:  # "(d) Level 0-99 …", "[F] DOG 1/2 slide switch"
            flush()
            para_bullet, para_step = True, None
            para.append((number, item_text(line)))
            continue
        if bullet:
            flush()
            step = _NUMBERED_RE.match(line)
            para_bullet = True
            para_step = int(step.group(1)) if step else None
            para.append((number, line[bullet.end() :].strip()))
            continue
        if re.match(r"\s{3,}\S", line) and len(re.findall(r"\S\s+·\s+\S", line)) >= 2:
            flush()  # an indented row of marks ("   OFF · 1 · 2 · CONT") drawn in a figure
            units.append(Unit(number, stripped, heading=heading))
            continue
        if para and number in leadered:  # a legend's row starts afresh (its wrapped lines
            flush()  # go on with it), never running on from the row above
            para.append((number, stripped))
            continue
        indent = len(line) - len(line.lstrip())
        if para and (
            _TERM_RE.match(line)
            or _FIELD_RE.match(line)
            or (
                indent == para_indent
                and _TERM_RE.match(line.lstrip())
                and not any(_STOP_RE.search(piece) for _, piece in para)
            )
        ):
            # "WARM      holds cooked food hot": a term and its definition, a new item; a
            # legend set in as a block has its terms at one indent (a wrapped line further in);
            # a paragraph of prose set in (its sentences end in full stops) is no legend, though
            # a justified line of it may start "8  hours to …"
            flush()
        if not para:
            para_indent = indent
        para.append((number, stripped))
    flush()
    units = drop_tagged_models(drop_boilerplate(units, original), original, keys)
    return Manual([_grouped_digits(u) for u in units], original, glyphs)


# a figure with its thousands set apart by commas ("2,500", "10,000 lux"): never a first group
# that starts with 0 ("0,500" is a decimal), never a group run on by more digits or a decimal
_THOUSANDS_RE = re.compile(r"(?<![\d.,])([1-9]\d{0,2})((?:,\d{3})+)(?![\d]|[.,]\d)")


def _grouped_digits(unit: Unit) -> Unit:
    """Write "2,500" as 2500: a comma before exactly three digits groups thousands (English
    figures), where the decimal comma is written before one or two ("1,5 kg"). Read as a
    decimal it made 2,500 / 5,000 / 10,000 lux levels of 2.5, 5 and 10."""
    if "," not in unit.text:
        return unit

    def join(text: str) -> str:
        return _THOUSANDS_RE.sub(lambda m: m.group(1) + m.group(2).replace(",", ""), text)

    text = join(unit.text)
    if text == unit.text:
        return unit
    return replace(
        unit,
        text=text,
        cells=tuple(join(c) for c in unit.cells),
        header=tuple(join(c) for c in unit.header),
    )


_LEADER_RE = re.compile(r"(?<=\S)[ \t]*(?:\.[ \t]?){4,}[ \t]*(?=\S)")
_FIELD_RE = re.compile(  # "Water level: …", "Cup-size lamps: …": a field of its own
    r"^\s{0,2}[A-Z][a-z]+(?:-[a-z]+)?(?:[ -][A-Za-z]+){0,3}(?: \([^)]{1,30}\))?:\s+\S"
)
_STOP_RE = re.compile(r"[.!?](?:\s|$)")  # a sentence's end: legend rows have none
_TERM_RE = re.compile(  # "TEMP knob     Sets …", "SET 60°C     Set temperature": a term
    r"^\s{0,2}[A-Z0-9](?:[A-Z0-9+/&.'°−-]|(?<=[\d-]):(?=[\d-]))*"  # a colon only in 01:30, --:--
    r"(?: (?:[A-Z0-9+/&.'°−▲▼-]|(?<=[\d-]):(?=[\d-]))+){0,3}"
    r"(?: (?:knob|dial|button|key|switch|lever|selector|wheel|ring|lamp|indicator)s?)?\s{2,}\S"
)
