"""Second looks at what evidence.py read about a control: whether a list is the setting's
values or only where it applies ("(STEW, JAM only)"), a table of amounts as a range, and the
settings a scale's printed marks imply (a click halfway between marks, every minute up to ten).
Apart from evidence.py because each is a small rule on one list or table, not the reading loop.
"""

from __future__ import annotations

import itertools
import math
import re

from apbot.read.labels import words
from apbot.read.text import Unit
from apbot.read.values import UNIT, Range, number, unit_name

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


# "cannot be used on", "is not available with", "does not work for": what follows is where the
# setting is missing
_EXCLUDED_BEFORE_RE = re.compile(
    r"\b(?:cannot|can\s?not|can't|not|never)\s+(?:be\s+)?(?:used|set|available|possible|"
    r"selected|chosen|work)\s+(?:on|with|for|in|at)\s+(?:the\s+)?(?:programmes?\s+|menus?\s+)?$",
    re.IGNORECASE,
)


def excluded_list(items: list[str], text: str) -> bool:
    """A list the sentence names as where the setting cannot be used ("PRESET cannot be used
    on QUICK, STEAM or CAKE"): the other menus' names, never the setting's own values."""
    first = re.search(rf"(?<!\w){re.escape(items[0].strip())}(?!\w)", text, re.I)
    return bool(
        first and _EXCLUDED_BEFORE_RE.search(text[max(0, first.start() - 60) : first.start()])
    )


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
# "above 10 the knob clicks at each small mark", "small marks between the printed numbers",
# "between two numbers it also clicks at a small mark"; not one mark named ("turn it back
# until it stops at the small mark beside 0") nor marks drawn ("settings shown by short lines")
_SMALL = r"(?:small|intermediate|minor|short)"
_SMALL_MARK_RE = re.compile(
    r"\b(?:clicks?|detents?|stops?|notch(?:es)?|settings?|engages?)\b[^.;]{0,40}"
    rf"\b(?:at|on|into)\s+(?:(?:each|every)\s+{_SMALL}\s+(?:mark|tick|line|division)\b"
    rf"|(?:the\s+|all\s+)?{_SMALL}\s+(?:marks|ticks|lines|divisions)\b)"
    rf"|\b{_SMALL}\s+(?:marks|ticks|lines)\s+between\b"
    rf"|\bbetween\b[^.;]{{0,60}}\b(?:clicks?|stops?|detents?)\b[^.;]{{0,30}}\b{_SMALL}\s+"
    r"(?:mark|tick|line)",
    re.I,
)


def between_marks(text: str) -> bool:
    """Whether a sentence says the knob also stops halfway between two printed marks."""
    return bool(_BETWEEN_RE.search(text) or _SMALL_MARK_RE.search(text))


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
SENTENCE_END_RE = re.compile(r"(?<=[.;!?])\s+")


def _every_minute_top(text: str) -> float | None:
    """The bound of a run of one-minute settings a sentence describes, else None."""
    for sentence in SENTENCE_END_RE.split(text):
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
    parsed = [re.match(r"\s*(\d+(?:\.\d+)?)\s*(.*)", v) for v in items]
    if not all(parsed):
        return items
    # (a halfway mark below the bound is one of those minutes: 2.5 between 0 and 5 is no setting)
    nums = sorted(
        {v for m in parsed if m if (v := float(m.group(1))) >= top or v == int(v)}
        | set(range(top + 1))
    )
    unit = next((m.group(2) for m in parsed if m and m.group(2)), "")
    return [f"{v:g}" + (f" {unit}" if unit else "") for v in nums]


def lettered_row(units: list[Unit], names: set[str]) -> tuple[list[str], int] | None:
    """The row of marks printed over a key that a legend names by a letter ("| B | Temperature
    key | …" and "The lamp rows over keys B and C read: B:  90   60   40   COLD  C:  1400 …"):
    the marks after its letter, split at wide gaps, glosses in brackets dropped; and the unit
    they stand in. ``names`` are the key's words (action word, printed label)."""
    for row in units:
        if len(row.cells) < 2 or not row.header or not re.fullmatch(r"[A-Z]", row.cells[0]):
            continue
        first = (words(row.cells[1]) or [""])[0]
        if len(first) < 3 or not any(first[:4] == n[:4] for n in names if len(n) >= 3):
            continue
        marks = re.compile(rf"(?<![\w.]){row.cells[0]}:\s+(.+?)(?=\s+[A-Z]:\s|$)")
        for k, unit in enumerate(units):
            m = None if unit.cells else marks.search(unit.text)
            if not m:
                continue
            items = [re.sub(r"\s*\([^)]*\)", "", c).strip() for c in re.split(r"\s{2,}", m[1])]
            items = [i for i in items if i]
            if len(items) >= 3 and all(len(i) <= 20 for i in items):
                return items, k
    return None


_USED_KEY_RE = r"(?:press|presses|pressing|touch|tap|push|hold|turn|turning|rotate)\s+(?:the\s+)?"


def about_another(text: str, others: set[str]) -> bool:
    """Whether a sentence is about another setting: it names one (a name with a word of three
    letters or more) other than as the key pressed or turned ("The cook time changes by 1 minute
    …" is the cook time's; "Press + or −. Up to 2 hours …" and "turn the dial" only use keys)."""
    for name in others:
        if not any(len(w) >= 3 for w in words(name)):
            continue
        for m in re.finditer(rf"(?<![\w-]){re.escape(name)}(?![\w-])", text, re.I):
            if not re.search(rf"\b{_USED_KEY_RE}$", text[: m.start()], re.I):
                return True
    return False
