"""The SHAPES the missed-settings diagnostic sorts manual lines into (measuring only).

Split from :mod:`benchmarks.missed_settings` so that module keeps one job (reading each appliance
and counting which settings were missed, and why) while this one holds the other: naming, in the
diagnostic's fixed vocabulary, how a manual line looks — a table row and its cells, a list item, a
heading, prose; what it holds (time digits, a range, "or", commas …); where a key's word stands
from it; how the values are printed. The names are fixed marks, never the manual's words, so the
tables may be printed over the held-out categories in aggregate.
"""

from __future__ import annotations

import re

from apbot.read.drawn_pieces import drawn_piece_marks
from apbot.read.text import Unit, parse_manual


def value_shape(manual: str, names: list[str]) -> str:
    """How the manual writes a setting's values: the shape of the line holding most of them."""
    best, line = _most_named(manual, names)
    line = line.strip()
    if best == 0:
        return "inside-words"
    together = "one-line" if best == len(names) else "spread"
    if line.count("|") >= 2:
        shape = "table-row"
    elif re.match(r"([-*•·▪●○◦]|\d+[.)]|\(?[a-z]\))\s", line):
        shape = "list-item"
    elif line.startswith("#") or line.isupper():
        shape = "heading"
    else:
        shape = "prose"
    return f"{shape}/{together}"


_TIME_DIGITS = re.compile(r"\d\s*(?:h|hrs?|hours?|min|mins|minutes?|s|sec|secs|seconds?)\b", re.I)
_RANGE = re.compile(r"\d\s*(?:[-–—~]|to)\s*\d|\d\s*\.\.\s*\d", re.I)


def line_shape(line: str) -> str:
    """A line's shape as '+'-joined marks: where it sits (table / item / heading / prose) and what
    it holds (time digits, a range, parentheses, an "or", commas, a colon)."""
    text = line.strip()
    if not text:
        return "none"
    if text.count("|") >= 2:
        place = "table"
    elif re.match(r"([-*•·▪●○◦]|\d+[.)]|\(?[a-z]\))\s", text):
        place = "item"
    elif text.startswith("#") or (text.isupper() and len(text) < 60):
        place = "heading"
    else:
        place = "prose"
    marks = [place]
    marks += ["timedig"] if _TIME_DIGITS.search(text) else []
    marks += ["range"] if _RANGE.search(text) else []
    marks += ["paren"] if re.search(r"\([^)]*\)", text) else []
    marks += ["or"] if re.search(r"\bor\b|/", text) else []
    marks += ["commas"] if text.count(",") >= 2 else []
    marks += ["arrows"] if re.search(r"[→►▶▸>»]|->", text) else []
    marks += ["and"] if re.search(r"\band\b|&", text) else []
    marks += ["dashes"] if re.search(r"\w\s+[-–—]\s+\w", text) else []
    marks += ["dots"] if re.search(r"[·•]", text) else []
    marks += [f"cells{text.strip('|').count('|') + 1}"] if place == "table" else []
    marks += ["semicolons"] if ";" in text else []
    marks += ["quotes"] if re.search(r"[\"“”‘’']\w", text) else []
    return "+".join(marks)


def note_kind(what: str) -> str:
    """The kind of a note in the reader's own fixed phrasing (never the manual's words, which a
    values note quotes): a range, an on/off, a list of values, a start, a guess of placeholders."""
    low = what.lower()
    for prefix, kind in (
        ("range", "range"),
        ("an on/off", "onoff"),
        ("a cooking time", "typed-time"),
        ("a clock", "clock"),
        ("starts at", "start"),
        ("the appliance runs", "running"),
        ("the quantity", "pair-quantity"),
    ):
        if low.startswith(prefix):
            return kind
    return "values-or-other"


def _most_named(manual: str, names: list[str]) -> tuple[int, str]:
    """The first line naming the most of ``names``, with how many it names (0, "" for none)."""
    best, line = 0, ""
    for candidate in manual.splitlines():
        low = candidate.lower()
        hits = sum(1 for name in names if re.search(rf"(?<![a-z]){re.escape(name)}(?![a-z])", low))
        if hits > best:
            best, line = hits, candidate
    return best, line


def values_line(manual: str, names: list[str]) -> str:
    """The line naming most of ``names`` (the one :func:`value_shape` judges)."""
    return _most_named(manual, names)[1]


def key_place(manual: str, line: str, keys: set[str]) -> str:
    """Where the values' line stands from the keys that set them: a key word on the line itself
    (``key-on``), within five lines (``key-near``), or further (``key-far``); and whether the
    line holds all the values (``one``) or some (``some``) — counted by :func:`values_line`."""
    words = {w for key in keys for w in key.lower().split("_") if len(w) >= 3}
    words -= {"press", "hold", "turn", "button", "key", "knob", "long", "short", "dial"}
    lines = manual.splitlines()
    at = lines.index(line)
    near = " ".join(lines[max(0, at - 5) : at + 6]).lower()
    has = lambda text: any(re.search(rf"(?<![a-z]){re.escape(w)}", text) for w in words)  # noqa: E731
    return "key-on" if has(line.lower()) else "key-near" if has(near) else "key-far"


def written_case(line: str, names: list[str]) -> str:
    """How the values are printed on their line: all in CAPITALS, Titled, lower case, mixed."""
    cases = set()
    for name in names:
        m = re.search(rf"(?<![A-Za-z]){re.escape(name)}(?![A-Za-z])", line, re.I)
        if m and any(c.isalpha() for c in m.group(0)):
            word = m.group(0)
            cases.add("caps" if word.isupper() else "title" if word[:1].isupper() else "lower")
    return "+".join(sorted(cases)) or "digits"


_KEY_STOPWORDS = {"press", "hold", "turn", "button", "key", "knob", "long", "short", "dial"}


def table_detail(manual: str, line: str, keys: set[str], names: list[str]) -> str:
    """For a values' line that is a table row, how its table is built, as '+'-joined marks: the
    row is the table's header (``hdr``, with ``below0``–``below3`` rows under it) or a row under a
    header of N cells (``rowhN``); where a key's word stands (``k@first`` the whole first cell,
    ``k@first-long`` inside a longer first cell, ``k@later`` another cell, ``k@head`` the header
    only, ``k@none``) and its length (``kw3`` for three letters or fewer); the first cell led by a
    digit (``lead-digit``) or another glyph (``lead-glyph``), left blank (``first-blank``); a cell
    holding a slash (``slash``). ``tab:n/a`` for a line without bars, ``tab:unparsed+…`` for a
    line with bars the reader holds as no table row (:func:`_unparsed_detail`).
    Fixed marks only, so held-out aggregates print no manual words."""
    if not line.strip():
        return "tab:n/a"
    at = manual.splitlines().index(line) + 1
    units = parse_manual(manual).units
    row = next((u for u in units if u.line == at and u.cells), None)
    words = {w for key in keys for w in key.lower().split("_") if len(w) >= 2} - _KEY_STOPWORDS
    if row is None:
        if line.count("|") < 2:
            return "tab:n/a"
        return "tab:unparsed+" + _unparsed_detail(manual.splitlines(), at - 1, units, words, names)
    cells = [c.strip(" *") for c in row.cells]
    marks = []
    if not row.header:
        below = sum(1 for u in units if u.header == row.cells and u.cells)
        marks.append(f"hdr+below{min(below, 3)}")
    else:
        marks.append(f"rowh{len(row.header)}")

    def found(text: str) -> list[str]:
        return [w for w in words if _names_word(text, {w})]

    first = found(cells[0]) if cells else []
    if first:
        alone = cells[0].lower().strip(" .:") in first
        marks.append("k@first" if alone else "k@first-long")
    elif any(found(c) for c in cells[1:]):
        marks.append("k@later")
    elif any(found(c) for c in row.header):
        marks.append("k@head")
    else:
        marks.append("k@none")
    hits = first or [w for c in [*cells[1:], *row.header] for w in found(c)]
    if hits and min(len(w) for w in hits) <= 3:
        marks.append("kw3")
    lead = cells[0][:1] if cells else ""
    if lead.isdigit() and lead.isascii():
        marks.append("lead-digit")
    elif (lead and not lead.isalnum()) or (lead and not lead.isascii() and not lead.isalpha()):
        marks.append("lead-glyph")
    if cells and not cells[0]:
        marks.append("first-blank")
    if any("/" in c for c in cells):
        marks.append("slash")
    return "tab:" + "+".join(marks)


def _unparsed_detail(
    lines: list[str], at: int, units: list[Unit], words: set[str], names: list[str]
) -> str:
    """Why a line with pipes is no table row to the reader, as marks: its pipes at both ends or
    not (``ends2``/``ends1``/``ends0``); the pipe lines around it (``block``N, capped at 5) and
    whether a rule line (``|---|``) stands among them (``rule``/``norule``) and where: above it
    (``rule-above``), right under it (``rule-under``); the unit the reader made of it, if any
    (``unit:sentence`` with its cells none, ``unit:none``); a tab or a run of spaces splitting
    it further (``gaps``); a code fence around it (``fence``) or an indent of four spaces
    (``indent``); then its pieces (:func:`_segments`)."""
    text = lines[at]
    stripped = text.strip()
    ends = int(stripped.startswith("|")) + int(stripped.endswith("|"))
    lo = at
    while lo > 0 and lines[lo - 1].count("|") >= 1:
        lo -= 1
    hi = at
    while hi + 1 < len(lines) and lines[hi + 1].count("|") >= 1:
        hi += 1
    rule = [
        k for k in range(lo, hi + 1) if re.fullmatch(r"\s*\|?[\s:|-]*-{2,}[\s:|-]*\|?\s*", lines[k])
    ]
    where = "norule"
    if rule:
        where = "rule-under" if at + 1 in rule else "rule-above" if rule[0] < at else "rule-below"
    marks = [f"ends{ends}", f"block{min(hi - lo + 1, 5)}", where]
    unit = next((u for u in units if u.line == at + 1), None)
    marks.append("unit:none" if unit is None else "unit:sentence")
    if re.search(r"\t| {3,}", stripped.strip("|")):
        marks.append("gaps")
    if sum(lines[k].lstrip().startswith("```") for k in range(at)) % 2:
        marks.append("fence")
    elif text.startswith("    "):
        marks.append("indent")
    marks.append(_segments(stripped, words, names))
    return "+".join(marks)


def _segments(text: str, words: set[str], names: list[str]) -> str:
    """The pipe-split pieces of a line no table holds: where a key's word stands (``seg@first``
    alone, ``seg@first-long`` with more words, ``seg@later``, ``seg@none``), the first piece's
    punctuation (``colon``, ``brackets``), how many pieces are all capitals (``capsN``), and
    pieces holding two words or more spread by runs of spaces (``spaced``); values named per
    piece (``vper``), the key's piece (``keyat``, :func:`_key_piece`), which of its tokens name
    a value (``hits``), what the reader's drawn-piece rule makes of the line (``drawn:``N or
    ``none``) and blank pieces (``blank``N)."""
    pieces = [p.strip() for p in text.strip("|").split("|")]
    low = [p.lower() for p in pieces]

    if _names_word(low[0], words):
        bare = re.sub(r"[^a-z0-9 ]", " ", low[0]).split()
        where = "seg@first" if len(bare) == 1 else "seg@first-long"
    else:
        where = "seg@later" if any(_names_word(p, words) for p in low[1:]) else "seg@none"
    marks = [where]
    marks += ["colon"] if ":" in pieces[0] else []
    marks += ["brackets"] if re.search(r"[\[\](){}<>]", pieces[0]) else []
    caps = sum(1 for p in pieces if p and p.upper() == p and any(c.isalpha() for c in p))
    marks.append(f"caps{caps}of{len(pieces)}")
    marks += ["spaced"] if any(re.search(r"\S {2,}\S", p) for p in pieces) else []
    named = [sum(1 for n in names if _names_word(p, {n})) for p in low]
    keyed = [k for k, p in enumerate(low) if _names_word(p, words)]
    marks.append("vper" + "-".join(str(n) for n in named))  # values named in each piece
    marks += [f"keyat{keyed[0]}"] if keyed else []
    if keyed:
        marks.append(_key_piece(pieces[keyed[0]], words))
        hits = [int(_names_word(x, set(names))) for x in pieces[keyed[0]].split()]
        marks.append("hits:" + "".join(map(str, hits)))  # which tokens name a value
        hit = drawn_piece_marks(text, set(), words, set())
        marks.append(f"drawn:{len(hit)}" if hit else "drawn:none")
    marks += [f"blank{sum(1 for p in pieces if not p)}"]
    return "+".join(marks)


def _key_piece(piece: str, words: set[str]) -> str:
    """Inside the piece holding a key's word: where the word stands among the piece's tokens
    (``kpos`` first / mid / last), how it is printed (``kcaps`` / ``ktitle`` / ``klower``), and
    the other tokens: in capitals, in lower or Title case, digits, glyphs (``tokC-L-D-G``)."""
    tokens = piece.split()
    at = next((k for k, tok in enumerate(tokens) if _names_word(tok, words)), -1)
    if at < 0:
        return "kpos-split"
    pos = "first" if at == 0 else "last" if at == len(tokens) - 1 else "mid"
    word = tokens[at]
    case = "kcaps" if word.isupper() else "ktitle" if word[:1].isupper() else "klower"
    rest = tokens[:at] + tokens[at + 1 :]
    caps = sum(1 for x in rest if x.isupper() and re.search(r"[A-Z]{2}", x))
    digit = sum(1 for x in rest if re.search(r"\d", x))
    glyph = sum(1 for x in rest if not re.search(r"\w", x))
    low = len(rest) - caps - digit - glyph
    shapes = "_".join(_token_shape(x) for x in tokens)
    return f"kpos-{pos}+{case}+tok{caps}-{low}-{digit}-{glyph}+shape:{shapes}"


def _token_shape(token: str) -> str:
    """A token's shape with its letters and digits hidden: capitals → A, lower case → a,
    digits → 9, each run collapsed ("4H" → 9A, "(P1)" → (A9)); punctuation kept."""
    shape = re.sub(r"[A-Z]+", "A", token)
    shape = re.sub(r"[a-z]+", "a", shape)
    shape = re.sub(r"[0-9]+", "9", shape)
    return re.sub(r"[^\x00-\x7f]", "#", shape)


def _names_word(text: str, words: set[str]) -> bool:
    """Whether ``text`` holds one of ``words`` as a word of its own (any case)."""
    low = text.lower()
    return any(re.search(rf"(?<![a-z]){re.escape(w)}(?![a-z])", low) for w in words)
