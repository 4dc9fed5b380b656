"""Tables a PDF converter drew with spaces, and charts printed sideways, turned into cells.

Split out of ``text.py`` (which turns a manual into units) because finding a table in text laid
out with spaces is a job of its own: column positions, wrapped cells, elided rows.
"""

from __future__ import annotations

import re


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
    # a gap before a comma is no column break: a symbol dropped from "Warm ▣, Hot" left it
    return tuple(c for c in re.split(r"\s{2,}(?![,;])|\t+", _strip_markup(line).strip()) if c)


def _caption(lines: list[str], k: int, breaks: set[int] | None = None) -> bool:
    """A short line standing alone above a table ("Steam chart (continued overleaf)"): a
    caption, which no table header goes on from as a sentence would. A blank line of a page
    break passed over (``breaks``) does not set it apart: the text runs on across the page."""
    line = lines[k].strip()
    alone = k == 0 or (not lines[k - 1].strip() and k - 1 not in (breaks or set()))
    return alone and len(line) <= 60 and len(_cells(line)) == 1 and not line.endswith(",")


# a callout printed beside a part of the drawing: "①", "❸", "(4)"
CALLOUT_RE = re.compile(r"[①-⑳❶-❿➀-➉]|\(\d{1,2}\)")


def _uncalled(cells: tuple[str, ...]) -> tuple[str, ...]:
    """A legend row's cells without its callout ("①", "M", "Hold …" → "M", "Hold …")."""
    return cells[1:] if len(cells) > 2 and CALLOUT_RE.fullmatch(cells[0]) else cells


def _space_tables(
    lines: list[str], breaks: set[int] | None = None
) -> dict[int, tuple[tuple[str, ...], bool | None]]:
    """Tables drawn with spaces (text from a PDF): a header of three or more cells followed by
    rows of two or more, or a header of two short column names over rows whose second cell
    starts under the header's; a row's wrapped lines (set in from the left) go on its cells. A page
    break (``breaks``: 0-based lines the page layout passes over) inside a table — often right
    under its header — is passed over when a row follows it.

    A table whose first line is led by a callout ("①  M   Hold for 2 seconds: …") is a legend
    of the panel drawing: it has no header, that line is its first row, and each row's callout
    is left out, so the key's name leads its row.

    Returns line number → (cells, is the header row; None for the first row of a legend)."""
    breaks = breaks or set()
    whole = set(re.findall(r"[A-Z]+", "\n".join(lines).upper()))  # words printed unbroken
    out: dict[int, tuple[tuple[str, ...], bool | None]] = {}
    i = 0
    while i < len(lines):
        head = _cells(lines[i])
        before = lines[i - 1].strip() if i else ""
        if (
            before
            and not re.fullmatch(r"[-=_][-=_\s]{2,}", before)  # a rule above a header
            and not re.search(r"[.:!?]$", before)
            and not before.isupper()
            and not before.startswith("#")  # a Markdown heading ends what came before
            and not _caption(lines, i - 1, breaks)
        ):
            i += 1  # the line goes on with a sentence from the line before: not a table header
            continue
        head = _unnamed_first(lines, i, head)
        two = len(head) == 2 and _two_column_head(head)
        if (len(head) < 3 and not two) or "|" in lines[i] or len(lines[i]) > 200:
            i += 1
            continue
        column = _placed_cells(lines[i])[-1][0] if two else 0
        rows: list[int] = []
        spans: list[tuple[int, int]] = []  # the columns a rule under the header marks
        more: dict[int, list[tuple[int, str]]] = {}  # row -> wrapped lines' cells, by position
        indent = len(lines[i]) - len(lines[i].lstrip())
        j = i + 1
        while j < len(lines):
            if j in breaks or not lines[j].strip():
                k = next(
                    (k for k in range(j, len(lines)) if not _passed(lines, k, breaks)), len(lines)
                )
                # a blank line, then a drawn line and page furniture: only a full row goes on
                paged = j in breaks or (
                    any(m in breaks for m in range(j, k))
                    and k < len(lines)
                    and len(_cells(lines[k])) >= max(3, len(head) - 1)
                )
                if (
                    paged
                    and k < len(lines)
                    and "|" not in lines[k]
                    and _lines_up(lines[i], lines[k])
                ):
                    j = k  # the table goes on over the page break
                    continue
                break
            if re.fullmatch(r"[-=_][-=_\s]{2,}", lines[j].strip()):
                spans = spans or rule_spans(lines[j])  # (its runs of dashes: the columns)
                j += 1  # a rule under the header ("-------  ------  -----")
                continue
            cells = _cells(lines[j])
            inset = len(lines[j]) - len(lines[j].lstrip()) > indent + 2
            if inset and "|" not in lines[j]:  # a wrapped line: of the header, or of a row
                more.setdefault(rows[-1] if rows else i, []).extend(_placed_cells(lines[j]))
            elif two and (len(cells) != 2 or abs(_placed_cells(lines[j])[-1][0] - column) > 2):
                break  # a two-column table's rows keep its second column under the header's
            elif len(cells) >= 2 and "|" not in lines[j]:
                rows.append(j)
            elif len(cells) != 1 or len(cells[0]) > 40:
                break
            j += 1
        if two and (more or not _two_column_rows(lines, rows, j)):
            rows = []
        if len(rows) >= 2:
            head_cells = _joined_cells(lines[i], more.get(i, []), whole)
            if not head[0] and head_cells[0]:
                head_cells = ("", *head_cells)
            legend = bool(CALLOUT_RE.fullmatch(head_cells[0]))  # "①  M   Hold 2 s: …": a row
            out[i + 1] = (_uncalled(head_cells), None) if legend else (head_cells, True)
            for r in rows:
                cells = _joined_cells(lines[r], more.get(r, []), whole, spans)
                out[r + 1] = (_uncalled(cells) if legend else cells, False)
            for k in range(i + 1, j):
                out.setdefault(k + 1, ((), False))
            i = j
        else:
            i += 1
    return out


def _passed(lines: list[str], k: int, breaks: set[int]) -> bool:
    """A line of a page break a table goes on over: one the page layout passes over, or a
    blank or drawn line ("-------" under the page's footer) that follows them."""
    return k in breaks or not re.search(r"[^\W_]", lines[k])


def _unnamed_first(lines: list[str], i: int, head: tuple[str, ...]) -> tuple[str, ...]:
    """A header whose first column has no name ("            Model 3     Model 6" over
    "Power       550 W       900 W"): its cells start under the rows' second and later
    cells, so it heads those, and the first column's name is empty."""
    if len(head) < 2:
        return head
    j = i + 1
    while j < len(lines) and re.fullmatch(r"[-=_][-=_\s]{2,}", lines[j].strip()):
        j += 1
    if j >= len(lines) or len(_cells(lines[j])) != len(head) + 1:
        return head
    starts = [at for at, _ in _placed_cells(lines[i])]
    placed = [at for at, _ in _placed_cells(lines[j])]
    if starts[0] > placed[0] + 4 and all(
        any(abs(at - s) <= 2 for at in placed[1:]) for s in starts
    ):
        return ("", *head)
    return head


def _two_column_head(cells: tuple[str, ...]) -> bool:
    """Two short column names ("Key   What it does", "Roast   Suggested temperature"): no
    sentence, no item of a key legend ("TEMP   Sets the temperature." ends in a stop; a
    definition starts in lower case), no number in the first (a row of a display legend; a
    model's name may head the second column: "Item   TL-70")."""
    return not re.search(r"\d", cells[0]) and all(  # ("SET 60°C   Set temperature": a row)
        len(cell) <= 25
        and len(cell.split()) <= 4
        and re.match(r"[A-Z]", cell)
        and not re.search(r"[.!?:;,]$", cell)
        for cell in cells
    )


def _two_column_rows(lines: list[str], rows: list[int], end: int) -> bool:
    """Rows of a two-column table stand alone: the block ends at a blank line, and no row goes
    on with the row above (a first cell "(flame)" or one in lower case is a wrapped legend,
    read as running text, as is one with lines set in under a row)."""
    if end < len(lines) and lines[end].strip():
        return False
    return not any(re.match(r"[(a-z]", _cells(lines[r])[0]) for r in rows)


def _lines_up(head: str, row: str) -> bool:
    """Whether a line after a page break is a row of the table headed by ``head``: as many
    cells as the header, or each cell starting under one of the header's. A key legend on the
    next page ("TEMP   Changes the wash temperature.") is two cells of its own layout."""
    cells = _cells(row)
    if len(cells) < 2:
        return False
    if len(cells) == len(_cells(head)):
        return True
    starts = [at for at, _ in _placed_cells(head)]
    placed = [at for at, _ in _placed_cells(row)]
    if all(any(abs(at - s) <= 2 for s in starts) for at in placed):
        return True
    # a row with a column the header left unnamed ("Steam ●" under no head): all but one of
    # the header's columns, at least two, have a cell starting under them
    under = sum(any(abs(at - s) <= 2 for at in placed) for s in starts)
    return under >= max(2, len(starts) - 1)


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
    return [(m.start(), m.group(0)) for m in re.finditer(r"\S+(?:(?: |\s{2,}(?=[,;]))\S+)*", body)]


def rule_spans(line: str) -> list[tuple[int, int]]:
    """The columns a rule under a table's header marks, one run of dashes each ("-------
    ------  -----"): where each column starts and ends."""
    return [(m.start(), m.end()) for m in re.finditer(r"[-=_]{2,}", line)]


def _within_rule(
    placed: list[tuple[int, str]], spans: list[tuple[int, int]]
) -> list[tuple[int, str]]:
    """A row's pieces, those that start inside one column of the rule joined into its cell
    ("automatic  ✗" under one run of dashes: one cell), when the row has more pieces than the
    rule has columns; else the pieces as they are."""
    if len(spans) < 2 or len(placed) <= len(spans):
        return placed
    merged: list[tuple[int, str]] = []
    column = -1
    for at, text in placed:
        inside = max((n for n, (start, _) in enumerate(spans) if start <= at + 1), default=0)
        if merged and inside == column and inside > 0:  # (a lead cell "a  ROOM": callout, name)
            merged[-1] = (merged[-1][0], f"{merged[-1][1]} {text}")
        else:
            merged.append((at, text))
        column = inside
    return merged


def _joined_cells(
    line: str,
    wrapped: list[tuple[int, str]],
    whole: frozenset[str] | set[str] = frozenset(),
    spans: list[tuple[int, int]] | None = None,
) -> tuple[str, ...]:
    """A row's cells with the text of its wrapped lines added to the cell each piece stands
    under ("To activate and deactivate the" + "hob."); ``spans``: the columns the rule under
    the header marks, which a cell's inner gap does not split."""
    placed = _placed_cells(line)
    ruled = _within_rule(placed, spans or [])
    if not wrapped and ruled is not placed:
        return tuple(text for _, text in ruled)
    placed = ruled
    if not wrapped or not placed:
        return _cells(line)
    cells = [text for _, text in placed]
    for at, text in wrapped:
        k = max((n for n, (start, _) in enumerate(placed) if start <= at + 2), default=0)
        if re.search(r"[A-Za-z]-$", cells[k]) and text[:1].isalpha():
            # "PRE-" over "WASH": one word where the manual prints it whole elsewhere
            # ("PREWASH"), else a compound keeping its hyphen ("EXTRA-RINSE", "TIME-DELAY")
            broken = re.search(r"[A-Za-z]+-$", cells[k])
            one = f"{broken[0][:-1] if broken else ''}{re.split(r'[^A-Za-z]', text)[0]}"
            cut = 1 if one.upper() in whole else 0
            cells[k] = f"{cells[k][: len(cells[k]) - cut]}{text}"
        else:
            cells[k] = f"{cells[k]} {text}"
    return tuple(cells)
