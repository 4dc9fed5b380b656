"""A range whose step changes part way, told in words: two pieces of one setting.

Times ("up to one hour by 10 minutes, after that by 30 minutes", :func:`find_two_steps`) come
in the smaller unit; other amounts ("500 to 2000 W in 100 W steps, above 2000 W in steps of
250 W up to 3500 W", :func:`find_amount_pieces`) in their one unit (watts, percent, degrees,
rpm)."""

from __future__ import annotations

import re

from apbot.read.values import (
    MOST_RE,
    NUM,
    UNIT,
    UPTO_RE,
    Range,
    is_time_unit,
    number,
    seconds,
    unit_name,
)

_AMOUNT = rf"(?:an?\s+)?({NUM})?\s*-?\s*({UNIT})(?!\w)"
_PIECE_STEP_RES = (  # "by 10 minutes", "adds 10 min", "steps of 10 minutes", "in 10-minute steps"
    re.compile(rf"\b(?:by|adds?)\s+{_AMOUNT}", re.IGNORECASE),
    re.compile(rf"\b(?:steps?|increments?)\s+of\s+{_AMOUNT}", re.IGNORECASE),
    re.compile(rf"\bin\s+(?:an?\s+)?({NUM})?\s*-?\s*({UNIT})\s+(?:steps|increments)\b", re.I),
)
_PIECE_BOUND_RES = (  # "up to 1 hour", "until 1 hour", "(from 0) to 1 hour"
    re.compile(rf"\b(?:up to|until|till)\s+{_AMOUNT}", re.IGNORECASE),
    re.compile(rf"\bto\s+(?:an?\s+)?({NUM})\s*({UNIT})(?!\w)", re.IGNORECASE),
)
_PIECE_CHANGE_RE = re.compile(  # where the second piece begins
    r"\b(?:after that|after this|beyond (?:that|this|it)|above (?:that|this|it)|over (?:that|this)"
    r"|thereafter|then|from there(?: on)?)\b|(?:,|\band)\s+(?=from\b)"
    r"|\b(?:above|over|beyond|past)\s+(?=\d+(?:[.,]\d+)?\s*(?:hours?|h|minutes?|min)\b)"
    r"|\band\b(?=\s+(?:in|by)\b)",
    re.IGNORECASE,
)


def _piece_events(text: str) -> list[tuple[int, str, float, str]]:
    """Steps and bounds told in a sentence, in order: (position, "step"/"bound", amount, unit)."""
    found: dict[int, tuple[int, str, float, str]] = {}
    for kind, regexes in (("step", _PIECE_STEP_RES), ("bound", _PIECE_BOUND_RES)):
        for regex in regexes:
            for m in regex.finditer(text):
                value = number(m.group(1) or "1")
                if value is not None and m.start() not in found:
                    found[m.start()] = (m.start(), kind, value, unit_name(m.group(2)))
    return sorted(found.values())


def find_two_steps(texts: list[str], names: tuple[str, ...] = ()) -> tuple[list[Range], int] | None:
    """A time range whose step changes part way, told in words: "Up to one hour, each press
    changes the delay by 10 minutes; after that it changes by 30 minutes. The longest delay is
    24 hours.", "in steps of 10 minutes up to 1 hour, then in 30-minute steps up to 24 hours",
    "from 0 to 1 hour by 10 minutes, from 1 to 24 hours by 30 minutes" — two pieces in the
    smaller unit (0–60 min by 10, 60–1440 min by 30), and the index of the text that told
    them. The top, unless the sentence gives it, comes from the rest of that sentence, the next
    one, or a later one that names the setting (one of ``names``)."""
    texts = [_plain_durations(t) for t in texts]
    for k, text in enumerate(texts):
        events = _piece_events(text)
        for change in _PIECE_CHANGE_RE.finditer(text):
            before = [e for e in events if e[0] < change.start()]
            after = [e for e in events if e[0] >= change.end()]
            steps = [e for e in before if e[1] == "step"]
            bounds = [e for e in before if e[1] == "bound"]
            later = [e for e in after if e[1] == "step"]
            if not (steps and bounds and later):
                continue
            top = next((e for e in after if e[1] == "bound"), None)
            most = (top[2], top[3]) if top else _top_after(texts, k, text[later[0][0] :], names)
            if most is None:
                return None
            amounts = [(bounds[-1][2], bounds[-1][3]), (steps[0][2], steps[0][3])]
            amounts += [(later[0][2], later[0][3]), most]
            if any(not is_time_unit(u) for _v, u in amounts):
                return None
            unit = min((u for _v, u in amounts), key=lambda u: seconds(1, u))
            middle, first, then, high = (seconds(v, u) / seconds(1, unit) for v, u in amounts)
            if not (0 < first < middle < high and then > 0):
                return None
            return [Range(0, middle, unit, first), Range(middle, high, unit, then)], k
    return None


def split_range(found: Range, texts: list[str], label: str) -> list[Range]:
    """A time range named elsewhere whose sentence also tells a step that changes part way
    ("Between 0:00 and 6:00 each touch changes the delay by half an hour; above 6 hours …
    by one hour, up to 20:00"): both pieces, when both start from nothing; else []."""
    if found.low != 0 or not (is_time_unit(found.unit) or found.unit == "hmm"):
        return []
    two = find_two_steps(texts, (label.lower(),) if label else ())
    return two[0] if two and two[0] and two[0][0].low == 0 else []


def _plain_durations(text: str) -> str:
    """Durations of a step sentence in one spelling: "half an hour" is 30 minutes, a whole-hour
    clock after "and" / "up to" ("between 0:00 and 6:00", "up to 20:00") is so many hours, and
    "between A and B" bounds the piece at B ("up to B")."""
    text = re.sub(r"\bhalf an hour\b", "30 minutes", text, flags=re.IGNORECASE)
    text = re.sub(r"\b(and|to|until)\s+(\d{1,2}):00\b", r"\1 \2 hours", text, flags=re.I)
    return re.sub(
        rf"\bbetween\s+(?:\d{{1,2}}:\d{{2}}|{NUM}\s*{UNIT}?)\s+and\s+(?=\d)",
        "up to ",
        text,
        flags=re.IGNORECASE,
    )


def _top_after(
    texts: list[str], k: int, rest: str, names: tuple[str, ...]
) -> tuple[float, str] | None:
    """The longest setting told after the two steps: in the rest of their sentence, the next
    sentence, or a later sentence naming the setting."""
    for j, text in enumerate([rest, *texts[k + 1 :]]):
        if j >= 2 and not any(n and n in text.lower() for n in names):
            continue
        most = MOST_RE.search(text) or UPTO_RE.search(text)
        if most:
            value = number(most.group(1))
            return (value, unit_name(most.group(2))) if value is not None else None
    return None


_STEP = (
    rf"(?:in\s+({NUM})\s*-?\s*(?:{UNIT})?\s*(?:steps|increments)"
    rf"|(?:in\s+)?(?:steps?|increments?)\s+of\s+({NUM})\s*(?:{UNIT})?"
    rf"|by\s+({NUM})\s*(?:{UNIT})?)"
)
_PIECES_RE = re.compile(
    rf"(?<![\w.,])({NUM})\s*(?:{UNIT})?\s*(?:to|–|—|-)\s*({NUM})\s*({UNIT})(?!\w)\s*,?\s*{_STEP}"
    rf"\s*[,;]?\s*(?:and\s+|then\s+)*(?:(?:above|over|beyond|past|from)\s+({NUM})\s*(?:{UNIT})?"
    rf"\s*,?\s*)?{_STEP}\s*,?\s*(?:up\s+to|to|until)\s+({NUM})\s*(?:{UNIT})?(?!\w)",
    re.IGNORECASE,
)


def find_amount_pieces(texts: list[str]) -> tuple[list[Range], int] | None:
    """The two pieces of the first text that tells them, and that text's index (else None)."""
    for k, text in enumerate(texts):
        for m in _PIECES_RE.finditer(text):
            g = m.groups()
            unit = unit_name(g[2])
            if is_time_unit(unit):
                continue  # times: find_two_steps, which knows hours from minutes
            low, middle, top = number(g[0]), number(g[1]), number(g[10])
            first = number(next((x for x in g[3:6] if x), ""))
            then = number(next((x for x in g[7:10] if x), ""))
            said = number(g[6]) if g[6] else middle
            if None in (low, middle, top, first, then, said) or said != middle:
                continue
            assert low is not None and middle is not None and top is not None
            assert first is not None and then is not None
            if low < middle < top and 0 < first <= middle - low and 0 < then <= top - middle:
                return [Range(low, middle, unit, first), Range(middle, top, unit, then)], k
    return None
