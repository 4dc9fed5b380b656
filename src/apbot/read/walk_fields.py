"""What one field of a held walk holds (see ``held_walks``), read from the steps that open it
and set it.

A field is opened by the hold or a short press of the walk's key ("The display shows the run
limit, e.g. t30 s."; "The display shows BIN and the alert level") and set by the stepping pair
or a dial in the step after it, or in the same step. Manuals give its values there in every
shape a setting's values take: a time of day that goes round midnight, a range in a unit, a
printed run of amounts ("20, 30, 45, 60, 90 seconds": uneven stops are pieces), a range of bare
levels ("choose the powder setting (1 to 12)"), the names or codes the pair steps through
("(r1, r2, r3; stops at both ends)"), or a switch the pair turns on and off ("Press ▲ to switch
the key beep on, ▼ to switch it off").
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.roles_lists import _nums, list_range, list_step
from apbot.read.shapes import Evidence
from apbot.read.value_lists import bare_list, find_list
from apbot.read.value_steps import find_step
from apbot.read.values import NUM, UNIT, find_ranges, gap_pieces, unit_name

# "after 23:30 comes 00:00", "After 23:45 the time continues at 00:00": the last time of a day
_DAY_WRAP_RE = re.compile(
    r"\b(?:after|past)\s+([01]?\d|2[0-3]):([0-5]\d)\b[^.;]{0,40}?\b0?0:00\b", re.I
)
# what the display shows on opening a field: "shows the start time", "appears with the length"
_SHOWS_RE = re.compile(
    r"\b(?:shows|displays|appears with|flashes with)\s+the\s+((?:[a-z-]+\s){0,2}?[a-z-]+)"
    r"(?=\s*(?:[,.(]|\bof\b|\bbeing\b|\be\.g\.|$))",
    re.I,
)
# ... also beside the word shown for it, in a walk of several fields: "shows AO and the current
# auto-off time"
_SHOWS_BESIDE_RE = re.compile(
    r"\b(?:shows|displays)\s+(?-i:[A-Z][A-Z0-9]{0,5})\s+and\s+the\s+((?:[a-z-]+\s){0,2}?[a-z-]+)"
    r"(?=\s*(?:[,.(]|\bof\b|\bbeing\b|\be\.g\.|$))",
    re.I,
)
# the field named beside the display word that stands for it: "ON and the start time flash",
# "AL and the alarm time appear"
_BESIDE_RE = re.compile(
    r"^([A-Za-z][A-Za-z0-9]{0,5})\s+and\s+the\s+((?:[a-z]+\s){0,2}?[a-z]+)\s+"
    r"(?:flash|appear|blink|light)s?\b"
)
# ... the same mid-sentence, the word quoted, after the key's press: 'Hold SET until "ON" and
# the switch-on hour flash', 'Press SET: "HRS" and the light period flash'
_BESIDE_WITHIN_RE = re.compile(
    r"(?:\buntil|\bwhen|:|,)\s+[\"'“‘]?([A-Za-z][A-Za-z0-9]{0,5})[\"'”’]?\s+and\s+the\s+"
    r"((?:[a-z-]+\s){0,2}?[a-z-]+)\s+(?:flash|appear|blink|light)s?\b"
)
# a display word standing before "appears": "F START appears with …"
_APPEARS_RE = re.compile(r"^([A-Z][A-Z0-9 ]{0,12}?)\s+appears\b")
# a display word and a number: "The display shows dL 0 h."; a word and the field: "shows BIN
# and the alert level"; a switch's word and its state: "shows BEEP on or BEEP off"
_SHOWS_CODE_RE = re.compile(
    r"\bshows\s+(?:([A-Za-z]{1,4})\s+\d|([A-Z][A-Z0-9]{0,5})\s+and\s+the\b"
    r"|([A-Z][A-Z0-9]{1,5})\s+(?:on|off)\b)"
)
# the display's example of a field: "e.g. t30 s", "for example PS 6"
_EXAMPLE_RE = re.compile(r"\b(?:e\.g\.|for example)\s+([A-Za-z]{1,5})\s?\d")
# a field set as the one before it: "Set the end hour with ► / ◄ in the same way."
SAME_WAY_RE = re.compile(r"\b(?:(?:in\s+)?the\s+same\s+way|likewise|as\s+before)\b", re.I)
# a switch the pair turns on and off: "Press ▲ to switch the key beep on, ▼ to switch it off"
_SWITCHED_RE = re.compile(
    r"\b(?:switch|turn)\s+(?:the\s+)?((?:[a-z-]+\s){0,2}?[a-z-]+)\s+(on|off)\b[^.]*?"
    r"\b(?:switch|turn)\s+(?:it|them)\s+(on|off)\b"
)
# the ends stop the pair: "stops at both ends", "no wrap-around", "does not go round"
_STOPS_RE = re.compile(
    r"\bstops\b|\bno\s+wrap|\bdoes\s+not\s+(?:go\s+round|wrap)|\bend\s+stops?\b", re.I
)
# a span of numbers that refers elsewhere, no levels: "(see pages 12-14)", "models 200-300 only"
_REFERENCE_RE = re.compile(
    r"\b(?:pages?|pp?\.|models?|types?|sections?|chapters?|fig(?:ure)?s?\.?)\s*\d+\s*"
    r"(?:-|–|to|and)\s*\d+",
    re.I,
)
_NOT_WORDS = frozenset({"and", "the", "for", "with", "then", "only"})
_CODE_RE = re.compile(r"[A-Za-z]{1,3}-?\d{1,2}|[A-Za-z][A-Za-z-]{1,15}")


def after_key(shown: str) -> str:
    """The step's sentence after the key press that opens it ("Hold X for 3 s. AL and …")."""
    return shown.split(". ", 1)[-1].strip() if ". " in shown else ""


def field_name(shown: str, beside: bool = False) -> str:
    """The field's name as the display is said to show it ("the sensor range": sensor_range);
    ``beside``: also beside its display word ("shows BIN and the alert level")."""
    m = (
        _SHOWS_RE.search(shown)
        or (_SHOWS_BESIDE_RE.search(shown) if beside else None)
        or _BESIDE_RE.match(after_key(shown))
        or _BESIDE_WITHIN_RE.search(shown.split(". ", 1)[0])
    )
    if not m:
        return ""
    return "_".join(
        w for w in m.group(m.lastindex or 1).lower().split() if w not in {"current", "set"}
    )


def field_label(shown: str, fallback: str, example: bool = False) -> str:
    """The word the display shows for the field ("BIN", "AO"), else (``example``) the letters
    before the number of the display's example ("e.g. t30 s", "e.g. PS 6"), else the walk key's
    label."""
    after = after_key(shown)
    m = _APPEARS_RE.match(after) or _BESIDE_RE.match(after) or _SHOWS_CODE_RE.search(after)
    m = m or _BESIDE_WITHIN_RE.search(shown.split(". ", 1)[0])
    if not m and example:
        m = _EXAMPLE_RE.search(after)
    if not m:
        return fallback
    return next(g for g in m.groups() if g).strip()


def read_field(shown: str, text: str, at: int, beside: bool = False) -> dict[str, Any] | None:
    """The setting a field holds: a time of day that wraps at midnight, an amount (a range, or
    a run of amounts, in a unit), else — in a walk of several fields — a range of bare levels,
    the names the pair steps through, or a switch. ``shown`` is the step that opens the field,
    ``text`` that step with the steps setting it."""
    name = field_name(shown, beside)
    m = _DAY_WRAP_RE.search(text)
    if m:
        last = int(m.group(1)) * 3600 + int(m.group(2)) * 60
        every = 24 * 3600 - last
        if every <= 0 or every > 3 * 3600:
            return None
        if name:  # "the start hour" of a time of day: its start time
            name = re.sub(r"(^|_)hours?$", r"\1time", name)
        spec = {
            "type": "time",
            "ranges": [["00:00:00", format_hms(last), every]],
            "format": "hh:mm",
            "wrap": True,
        }
        return {"name": name or "time", "spec": spec}
    ranges = _one_span(find_ranges(text))
    step = find_step(text)
    listed = find_list(text) if not ranges else None
    pieces = []
    if listed and all(re.fullmatch(rf"{NUM}\s*{UNIT}", v, re.I) for v in listed[0]):
        ranges = [list_range(listed[0])]  # "Set the length: 1, 2, 3 or 4 hours."
        step = step or list_step(listed[0])
        pieces = gap_pieces(_nums(listed[0]), ranges[0].unit)
        if len(pieces) > 1:  # "1, 2, 5, 10 and 30 minutes": each run of equal gaps a piece
            ranges, step = pieces, None
    if ranges and (len(ranges) == 1 or ranges == pieces) and ranges[0].unit:
        ev = Evidence(ranges=ranges, range_at=at, step=step, step_at=at if step else None)
        return {"name": name or "setting", "evidence": ev}
    return None


def _one_span(ranges: list[Any]) -> list[Any]:
    """One span read twice, with its unit and without ("The range is 0 to 60 seconds; it
    stops at 0 and at 60"): the reading with the unit."""
    units = {r.unit for r in ranges}
    if len(ranges) > 1 and len({(r.low, r.high) for r in ranges}) == 1 and len(units - {""}) == 1:
        return [r for r in ranges if r.unit][:1]
    return ranges


def read_more_field(shown: str, text: str, at: int) -> dict[str, Any] | None:
    """A field of a walk through several settings that :func:`read_field` leaves: a run of
    amounts whose unit follows the last ("20, 30, 45, 60, 90 seconds"), a range of bare levels
    ("(1 to 12)"), the codes or names the pair steps through, or a switch."""
    name = field_name(shown, beside=True)
    run = _amount_run(text)
    if run is not None:
        return {"name": name or "setting", "evidence": Evidence(ranges=run, range_at=at)}
    ranges = find_ranges(_REFERENCE_RE.sub(" ", text))
    if len(ranges) == 1 and not ranges[0].unit and ranges[0].high > ranges[0].low:
        ev = Evidence(ranges=ranges, range_at=at)
        return {"name": name or "setting", "evidence": ev}
    switched = _SWITCHED_RE.search(text)
    if switched and {switched.group(2), switched.group(3)} == {"on", "off"}:
        own = "_".join(switched.group(1).split())
        return {"name": name or own, "values": ["off", "on"], "stops": True}
    choices = _choices(text)
    if choices:
        return {"name": name or "setting", "values": choices, "stops": bool(_STOPS_RE.search(text))}
    return None


def _amount_run(text: str) -> list[Any] | None:
    """The pieces of a printed run of amounts, its unit after the last one or after each."""
    listed = find_list(text)
    if not listed or len(listed[0]) < 3:
        return None
    items = listed[0]
    if not all(re.fullmatch(rf"{NUM}(?:\s*{UNIT})?", v, re.I) for v in items):
        return None
    tail = re.sub(r"^[\d.,\s]+", "", items[-1])
    if not tail:
        return None
    nums = _nums(items)
    if len(nums) != len(items):
        return None
    return gap_pieces(nums, unit_name(tail))


def _choices(text: str) -> list[str] | None:
    """The codes or names a bracket lists ("(r1, r2, r3; stops at both ends)")."""
    for m in re.finditer(r"\(([^()]*)\)", text):
        items = bare_list(m.group(1).split(";")[0])
        if items and all(_CODE_RE.fullmatch(i) for i in items):
            return items
    return None


def code_words(lines: list[str], codes: list[str]) -> dict[str, str] | None:
    """The word the manual prints right after each of a field's codes, all of them in order on
    one line (or running on to the next): "r1 near (≈ 8 cm) – r2 middle (≈ 15 cm) – r3 far".
    The user says the word ("the far sensor range"), the display shows the code."""
    if len(codes) < 2 or not all(re.fullmatch(r"[A-Za-z]{1,3}-?\d{1,2}", c) for c in codes):
        return None
    for k, line in enumerate(lines):
        if not re.search(rf"(?<![\w-]){re.escape(codes[0])}\s+[a-z]", line):
            continue
        text = f"{line} {lines[k + 1]}" if k + 1 < len(lines) else line
        words: dict[str, str] = {}
        at = 0
        for code in codes:
            m = re.compile(rf"(?<![\w-]){re.escape(code)}\s+([a-z]{{3,15}})\b").search(text, at)
            if m is None or m.group(1) in _NOT_WORDS or re.fullmatch(UNIT, m.group(1), re.I):
                break
            words[code], at = m.group(1), m.end()
        if len(words) == len(codes) and len(set(words.values())) == len(codes):
            return words
    return None


def like(one: dict[str, Any], name: str) -> dict[str, Any] | None:
    """The second field of a walk whose step says it is set "in the same way" as the first:
    the first's kind of value under its own name ("the end hour" of a time of day: end_time)."""
    if not name:
        return None
    if "spec" in one:
        return {"name": re.sub(r"(^|_)hours?$", r"\1time", name), "spec": dict(one["spec"])}
    if "values" in one:
        return {**one, "name": name}
    return {"name": name, "evidence": one["evidence"]}
