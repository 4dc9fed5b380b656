"""Value lists, ranges and steps in manual prose and tables.

"AUTO → CONTINUOUS → LAUNDRY", "switch between HIGH and LOW", "35 % to 85 %", "0:30–24:00",
"in 5% steps", "each touch adds one hour": the few shapes manuals use to say which values a
setting takes. Every finder returns what it read and nothing it did not (None), so the builder
can tell evidence from guesses.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from apbot.model.values import unit_of, words_to_number

NUM = (
    r"(?:\d+(?:[.,]\d+)?|one|two|three|four|five|six|seven|eight|nine|ten|twelve|fifteen"
    r"|twenty|thirty|half)"
)
UNIT = (
    r"(?:%|°\s?[CF]|°|degrees?|min(?:ute)?s?|h(?:ou)?rs?|hours?|h|sec(?:ond)?s?|s|rpm|W|watts?"
    r"|kg|lbs?|oz|g|ml|L|litres?|cups?)"
)
_TIME = r"\d{1,2}:\d{2}"
_DASH = r"\s*(?:–|—|-|to|and|~|until)\s*"
RANGE_RE = re.compile(
    rf"(?<![\w:.])({NUM})\s*({UNIT})?{_DASH}({NUM})\s*({UNIT})?(?![\w:])", re.IGNORECASE
)
TIME_RANGE_RE = re.compile(rf"(?<![\d:])({_TIME}){_DASH}({_TIME})(?![\d:])")
UPTO_RE = re.compile(rf"\bup to\s+({NUM})\s*({UNIT})(?!\w)", re.IGNORECASE)
STEP_RE = re.compile(
    rf"(?:in\s+({NUM})\s*-?\s*({UNIT})?\s*(?:steps|increments|stages|units)"
    rf"|(?:steps?|increments?|units?)\s+of\s+({NUM})\s*({UNIT})?"
    rf"|(?:each|every)\s+(?:press|touch|turn|click|tap|step)[^.;]*?"
    rf"(?:adds?|by|changes?[^.;]*?by|raises?|moves?[^.;]*?by)\s+(?:an?\s+|another\s+)?({NUM})?\s*({UNIT}))",
    re.IGNORECASE,
)
_ARROW = re.compile(r"\s*(?:→|->|⇒|>|»|⟶)\s*")
_CUE = re.compile(  # a lookahead, so that every cue in a sentence is tried
    r"(?=(?:\bbetween|\bamong|\bchoose(?: from)?|\bselect(?:s| from)?|\bcycles?(?: through)?|"
    r"\boptions?(?: are)?|\bsettings?(?: are)?|\blevels?(?: are)?|\bmodes?(?: are)?|\border|"
    r"\bpositions?(?: are)?|\bpick|\bsteps? through|\bchanges?|:)\s+(.*))",
    re.IGNORECASE,
)
_STOP_WORDS = {"the", "a", "an", "your", "this", "that", "it", "you", "to", "is", "are", "of"}


def number(text: str) -> float | None:
    text = text.strip().lower().replace(",", ".")
    if text == "half":
        return 0.5
    try:
        return float(text)
    except ValueError:
        return words_to_number(text)


def unit_name(text: str | None) -> str:
    """A canonical unit spelling: %, °C, °F, min, h, s, rpm, W, kg, g, ml, l (or "")."""
    if not text:
        return ""
    t = text.strip().replace(" ", "")
    low = t.lower()
    if low in ("%", "percent"):
        return "%"
    if low in ("°c", "°", "degree", "degrees", "c"):
        return "°C"
    if low == "°f":
        return "°F"
    info = unit_of(low)
    if info and info[0] == "time":
        return {1: "s", 60: "min", 3600: "h"}[int(info[1])]
    return {"watt": "W", "watts": "W", "w": "W", "litre": "l", "litres": "l", "lbs": "lb"}.get(
        low, low
    )


def rescale(value: float, unit: str, to: str) -> float | None:
    """``value`` in ``unit`` written in ``to`` when both measure the same (1.5 kg = 1500 g,
    0.5 l = 500 ml); None for units of different kinds (or none)."""
    if unit == to:
        return value
    a, b = unit_of(unit.lower()) if unit else None, unit_of(to.lower()) if to else None
    if a is None or b is None or a[0] != b[0] or a[0] in ("time", "temperature", "fahrenheit"):
        return None
    return round(value * a[1] / b[1], 6)


def is_time_unit(unit: str) -> bool:
    return unit in ("s", "min", "h")


def seconds(value: float, unit: str) -> int:
    return round(value * {"s": 1, "min": 60, "h": 3600}.get(unit, 60))


@dataclass(frozen=True)
class Range:
    low: float
    high: float
    unit: str  # canonical; "hmm" for times written h:mm
    step: float | None = None


_FOREIGN_UNIT = re.compile(
    r"\s*(?:V|VAC|Hz|kHz|mm|cm|m|nm|µm|mA|mAh|dB|dBA|kWh|VA|bar|MPa|kPa|psi|Pa|lux)(?![\w])"
)  # units no setting of a household appliance is set in: ratings and sizes


_ASIDE_RE = re.compile(  # "1 (barely warm)": words in brackets, no number and no unit
    rf"(?<=\d)\s*\((?!\s*{UNIT}\s*\))[^()\d]{{3,30}}\)", re.IGNORECASE
)


def find_ranges(text: str) -> list[Range]:
    """Ranges written in the text (times h:mm in seconds with unit ``s``); a word or two in
    brackets after a number is an aside ("from 1 (barely warm) to 10 (full power)")."""
    out = _ranges(text)
    bare = _ASIDE_RE.sub("", text)
    return out + [r for r in _ranges(bare) if r not in out] if bare != text else out


def _ranges(text: str) -> list[Range]:
    out: list[Range] = []
    for m in TIME_RANGE_RE.finditer(text):
        a, b = _hmm(m.group(1)), _hmm(m.group(2))
        if a < b:
            out.append(Range(a, b, "s"))
    for m in RANGE_RE.finditer(text):
        if TIME_RANGE_RE.search(m.group(0)):
            continue
        lo, hi = number(m.group(1)), number(m.group(3))
        unit = unit_name(m.group(4) or m.group(2))
        first = unit_name(m.group(2))
        mixed = first != unit and is_time_unit(first) and is_time_unit(unit)
        if hi is not None and mixed:  # "1 min – 3 h": in minutes
            hi, unit = seconds(hi, unit) / seconds(1, first), first
        elif lo is not None and hi is not None and first and first != unit:
            small = min((first, unit), key=lambda u: (unit_of(u) or ("", 0))[1])
            low_in, high_in = rescale(lo, first, small), rescale(hi, unit, small)
            if low_in is not None and high_in is not None:  # "100 g – 2.0 kg": in grams
                lo, hi, unit = low_in, high_in, small
        if lo is None or hi is None or not lo < hi:
            continue
        if not unit and m.group(0).strip().lower().split()[1:2] == ["and"]:
            continue  # "press A and B": no unit, "and" joins words more often than numbers
        if unit == "" and (hi > 10_000 or _FOREIGN_UNIT.match(text, m.end())):
            continue  # "220–240 V", "12–32 cm": a rating or a size, not a setting's range
        out.append(Range(lo, hi, unit))
    for m in UPTO_RE.finditer(text):
        hi = number(m.group(1))
        if hi:
            out.append(Range(0, hi, unit_name(m.group(2))))
    return out


_FIRST_RE = re.compile(
    rf"\bfirst (?:press|tap|touch|push|click|turn)\b[^.;]*?\b(?:gives|shows|sets|is|selects)\s+"
    rf"({NUM})\s*({UNIT})(?!\w)",
    re.IGNORECASE,
)
_MOST_RE = re.compile(
    rf"\b(?:longest|maximum|highest|max\.?)\b[^.;]*?\b(?:is|of)\s+({NUM})\s*({UNIT})(?!\w)",
    re.IGNORECASE,
)


_STEPPED_PIECE_RE = re.compile(  # "0:30 – 12:00  30 minutes": a range, then its step
    rf"(?<![\d:])({_TIME}){_DASH}({_TIME})(?![\d:])\s*(?:h\b)?\s*(?:by\s+)?"
    r"(\d+(?:[.,]\d+)?|one|an?)\s*(minutes?|mins?|hours?|hrs?|h)\b",
    re.IGNORECASE,
)


def find_stepped_pieces(text: str) -> list[Range]:
    """Two or more time ranges, each followed by its step, the next starting where the last
    ends ("Range Step 0:30 - 12:00 30 minutes 12:00 - 24:00 1 hour"), in seconds; else []."""
    pieces: list[Range] = []
    for m in _STEPPED_PIECE_RE.finditer(text):
        low, high = _hmm(m.group(1)), _hmm(m.group(2))
        amount = 1.0 if m.group(3).lower() in ("one", "a", "an") else number(m.group(3))
        if amount is None or not low < high or (pieces and pieces[-1].high != low):
            return pieces if len(pieces) >= 2 else []
        pieces.append(Range(low, high, "s", seconds(amount, unit_name(m.group(4)))))
    return pieces if len(pieces) >= 2 else []


def find_bounds(texts: list[str]) -> Range | None:
    """A range told in two sentences: "the first tap gives 0.5 h" and "the longest
    reservation is 24 h" (the first value is also the step: each tap adds time); a time's
    longest setting alone ("the longest setting is 13 hours") is a range from 0."""
    first = most = None
    for text in texts:
        first = first or _FIRST_RE.search(text)
        most = most or _MOST_RE.search(text)
    if not most:
        return None
    if not first:  # "the longest setting is 13 hours": from nothing up to that
        high, unit = number(most.group(1)), unit_name(most.group(2))
        return Range(0, high, unit) if high and is_time_unit(unit) else None
    low, high = number(first.group(1)), number(most.group(1))
    unit, top = unit_name(first.group(2)), unit_name(most.group(2))
    if low is None or high is None:
        return None
    if unit != top:
        if not (is_time_unit(unit) and is_time_unit(top)):
            return None
        high = seconds(high, top) / seconds(1, unit)
    return Range(low, high, unit, low) if low < high else None


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


def _top_after(
    texts: list[str], k: int, rest: str, names: tuple[str, ...]
) -> tuple[float, str] | None:
    """The longest setting told after the two steps: in the rest of their sentence, the next
    sentence, or a later sentence naming the setting."""
    for j, text in enumerate([rest, *texts[k + 1 :]]):
        if j >= 2 and not any(n and n in text.lower() for n in names):
            continue
        most = _MOST_RE.search(text) or UPTO_RE.search(text)
        if most:
            value = number(most.group(1))
            return (value, unit_name(most.group(2))) if value is not None else None
    return None


def _hmm(text: str) -> int:
    h, m = text.split(":")
    return int(h) * 3600 + int(m) * 60


PER_RE = re.compile(
    rf"\b({NUM})\s*({UNIT})\s+(?:per|for each|each|with each|with every|a)\s+"
    rf"(?:press|click|turn|touch|detent|step|tap|notch)",
    re.IGNORECASE,
)


_BARE_STEPS_RE = re.compile(rf"(?<![\w-])({NUM})-({UNIT})\s+(?:steps|increments)\b", re.I)


def find_step(text: str) -> tuple[float, str] | None:
    """A step size: (number, canonical unit)."""
    per = PER_RE.search(text)
    if per and number(per.group(1)):
        return number(per.group(1)) or 1.0, unit_name(per.group(2))
    m = STEP_RE.search(text)
    if not m:
        bare = _BARE_STEPS_RE.search(text)  # "| up to 15 h ahead, ten-minute steps |"
        if bare and number(bare.group(1)):
            return number(bare.group(1)) or 1.0, unit_name(bare.group(2))
        return None
    groups = m.groups()
    if m.group(0).lower().endswith(("units", "stages")) and not groups[1]:
        return None  # "in half-hour units" is a step, "sold in 2 units", "in two stages" not
    for i in (0, 2, 4):
        raw, unit = groups[i], groups[i + 1]
        if raw is None and i == 4 and unit:
            raw = "1"
        if raw is not None:
            value = number(raw)
            if value:
                return value, unit_name(unit)
    return None


def find_initial(text: str) -> tuple[float, str] | None:
    m = re.search(
        rf"\b(?:default|factory setting|preset|standard|starts? (?:at|on)|initially)\b[^.;]*?"
        rf"({NUM})\s*({UNIT})?(?![\w:])",
        text,
        re.IGNORECASE,
    )
    if not m:
        return None
    value = number(m.group(1))
    return (value, unit_name(m.group(2))) if value is not None else None


def _clean_item(item: str) -> str:
    item = re.sub(r"\(.*?\)", "", item)
    item = re.sub(r"^(?:back to|then|and|or|finally)\s+", "", item.strip(), flags=re.I)
    return item.strip(" .;:!?\"'“”‘’*_")


def _value_like(item: str, caps_context: bool) -> bool:
    if not item or len(item) > 24 or re.search(r"[()\[\]{}]", item):
        return False
    ws = item.split()
    if len(ws) > 3 or ws[0].lower() in _STOP_WORDS:
        return False
    if re.fullmatch(rf"{NUM}\s*{UNIT}?", item, re.IGNORECASE):
        return True
    if caps_context:
        return item.upper() == item and any(c.isalpha() for c in item)
    return all(w[:1].isupper() or w[:1].isdigit() for w in ws) or len(ws) == 1


_NUMBER_LIST = re.compile(
    r"(?<![\w.])(\d+(?:[.,]\d+)?(?:\s*,\s*\d+(?:[.,]\d+)?)*)\s*,?\s*(?:or|and)\s*"
    r"(\d+(?:[.,]\d+)?)\s*([A-Za-z%°]{1,8})?(?!\w)",
)


def _nothing_as_zero(items: list[str]) -> list[str]:
    """A list of durations led by a word for none ("no timer → 2H → 4H", "OFF, 1 h, 2 h"): the
    first is zero of their unit."""
    rest = [
        re.fullmatch(r"(\d+(?:[.,]\d+)?)\s*(h|hr|hrs|hours?|min|mins|minutes?)", i.strip(), re.I)
        for i in items[1:]
    ]
    if len(items) < 3 or not all(rest):
        return items
    if not re.fullmatch(r"(?:no\b.{0,12}|none|off|-+|–|—)", items[0].strip(), re.I):
        return items
    unit = rest[0].group(2) if rest[0] else "h"
    return [f"0 {unit}"] + [f"{m.group(1)} {m.group(2)}" for m in rest if m]


_PROGRESSION_RE = re.compile(  # "50, 55, 60 ... 95, 100", "MENU 1, MENU 2 … MENU 15"
    r"(?<![\d.])(?:([A-Z]{2,12}) )?(\d+(?:\.\d+)?),\s*(?:\1 )?(\d+(?:\.\d+)?)"
    r"(?:,\s*(?:\1 )?\d+(?:\.\d+)?)*,?\s*(?:\.\.\.|…)\s*(?:(?:up )?to\s+)?"
    r"(?:(?:\1 )?\d+(?:\.\d+)?,\s*)*(?:\1 )?(\d+(?:\.\d+)?)(?!\d|\.\d)\s*([A-Za-z%°]{1,8})?"
)


def find_progression(text: str) -> list[str] | None:
    """Settings written as the first few, an ellipsis and the last ("50, 55, 60 ... 95, 100"):
    every one of them, the step being the first gap."""
    m = _PROGRESSION_RE.search(text)
    if not m:
        return None
    first, second, last = float(m.group(2)), float(m.group(3)), float(m.group(4))
    gap = second - first
    if gap <= 0 or last <= second or (last - first) / gap > 400:
        return None
    count = round((last - first) / gap)
    if abs(first + count * gap - last) > 1e-6:
        return None  # the last is off the step: no progression
    unit = m.group(5) if m.group(5) and re.fullmatch(UNIT, m.group(5), re.I) else ""
    return [f"{first + k * gap:g}" + (f" {unit}" if unit else "") for k in range(count + 1)]


def find_list(text: str) -> tuple[list[str], str] | None:
    """A list of values in one sentence, and how it was written ("arrows", "list")."""
    numbers = _NUMBER_LIST.search(text)
    if numbers:  # "3, 6 or 9 hours"
        items = [*re.split(r"\s*,\s*", numbers.group(1)), numbers.group(2)]
        unit = numbers.group(3) or ""
        known = bool(unit) and bool(re.fullmatch(UNIT, unit, re.IGNORECASE))
        if len(items) >= 3:
            return [f"{i} {unit}" if known else i for i in items], "list"
    parts = [_clean_item(p) for p in _ARROW.split(text)]
    if len(parts) >= 3:  # "… → HIGH, and from HIGH the next press …": the list ends at the comma
        last = re.split(r"[,;]\s|\s[—–]\s|(?:^|\s+)(?:and\s+)?(?:then|back|again)\b", parts[-1])[0]
        parts[-1] = _clean_item(last)
    amount = re.search(rf"(?<![\w.])({NUM}\s*{UNIT})\s*$", parts[0], re.I)
    if len(parts) >= 3 or (len(parts) == 2 and all(_value_like(p, True) for p in parts)):
        head = parts[0].split(":")[-1].split()  # "in this order: AUTO → ...", "Clockwise: Cotton"
        capital = [w for w in head if w.upper() == w and any(c.isalpha() for c in w)]
        trailing: list[str] = []  # "Tap FAN to step through AUTO →": the run before the arrow
        for w in reversed(head):
            if w.upper() != w or not any(c.isalpha() for c in w):
                break
            trailing.insert(0, w)
        if trailing and len(trailing) < len(capital):
            capital = trailing
        parts[0] = _clean_item(" ".join(capital) or " ".join(head[-2:]) or parts[0])
        if len(head) > 3 and not capital:
            parts[0] = _clean_item(head[-1])
        if amount and len(parts) >= 3:  # "… in the order 1.0 LB → 1.5 LB": the amount first
            parts[0] = amount.group(1)
        items = [p for p in parts if p and re.search(r"\w", p)]  # "… → OFF → …": no item
        if items and items[0] in items[1:]:
            items = items[: items.index(items[0], 1)]  # "OFF → 2H → 4H → OFF": the cycle, once
        items = _nothing_as_zero(items)
        if all(_value_like(p, False) for p in items) and len(items) >= 2:
            return _dedupe(items), "arrows"
    for m in _CUE.finditer(text):
        segment = re.split(r"[.;]\s|\s[—–]\s|\bwhile\b|\bwhen\b|\bto (?!\d)", m.group(1))[0]
        segment = re.sub(r"\s+only\W*$", "", segment, flags=re.I)  # "SOFT or FIRM only."
        items = [
            _clean_item(p)
            for p in re.split(r",\s*|\s*/\s*|\s*[·•|]\s*|\s{2,}|\s+or\s+|\s+and\s+", segment)
        ]
        items = [i for i in items if i]
        caps = sum(1 for i in items if i.upper() == i and any(c.isalpha() for c in i))
        if len(items) >= 2 and all(_value_like(i, caps >= 2) for i in items):
            lower_ok = len(items) >= 3 and all(len(i.split()) <= 2 for i in items)
            numeric = all(re.fullmatch(rf"{NUM}\s*{UNIT}?", i, re.I) for i in items)
            if caps >= 2 or numeric or lower_ok:
                return _dedupe(items), "list"
        if caps >= 3:  # names in capitals, then the prose that describes the first one
            head = []
            for item in items:
                if not _value_like(item, True):
                    break
                head.append(item)
            if len(head) >= 3:
                return _dedupe(head), "list"
    dotted = _dotted_run(text)  # the last resort: a dotted run inside a flattened sentence
    return (dotted, "list") if dotted else None


_QUANTITY = re.compile(rf"\d\s*{UNIT}\b", re.IGNORECASE)


def _dotted_run(text: str) -> list[str] | None:
    """Names run together with middle dots inside a longer sentence, as text flattened from a
    PDF prints a knob's positions ("… starting from OFF: OFF · Cottons · Eco Cottons · … ·
    Spin/Drain Programme Default temp."): the first and last names are cut to the length most
    of the names have."""
    parts = re.split(r"\s*[·•]\s*", text)
    if len(parts) < 5 or ":" not in parts[0]:
        return None  # a list a colon introduces, not a legend or a row of figures
    middle = [_clean_item(p) for p in parts[1:-1]]
    names = all(
        _value_like(p, False) and re.match(r"[A-Za-z]", p) and not _QUANTITY.search(p)
        for p in middle
    )
    if not names:
        return None
    counts = [len(p.split()) for p in middle]
    k = max(set(counts), key=lambda c: (counts.count(c), -c))
    first = _clean_item(" ".join(parts[0].split(":")[-1].split()[-k:]))
    last = _clean_item(" ".join(parts[-1].split()[:k]))
    items = [i for i in [first, *middle, last] if i]
    return _dedupe(items)


_CAPS_ITEM = r"[A-Z][A-Z0-9+-]*(?: [A-Z0-9+-]+){0,2}"
_CAPS_RUN = re.compile(
    rf"(?<![\w/])({_CAPS_ITEM}(?:\s*(?:,|/|·|\s[–—]\s)\s*{_CAPS_ITEM})*\s*(?:,\s*)?"
    rf"(?:or|and|,|/|[–—])\s*{_CAPS_ITEM})(?![\w/])"
)
_QTY = r"\d+(?:[.,]\d+)?\s*(?:[a-zA-Z%°]{1,4}\b|%|°[CF])?"
_QTY_RUN = re.compile(rf"(?<![\w.])({_QTY}(?:\s*,\s*{_QTY})+\s*,?\s*(?:or|and)\s+{_QTY})")


def quantity_run(text: str) -> list[str] | None:
    """Three or more amounts in a row in a key's own sentence ("750 g, 1000 g or 1250 g")."""
    m = _QTY_RUN.search(text)
    if not m:
        return None
    items = [i.strip() for i in re.split(r"\s*,\s*(?:or\s+|and\s+)?|\s+(?:or|and)\s+", m.group(1))]
    items = [i for i in items if i]
    return _dedupe(items) if len(items) >= 3 else None


def caps_run(text: str, exclude: set[str]) -> list[str] | None:
    """Three or more names in capitals written in a row in a key's own sentence ("COLOUR –
    crust colour, LIGHT, MEDIUM or DARK"), the key's own names excluded."""
    for m in _CAPS_RUN.finditer(text):
        items = [i.strip() for i in re.split(r"\s*(?:,|/|·|[–—])\s*|\s+(?:or|and)\s+", m.group(1))]
        items = [i for i in items if i and i.upper() not in exclude]
        if len(items) >= 3 and all(len(i) <= 16 for i in items):
            return _dedupe(items)
    return None


def bare_list(text: str) -> list[str] | None:
    """A line that is nothing but a list ("OFF · 1 · 2 · 3 · CONT", "WARM   BAKE   TOAST"), as
    printed round a knob or under a key after a sentence ending in a colon."""
    items = [
        _clean_item(p)
        for p in re.split(r"\s*[·•|,]\s*|\s*/\s*|\s{2,}|\s+or\s+|\s*[→>]\s*", text.strip())
    ]
    items = [i for i in items if i]
    if len(items) < 3 or len(items) > 16:
        return None
    if all(len(i) <= 20 and len(i.split()) <= 3 and not i.endswith(":") for i in items):
        return _dedupe(items)
    return None


def cell_list(text: str) -> list[str] | None:
    """A table cell that is nothing but a list of values ("22, 26, 30 … 58 L", "Low, Medium
    and High", "400 / 800 / 1200 rpm"): three to sixteen short items, no sentence."""
    items = [
        _clean_item(p)
        for p in re.split(r"\s*[·•,;/]\s*(?:(?:and|or)\s+)?|\s+(?:and|or)\s+", text.strip())
    ]
    items = [i for i in items if i]
    if not 3 <= len(items) <= 16 or len(text) > 160 or re.search(r"[.:!?]\s*$|:\s", text):
        return None  # a sentence describing the key, not a cell of values
    if all(len(i) <= 20 and len(i.split()) <= 2 for i in items):
        return _dedupe(items)
    return None


def anchored_lists(text: str, word: str) -> list[list[str]]:
    """Lists tied to a setting's word: "loaf weight (500 / 750 / 1000)", "a light, medium or
    dark crust"."""
    out: list[list[str]] = []
    if word.lower() not in text.lower():
        return out
    w = re.escape(word)
    for m in re.finditer(rf"\b{w}\w*(?:\s+\w+){{0,2}}\s*\(([^()]{{3,80}})\)", text, re.I):
        if _ASIDE_PAREN_RE.match(m.group(1)):
            continue  # "choose the menu (and texture, if needed)": an aside, not the values
        items = [_clean_item(i) for i in re.split(r"\s*/\s*|,\s*|\s+or\s+", m.group(1))]
        if len(items) >= 2 and all(i and len(i) <= 16 and len(i.split()) <= 2 for i in items):
            out.append(items)
    pattern = (
        r"\b(?:choose|select|set|pick)\s+(?:an?\s+|the\s+)?"
        rf"((?:[\w-]+,\s*)+[\w-]+\s+or\s+[\w-]+)\s+{w}"
    )
    for m in re.finditer(pattern, text, re.I):
        items = [_clean_item(i) for i in re.split(r",\s*|\s+or\s+", m.group(1))]
        if len(items) >= 2:
            out.append(items)
    found = named_list(text, word)
    if found:
        out.append(found)
    return out


def named_list(text: str, word: str) -> list[str] | None:
    """A sentence that is the setting's list of names: "The menu names printed on the lid: WHITE
    · BROWN · PORRIDGE". Unlike a passing "(for the menus (WHITE, BROWN))", the whole sentence
    is about that setting, so it says nothing about the key next to it."""
    w = re.escape(word)
    named = re.search(rf"\b{w}\w*\s+{_NAMES_NOUN}\b[^:.;]{{0,60}}:\s*(.+)$", text, re.I)
    return bare_list(named.group(1)) if named else None


_ASIDE_PAREN_RE = re.compile(r"\s*(?:and|or|also|plus|e\.g\.|i\.e\.|see|if)\b", re.I)
"""A parenthesis that adds a step, an example or a reference, not the setting's values."""
_NAMES_NOUN = r"(?:names|settings|options|choices|positions)"


_RUN_CUE = re.compile(  # a lookahead: every cue is tried
    r"(?=\b(?:printed|marked|markings?|labell?ed|reads?|positions?|settings?|scale|steps?|values?"
    r"|levels?|(?:lamps?|leds?|indicators?|lights?)\s+(?:show|read|mark))\b[^:.;]{0,30}?:?\s*(.*))",
    re.IGNORECASE,
)


def find_number_run(text: str) -> list[str] | None:
    """Numbers printed in a row after a cue ("marked 20 30 40 60 90"), in their order; a leading
    OFF reads as 0, another leading word (a named end position) is skipped."""
    for m in _RUN_CUE.finditer(text):
        # a mark's gloss is no break in the row: "0 (no spin)  400  600", "COLD (cold)  20  30"
        row = re.sub(r"(?<=\S)\s*\([^()]{1,20}\)(?=\s)", " ", m.group(1))
        tokens = [t.strip(".*:") for t in re.findall(r"[^\s,;]+", row)][:40]
        for start in range(min(8, len(tokens))):
            run: list[str] = []
            rest = tokens[start:]
            if rest and re.fullmatch(r"[A-Z][A-Z-]{1,9}", rest[0]):
                if rest[0].lower() == "off":
                    run.append("0")
                elif rest[0].lower() in ("cold", "cool"):  # a wash knob's first mark: a value
                    run.append(rest[0].lower())
                rest = rest[1:]
            for token in rest:
                if re.fullmatch(r"\d+(?:[.,]\d+)?", token):
                    run.append(token)
                else:
                    break
            if len(run) >= 3:
                return run
    return None


def _dedupe(items: list[str]) -> list[str]:
    seen: list[str] = []
    for item in items:
        if item.lower() not in (s.lower() for s in seen):
            seen.append(item)
    return seen


ON_OFF_RE = re.compile(
    r"\bon\s*(?:/|or|and)\s*off\b|\boff\s*(?:/|or|and)\s*on\b|\btoggles?\b"
    r"|\b(?:enable|disable|activate|deactivate)s?\b[^.]*\b(?:or|and|/)\b"
    r"|\bagain to (?:switch|turn|cancel|deactivate|disable)\b"
    r"|\b(?:switch|turn)\w*\s+(?:\w+\s+){0,3}(?:on|off)\s+(?:or|and|/)\s+(?:\w+\s+){0,2}(?:on|off)\b",
    re.IGNORECASE,
)
EACH_PRESS_RE = re.compile(
    r"\b(?:each|every|repeated(?:ly)?|successive)\s+(?:press|touch|tap|push"
    # ("every click of the dial changes the temperature": the dial's detents, not presses; "each
    # press of the timer knob" is a press all the same)
    r"|click(?!\w*\s+of\s+the\s+(?:\w+\s+)?(?:dial|knob|wheel|ring|selector|encoder)\b))",
    re.I,
)
