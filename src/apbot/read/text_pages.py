"""Page layout: running headers and footers, page breaks, plain headings and reading order.

Split out of ``text.py`` (which turns a manual into units): text flattened out of a PDF carries
page furniture and side-by-side blocks that must be dropped or put in order before the lines
become sentences.
"""

from __future__ import annotations

import itertools
import re

from apbot.read.text_tables import _cells, _two_column_head

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


# one entry of a table of contents: a title, a dot leader and a page number ("Keep warm ...... 7")
_CONTENTS_ENTRY = re.compile(r"\S.*?(?:\.[ \t]?){4,}[ \t]*(\d{1,3})(?=\s{2,}\S|\s*$)")


def contents_lines(lines: list[str]) -> set[int]:
    """The lines of a table of contents (0-based): a run of three or more lines, each made of
    entries that end in a dot leader and a page number ("Special functions: ECO, SUPER ....
    9"; two entries side by side in a two-column contents), the pages never going back. Its
    titles name chapters and keys, but say nothing about what a key sets: a title's list of
    functions is no value list."""
    out: set[int] = set()
    run: list[int] = []
    pages: list[int] = []

    def close() -> None:
        if len(run) >= 3 and pages == sorted(pages) and (_headed(lines, run[0]) or _paged(pages)):
            out.update(run)
        run.clear()
        pages.clear()

    for i, line in enumerate([*lines, ""]):
        stripped = line.strip()
        # a dot leader has four dots with at most a space or tab between: the pattern's
        # lazy title scan is slow on long lines, so lines without one are passed over
        leader = "...." in stripped.replace(" ", "").replace("\t", "")
        entries = list(_CONTENTS_ENTRY.finditer(stripped)) if leader else []
        if entries and "".join(m.group(0) for m in entries).replace(" ", "") == stripped.replace(
            " ", ""
        ):
            run.append(i)
            pages.append(int(entries[0].group(1)))
        elif stripped or not run:
            close()
    close()  # a run the text ends with
    return out


_CONTENTS_HEAD = re.compile(
    r"^\W*(?:table\s+of\s+)?(?:contents?|index)\b|^\W*in\s+this\s+(?:manual|booklet)\b",
    re.IGNORECASE,
)


def _headed(lines: list[str], first: int) -> bool:
    """A contents heading ("Contents", "TABLE OF CONTENTS", "Index") among the two written lines
    above a run of leader lines."""
    above = [line for line in lines[max(0, first - 4) : first] if line.strip()][-2:]
    return any(_CONTENTS_HEAD.match(line.strip()) for line in above)


def _paged(pages: list[int]) -> bool:
    """Numbers that read as pages without a heading: five or more, from an early page, a few
    pages apart. A chart with dot leaders ("Steam ...... 120": minutes, watts) counts up in
    bigger steps, or from further on, or has fewer rows; a dial's positions count one by one."""
    steps = [b - a for a, b in itertools.pairwise(pages)]
    counted = set(steps) == {1}  # "Cotton ..... 1", "Wool ..... 2": dial positions, not pages
    return len(pages) >= 5 and pages[0] <= 10 and max(steps) <= 6 and not counted


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
    # "EXAMPLES (after switching on)": a title in capitals and a short remark in brackets
    title = re.sub(r"\s+\([a-z][^()]{0,30}\)$", "", rest)
    if _CAPS_HEADING.fullmatch(title) and len(title.split()) <= 7 and len(title) >= 3:
        return True
    sub_level = bool(number and re.match(r"\d{1,2}\.\d", stripped))
    # "2  Grinding": a PDF's section number set apart from its title by a wide gap, which a
    # numbered step ("2. Rinse the jar") or a list's item never is
    spaced = bool(re.match(r"\d{1,2}\s{2,}\S", stripped)) and len(rest.split()) <= 4
    short = len(rest.split()) <= 6  # a title, not a sentence run on after it
    titled = rest[0].isupper() and not re.search(r"\d", rest)
    return (sub_level or spaced) and short and titled


_TITLE_SMALL = {"of", "and", "the", "for", "to", "a", "an", "in", "on", "&"}


def _page_title(line: str) -> bool:
    """A page's first line written as a title in Title Case ("Control Panel", "Names of Parts"):
    a plain-text manual's section heading, which names no capitals to tell it by; without it the
    heading before the break ("CAUTION" of the safety pages) would hold for the whole manual."""
    ws = line.split()
    if (
        not 1 <= len(ws) <= 5
        or not 3 <= len(line) <= 40
        or re.search(r"\d|\s{2,}|[.:;,!?|]$", line)
    ):
        return False
    return ws[0][:1].isupper() and all(w[:1].isupper() or w in _TITLE_SMALL for w in ws)


# a word no line of a sentence ends on: the next line goes on with it (a page's, a table cell's)
OPEN_ENDS = _TITLE_SMALL | {"then", "or", "with", "by", "at", "from", "until", "press"}
OPEN_ENDS |= {"than", "into", "when", "if"}


def _unfinished(line: str) -> bool:
    """A line that stops mid-sentence (a comma, a hyphen, "…, then"): the page after it goes
    on with the sentence, and its first line ("Press START") is no page title."""
    words = line.rstrip().split()
    return bool(words) and (line.rstrip()[-1] in ",-–" or words[-1].lower() in OPEN_ENDS)


def _running_titles(lines: list[str]) -> set[int]:
    """A title heading two or more pages alike ("Owner's Manual" after each rule): the running
    header a PDF prints on every page, no section; were it read as one, it would cut a
    procedure running over the page in two and hide the headings under it (0-based lines)."""
    tops: dict[str, list[int]] = {}
    ruled = True  # (the first line of the text heads its first page)
    for i, line in enumerate(lines):
        stripped = line.strip()
        if not stripped:
            continue
        if "\f" in line or re.fullmatch(r"[-=_*~`#]{3,}", stripped):
            ruled = True
            continue
        if ruled and _page_title(stripped):
            tops.setdefault(stripped, []).append(i)
        ruled = False
    return {i for at in tops.values() if len(at) >= 2 for i in at}


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


def _column_head(line: str, column: int) -> bool:
    """A line of two short column names split at ``column`` ("Key      Use"): the lines under
    it are a table's rows, not prose set side by side."""
    cells = _cells(line)
    gap = re.search(r"\S(\s{2,})(?=\S)", line)
    return (
        len(cells) == 2
        and gap is not None
        and abs(gap.end(1) - column) <= 2
        and _two_column_head(cells)
    )


def _left_runs_on(above: str) -> int:
    """How long the left part of the line under ``above`` must be to be a column's: any
    length when the left column's line above runs on to it (a sentence ends there, "Default:"
    then "MEDIUM."), else ten characters."""
    return 1 if re.search(r"[a-z,:]\s{3,}\S", above) else 10


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

    def at(k: int, column: int, short: int = 10) -> tuple[int, str, str] | None:
        """Line k split by a gap of two or more spaces ending near ``column`` (a left part
        shorter than ``short`` characters is no column's)."""
        if splits[k] is not None and abs(splits[k][0] - column) <= 8:  # type: ignore[index]
            return splits[k]
        for m in re.finditer(r"\S(\s{2,})(?=\S)", lines[k]):
            if abs(m.end(1) - column) <= 8 and "|" not in lines[k]:
                left, right = lines[k][: m.start(1)].strip(), lines[k][m.end(1) :].strip()
                plain = not re.search(r"\s{2,}", left + "\n" + right)
                # (a paragraph's last line in the left column may be short: "MEDIUM.")
                if len(left) >= short and len(right) >= 10 and plain:
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
            here = at(j, first[0], 10 if j == i else _left_runs_on(lines[j - 1]))
            if here is None or (j > i and re.match(r"\d{1,2}\.\d{1,2}\.?\s+[A-Z]", here[1])):
                break  # a numbered section starting on the left begins a block of its own
            parts.append(here)
            j += 1
        prose = sum(bool(re.search(r"[a-z]{3,} [a-z]{3,}", p[1] + " " + p[2])) for p in parts)
        headed = bool(parts) and i > 0 and _column_head(lines[i - 1], parts[0][0])
        if j - i >= 3 and prose * 3 >= 2 * (j - i) and not _legend(parts) and not headed:
            out += [p[1] for p in parts] + [p[2] for p in parts]
            numbers += [k + 1 for k in range(i, j)] * 2
            i, column = j, parts[0][0]
        else:
            out.append(lines[i])
            numbers.append(i + 1)
            i += 1
            column = 0  # only the line right after a block may go on with its gap
    return out, numbers
