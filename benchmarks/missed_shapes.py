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
