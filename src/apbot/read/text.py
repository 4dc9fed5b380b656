"""Manual text → units: cleaned sentences and table rows, each with the line it came from.

Manuals arrive as Markdown, plain text, or text a vision model flattened out of a PDF (broken
lines, page headers, bullet glyphs, emoji, pipe tables). Everything later works on *units*: a
sentence of running text (joined across broken lines) or one table row split into cells, so a
rule never depends on where the converter happened to break a line.
"""

from __future__ import annotations

import itertools
import re
import unicodedata
from dataclasses import dataclass, field

from apbot.read.errors import ReaderError

MAX_MANUAL_CHARS = 400_000  # ten times the longest real manual we expect; larger is not a manual

_BULLETS = "•●○◦▪▫■□►▶➤➢✓✔✗✘–—·*-"
_BULLET_RE = re.compile(rf"^\s*(?:[{re.escape(_BULLETS)}]|\d{{1,2}}[.)])\s+")
_NUMBERED_RE = re.compile(r"^\s*(\d{1,2})[.)]\s+")
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

    def quote(self, line: int) -> str:
        if 1 <= line <= len(self.lines):
            return self.lines[line - 1].strip()[:160]
        return ""


_KEEP = frozenset("▲▼△▽◀▶◄►◁▷⏻°↑↓←→⟳⟲↻↺")
_SPECIAL = re.compile(r"[^\x20-\x7e\n\t]")  # anything outside printable ASCII


def _clean_chars(text: str) -> str:
    """Drop control characters and pictographs; keep letters, digits, punctuation, ▲▼ and °."""

    def one(match: re.Match[str]) -> str:
        ch = match.group(0)
        cat = unicodedata.category(ch)
        if cat.startswith("C"):
            return "\f" if ch == "\f" else ""  # a form feed marks a page: kept, on its own line
        if ch == "❄":
            return "COLD"  # the snowflake printed for a cold wash or a cold setting
        if "\u2500" <= ch <= "\u257f":
            return "-"  # box drawing: a rule across a table stays a rule
        if cat == "So" and ch not in _KEEP:
            return " "  # emoji and dingbats
        return ch

    return _SPECIAL.sub(one, text)


def _strip_markup(line: str) -> str:
    line = re.sub(r"\*\*|__|`+", "", line)
    # a star alone in brackets or quotes is a printed symbol ("the star symbol (*)"), no emphasis
    alone = r"(?!(?<=[(\"'])\*[)\"'])"
    line = re.sub(rf"(?<!\w){alone}\*(?=\S)|(?<=\S){alone}\*(?!\w)", "", line)
    line = re.sub(r"^\s*>+\s?", "", line)
    # a dot leader ("0:00 to 0:30 ........ 1 minute per touch") joins two halves of one
    # statement; its dots are no sentence end
    line = re.sub(r"(?<=\S) ?\.{4,} ?(?=\S)", " ", line)
    return line


def _cells(line: str) -> tuple[str, ...]:
    return tuple(c for c in re.split(r"\s{2,}|\t+", _strip_markup(line).strip()) if c)


def _space_tables(lines: list[str]) -> dict[int, tuple[tuple[str, ...], bool]]:
    """Tables drawn with spaces (text from a PDF): a header of three or more cells followed by
    rows of two or more; a row's wrapped lines (set in from the left) go on its cells.

    Returns line number → (cells, is the header row)."""
    out: dict[int, tuple[tuple[str, ...], bool]] = {}
    i = 0
    while i < len(lines):
        head = _cells(lines[i])
        before = lines[i - 1].strip() if i else ""
        if (
            before
            and not re.search(r"[.:!?]$", before)
            and not before.isupper()
            and not before.startswith("#")  # a Markdown heading ends what came before
        ):
            i += 1  # the line goes on with a sentence from the line before: not a table header
            continue
        if len(head) < 3 or "|" in lines[i] or len(lines[i]) > 200:
            i += 1
            continue
        rows: list[int] = []
        more: dict[int, list[tuple[int, str]]] = {}  # row -> wrapped lines' cells, by position
        indent = len(lines[i]) - len(lines[i].lstrip())
        j = i + 1
        while j < len(lines) and lines[j].strip():
            if re.fullmatch(r"[-=_][-=_\s]{2,}", lines[j].strip()):
                j += 1  # a rule under the header ("-------  ------  -----")
                continue
            cells = _cells(lines[j])
            inset = len(lines[j]) - len(lines[j].lstrip()) > indent + 2
            if inset and "|" not in lines[j]:  # a wrapped line: of the header, or of a row
                more.setdefault(rows[-1] if rows else i, []).extend(_placed_cells(lines[j]))
            elif len(cells) >= 2 and "|" not in lines[j]:
                rows.append(j)
            elif len(cells) != 1 or len(cells[0]) > 40:
                break
            j += 1
        if len(rows) >= 2:
            out[i + 1] = (_joined_cells(lines[i], more.get(i, [])), True)
            for r in rows:
                out[r + 1] = (_joined_cells(lines[r], more.get(r, [])), False)
            for k in range(i + 1, j):
                out.setdefault(k + 1, ((), False))
            i = j
        else:
            i += 1
    return out


# the first cell of a chart's row counting the presses ("touch  1  2  3", "No. of presses")
_COUNT_ROW_RE = re.compile(
    r"^(?:no\.? of |number of )?(?:press(?:es)?|touch(?:es)?|taps?|clicks?|times?)"
    r"(?: pressed| touched)?\W*$",
    re.IGNORECASE,
)


def _row_charts(lines: list[str]) -> dict[int, list[tuple[str, ...]]]:
    """Charts printed sideways, each row a line led by its name, the first counting the
    presses: "touch    1      2     3   ...   26" over "display  0.5 h  1 h   2 h  ...  (off)".
    Read as a table turned upright: a header of the row names, then one row per column
    ("| touch | display |", "| 1 | 0.5 h |" …); ellipsis columns are left out.

    Returns the first line's index → the table's rows (header first); the other lines of the
    chart map to no rows."""
    out: dict[int, list[tuple[str, ...]]] = {}
    i = 0
    while i + 1 < len(lines):
        first = _cells(lines[i])
        before = lines[i - 1].strip() if i else ""
        if (
            len(first) < 4
            or "|" in lines[i]
            or not _COUNT_ROW_RE.match(first[0])
            or (before and not re.search(r"[.:!?]$", before))
        ):
            i += 1
            continue
        rows = [first]
        j = i + 1
        while j < len(lines) and lines[j].strip():
            cells = _cells(lines[j])
            if len(cells) != len(first) or not re.match(r"[A-Za-z]", cells[0]):
                break
            rows.append(cells)
            j += 1
        if len(rows) < 2:
            i += 1
            continue
        table = [tuple(r[0] for r in rows)]
        columns = [
            tuple(re.sub(r"^\((.*)\)$", r"\1", r[c]) for r in rows) for c in range(1, len(first))
        ]
        for c, cells in enumerate(columns):
            if all(re.fullmatch(r"\.{3}|…", x) for x in cells):
                if 0 < c < len(columns) - 1:
                    table += _elided(columns[c - 1], columns[c + 1])
                continue
            table.append(cells)
        out[i] = table
        for k in range(i + 1, j):
            out[k] = []
        i = j
    return out


_AMOUNT_RE = re.compile(r"(\d+(?:\.\d+)?)\s*([A-Za-z°%]{1,4})")


def _elided(before: tuple[str, ...], after: tuple[str, ...]) -> list[tuple[str, ...]]:
    """The columns an ellipsis stands for in a sideways chart, between touch 5 (4 h) and touch
    25 (24 h): one a touch, each row's amount in equal steps (6 | 5 h … 24 | 23 h). None when
    the counts or the amounts do not divide evenly."""
    if not (before[0].isdigit() and after[0].isdigit()):
        return []
    a, b = int(before[0]), int(after[0])
    if not 1 < b - a <= 200:
        return []
    out: list[list[str]] = [[str(n)] for n in range(a + 1, b)]
    for x, y in zip(before[1:], after[1:], strict=True):
        mx, my = _AMOUNT_RE.fullmatch(x), _AMOUNT_RE.fullmatch(y)
        if not mx or not my or mx.group(2) != my.group(2):
            return []
        step = (float(my.group(1)) - float(mx.group(1))) / (b - a)
        if step <= 0 or abs(step * 1000 - round(step * 1000)) > 1e-6:
            return []
        for k, row in enumerate(out, start=1):
            row.append(f"{float(mx.group(1)) + step * k:g} {mx.group(2)}")
    return [tuple(row) for row in out]


def _placed_cells(line: str) -> list[tuple[int, str]]:
    """A line's cells (split at wide gaps) with the column each starts at."""
    body = _strip_markup(line).rstrip()
    return [(m.start(), m.group(0)) for m in re.finditer(r"\S+(?: \S+)*", body)]


def _joined_cells(line: str, wrapped: list[tuple[int, str]]) -> tuple[str, ...]:
    """A row's cells with the text of its wrapped lines added to the cell each piece stands
    under ("To activate and deactivate the" + "hob.")."""
    placed = _placed_cells(line)
    if not wrapped or not placed:
        return _cells(line)
    cells = [text for _, text in placed]
    for at, text in wrapped:
        k = max((n for n, (start, _) in enumerate(placed) if start <= at + 2), default=0)
        cells[k] = f"{cells[k]} {text}"
    return tuple(cells)


_PAGE_NUMBER = re.compile(
    r"^[-—–\s]*(?:page\s+)?\d{1,3}(?:\s*(?:/|of)\s*\d{1,3})?[-—–\s]*$", re.IGNORECASE
)
_NUMBER_PREFIX = re.compile(r"^\d{1,2}(?:\.\d{1,2})*\.?\s+")
_CAPS_HEADING = re.compile(r"[A-Z][A-Z0-9 &/,'’()+-]*")


_PAGE_TAG = re.compile(  # "- 3 -", "Page 2 — EN", "EN · 1/14", "p. 3 / 12", "EN-4", "2 en", "6a"
    r"[-—–·\s]*(?:(?:en|de|fr|es|it|nl|uk|us|gb)\s*[-—–·/]?\s*)?(?:(?:page|p\.)\s*)?\d{1,3}[a-d]?"
    r"(?:\s*(?:/|of)\s*\d{1,3}|\s*\(\d{1,3}\))?(?:\s*[-—–·]?\s*(?:en|de|fr|es|it|nl))?"
    r"[-—–·\s]*",
    re.IGNORECASE,
)
_CONTENT_START = re.compile(r"\d{1,2}[.)]\s|\d{1,2}(?:\.\d{1,2})*\s+\S|[-*•·▪●◦–]\s")
_KEY_WORDS = re.compile(r"\b(?:press|touch|tap|turn|hold|select|push)\b|\[[^\]]+\]", re.I)


def _furniture(lines: list[str]) -> set[int]:
    """Page headers and footers of text flattened from a PDF (0-based line indexes). Only text
    that shows its pages has them: two or more page markers — a form feed, a page number
    standing alone by a blank line ("— 2 —", "Page 3", "EN · 2/14"), or one beside a running
    title that comes back three or more times ("GLIMMERKIN UVC-9    - 3 -"). Then a short line
    that comes back three or more times (digits aside) is furniture only next to a marker, at
    the top or bottom of a page, and never when it reads as content: a numbered or bulleted
    line, one naming a key to press, a single word ("Note"), or a row of a table."""

    def key(line: str) -> str:
        return re.sub(r"\s+", " ", re.sub(r"\d+", "#", line.strip())).lower()

    cells = [re.split(r"\s{3,}", line.strip()) for line in lines]
    counts: dict[str, int] = {}
    for i, line in enumerate(lines):
        for k in {key(line), key(cells[i][0]) + " …", key(cells[i][-1]) + " …"}:
            counts[k] = counts.get(k, 0) + 1

    def plain(k: int) -> bool:  # a blank line or a line drawn across the page
        return not 0 <= k < len(lines) or not re.search(r"[A-Za-z0-9]", lines[k])

    markers: set[int] = set()
    titles: set[str] = set()  # running titles beside page numbers ("GLIMMERKIN UVC-9")
    for i, line in enumerate(lines):
        stripped = line.strip()
        apart = plain(i - 1) or plain(i + 1) or re.match(r"\s{20,}", line)
        numbered = bool(stripped and _PAGE_TAG.fullmatch(stripped) and re.search("[1-9]", line))
        if "\f" in line or (numbered and apart):
            markers.add(i)
        elif len(cells[i]) == 2 and "|" not in stripped:
            for tag, title in (cells[i], reversed(cells[i])):
                if _PAGE_TAG.fullmatch(tag) and counts[key(title) + " …"] >= 3:
                    markers.add(i)
                    titles.add(key(title))
    if len(markers) < 2:
        return set()
    filled = [i for i, line in enumerate(lines) if line.strip() and i not in markers]
    edge: set[int] = set()
    for m in markers:  # up to three lines of text above and below each page marker
        after = [i for i in filled if i > m][:3]
        before = [i for i in filled if i < m][-3:]
        edge |= set(after) | set(before)
    edge |= set(filled[:3])  # the first page's header
    out = {i for i in markers if "\f" not in lines[i]}
    for i in sorted(edge):
        stripped = lines[i].strip()
        if "|" in stripped or len(stripped) > 90 or counts[key(lines[i])] < 3:
            continue
        rule = not re.search(r"[A-Za-z0-9]", stripped)  # a drawn line across the page
        if rule and len(stripped) >= 10 and not re.match(r"[-*#>|`]", stripped):
            out.add(i)
            continue
        content = (
            _CONTENT_START.match(stripped)
            or _KEY_WORDS.search(stripped)
            or len(stripped.split()) < 2
            or len(cells[i]) > 2
            or (len(cells[i]) == 2 and re.match(r"\s{2,}", lines[i]))  # an indented table row
            or re.search(r"[.!?:;,]$", stripped)
            or re.match(r"[-*#>|`]", stripped)
        )
        if not content:
            out.add(i)
    for i, line in enumerate(lines):  # a running title beside the section's name, anywhere
        if len(cells[i]) == 2 and key(cells[i][0]) in titles and not re.match(r"\s", line):
            out.add(i)
    return out


def _page_breaks(lines: list[str], furniture: set[int]) -> set[int]:
    """Lines to pass over so a sentence broken by a page goes on (0-based): a run of blank lines
    and page furniture, unless the text before it ended a sentence (then it is a paragraph
    break, and one blank line stays)."""
    skip: set[int] = set()
    i = 0
    while i < len(lines):
        if i not in furniture and lines[i].strip():
            i += 1
            continue
        j = i
        while j < len(lines) and (j in furniture or not lines[j].strip()):
            j += 1
        run = range(i, j)
        if any(k in furniture for k in run):
            before = next((lines[k].strip() for k in range(i - 1, -1, -1) if k not in skip), "")
            ended = not before or re.search(r"[.!?:]$", before) or _plain_heading(before)
            skip |= {k for k in run if k in furniture or not ended or k != i}
            if ended and i in furniture:  # keep one break: the first blank line of the run
                blank = next((k for k in run if k not in furniture), None)
                skip -= {blank} if blank is not None else set()
        i = j
    return skip


def _plain_heading(line: str) -> bool:
    """A heading of a plain-text manual: a short line in capitals ("PANEL AND KNOBS", "4 CONTROL
    PANEL", "1. SAFETY INFORMATION") or a section number with a short title ("6.1 Entering the
    output on the keypad"), never a sentence, a numbered step or a drawing of the panel."""
    stripped = line.strip()
    number = _NUMBER_PREFIX.match(stripped)
    rest = stripped[number.end() :] if number else stripped
    if not 3 <= len(rest) <= 60 or re.search(r"\s{2,}|[.:;!?,-]$|\[|\|", rest):
        return False
    if len(re.findall(r"[A-Za-z]", rest)) < 3 or len(rest.split()) > 8:
        return False
    if _CAPS_HEADING.fullmatch(rest) and len(rest.split()) <= 7:
        return True
    sub_level = bool(number and re.match(r"\d{1,2}\.\d", stripped))
    short = len(rest.split()) <= 6  # a title, not a sentence run on after it
    return sub_level and short and rest[0].isupper() and not re.search(r"\d", rest)


def _legend(parts: list[tuple[int, str, str]]) -> bool:
    """Rows of a legend or a table ("DELAY START button     Sets the finish time …"), not two
    columns of prose: the left parts are mostly short terms, each starting afresh, and the left
    column's text does not run on from one line to the next."""
    lefts = [p[1] for p in parts]
    if sum("→" in left or "►" in left for left in lefts) >= 2 and not any(
        re.search(r"[a-z]{3,} [a-z]{3,}", left) for left in lefts
    ):
        return True  # a chart's rows: amounts and arrows on the left ("1 h → … → 12 h")
    terms = sum(
        len(left.split()) <= 4
        and not re.search(r"[,;-]$|\b(?:the|and|or|to|of|a|an)$", left)
        and not left[0].islower()
        for left in lefts
    )
    runs_on = sum(
        nxt[0].islower() or bool(re.search(r"[,-]$|\b(?:the|and|or|to|of|a|an|with)$", left))
        for left, nxt in itertools.pairwise(lefts)
    )
    return terms * 3 >= 2 * len(lefts) and runs_on * 2 < len(lefts) - 1


def _reading_order(lines: list[str]) -> tuple[list[str], list[int]]:
    """The lines in reading order, each with its 1-based number in the text: prose set in two
    columns side by side ("5.2 Spin Press the SPIN button to     Spin: no final spin; the…") is
    read down the left column, then down the right one. A block counts as two columns when
    three or more lines in a row split at one place by a wide gap into two parts of running
    text (a table's cells are short; a drawing's are words in capitals)."""
    splits: list[tuple[int, str, str] | None] = []
    for line in lines:
        found = None
        if "|" not in line:
            for m in re.finditer(r"\S(\s{3,})(?=\S)", line):
                left, right = line[: m.start(1)].strip(), line[m.end(1) :].strip()
                if len(left) >= 18 and len(right) >= 18 and not re.search(r"\s{2,}", right):
                    found = (m.end(1), left, right)
                break
        splits.append(found)

    def at(k: int, column: int) -> tuple[int, str, str] | None:
        """Line k split by a gap of two or more spaces ending near ``column``."""
        if splits[k] is not None and abs(splits[k][0] - column) <= 8:  # type: ignore[index]
            return splits[k]
        for m in re.finditer(r"\S(\s{2,})(?=\S)", lines[k]):
            if abs(m.end(1) - column) <= 8 and "|" not in lines[k]:
                left, right = lines[k][: m.start(1)].strip(), lines[k][m.end(1) :].strip()
                plain = not re.search(r"\s{2,}", left + "\n" + right)
                if len(left) >= 10 and len(right) >= 10 and plain:
                    return (m.end(1), left, right)
        return None

    out: list[str] = []
    numbers: list[int] = []
    i = 0
    column = 0  # the gap of the block just read: the next section's block may share it
    while i < len(lines):
        first = splits[i] or (at(i, column) if column else None)
        parts: list[tuple[int, str, str]] = []
        j = i
        while j < len(lines) and first is not None:
            here = at(j, first[0])
            if here is None or (j > i and re.match(r"\d{1,2}\.\d{1,2}\.?\s+[A-Z]", here[1])):
                break  # a numbered section starting on the left begins a block of its own
            parts.append(here)
            j += 1
        prose = sum(bool(re.search(r"[a-z]{3,} [a-z]{3,}", p[1] + " " + p[2])) for p in parts)
        if j - i >= 3 and prose * 3 >= 2 * (j - i) and not _legend(parts):
            out += [p[1] for p in parts] + [p[2] for p in parts]
            numbers += [k + 1 for k in range(i, j)] * 2
            i, column = j, parts[0][0]
        else:
            out.append(lines[i])
            numbers.append(i + 1)
            i += 1
            column = 0  # only the line right after a block may go on with its gap
    return out, numbers


def parse_manual(text: str) -> Manual:
    """Split a manual into units; raise :class:`ReaderError` for input that is not text."""
    if not isinstance(text, str):
        raise ReaderError(f"a manual is text, got {type(text).__name__}")
    if len(text) > MAX_MANUAL_CHARS:
        raise ReaderError(
            f"the manual has {len(text):,} characters; the reader accepts at most "
            f"{MAX_MANUAL_CHARS:,}"
        )
    text = text.replace("\r\n", "\n").replace("\r", "\n").replace("\f", "\n\f\n")
    text = _clean_chars(re.sub(r" ?❄ ?", " ❄ ", text))  # one space each side, not two
    text = _LEADER_RE.sub("    ", text)  # "Timer ........ 0:00 - 99:59": a gap between columns
    original = text.split("\n")
    raw_lines, line_numbers = _reading_order(original)
    units: list[Unit] = []
    heading = ""
    header: tuple[str, ...] = ()
    ruled: tuple[str, ...] = ()  # the header of the table whose rule has been read
    para: list[tuple[int, str]] = []
    para_bullet = False
    para_step: int | None = None

    def flush() -> None:
        nonlocal para, para_bullet, para_step
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

    fenced = False
    spaced = _space_tables(raw_lines)
    sideways = _row_charts(raw_lines)
    furniture = _furniture(raw_lines)
    passed = _page_breaks(raw_lines, furniture)
    previous, last = "", 0
    for position, raw in enumerate(raw_lines, start=1):
        number = line_numbers[position - 1]
        if position - 1 in passed or position - 1 in furniture:
            continue
        # after a page break passed over, a line in capitals may start a new section
        before, previous = ("" if position > last + 1 else previous), raw.strip()
        last = position
        if position - 1 in sideways:  # a chart printed sideways: turned upright
            flush()
            chart = sideways[position - 1]
            for row in chart:
                rows_header = chart[0] if row is not chart[0] else ()
                units.append(Unit(number, " | ".join(row), row, rows_header, heading=heading))
            continue
        if position in spaced:
            flush()
            cells, is_header = spaced[position]
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
            continue
        plain = (
            not stripped.startswith(("#", "-", "*", ">"))
            and (not before or re.search(r"[.!?:]$", before) or _plain_heading(before))
            and _plain_heading(stripped)
        )
        if stripped.startswith("#") or plain:
            flush()
            header = ()
            heading = stripped.lstrip("#").strip()
            units.append(Unit(number, heading, heading=heading))
            continue
        if "|" in stripped and stripped.count("|") >= 2:
            flush()
            if _TABLE_RULE.match(stripped):
                if header and header != ruled:  # the rows above a table's first rule: header
                    header = ruled = _header_lines(units, header)
                continue
            cells = tuple(c.strip() for c in stripped.strip("|").split("|"))
            if not header:
                header = cells
                units.append(Unit(number, " | ".join(cells), cells, (), heading=heading))
            else:
                units.append(Unit(number, " | ".join(cells), cells, header, heading=heading))
            continue
        header = ()
        bullet = _BULLET_RE.match(line)
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
        if para and (_TERM_RE.match(line) or _FIELD_RE.match(line)):
            flush()  # "WARM      holds cooked food hot": a term and its definition, a new item
        para.append((number, stripped))
    flush()
    return Manual(units, original)


_LEADER_RE = re.compile(r"(?<=\S)[ \t]*(?:\.[ \t]?){4,}[ \t]*(?=\S)")
_FIELD_RE = re.compile(  # "Water level: …", "Cup-size lamps: …": a field of its own
    r"^\s{0,2}[A-Z][a-z]+(?:-[a-z]+)?(?:[ -][A-Za-z]+){0,3}(?: \([^)]{1,30}\))?:\s+\S"
)
_TERM_RE = re.compile(  # "TEMP knob     Sets …", "SET 60°C     Set temperature": a term
    r"^\s{0,2}[A-Z0-9](?:[A-Z0-9+/&.'°-]|(?<=[\d-]):(?=[\d-]))*"  # a colon only in 01:30, --:--
    r"(?: (?:[A-Z0-9+/&.'°-]|(?<=[\d-]):(?=[\d-]))+){0,3}"
    r"(?: (?:knob|dial|button|key|switch|lever|selector|wheel|ring|lamp|indicator)s?)?\s{2,}\S"
)
