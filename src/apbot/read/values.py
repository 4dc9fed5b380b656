"""Ranges, steps and amounts in manual prose and tables.

"35 % to 85 %", "0:30–24:00", "in 5% steps", "each touch adds one hour", "the longest delay is
24 hours": the few shapes manuals use to say how far a setting goes and how it moves. Every
finder returns what it read and nothing it did not (None), so the builder can tell evidence
from guesses. Lists of named values are in value_lists.py; ranges told in pieces, each with its
own step (a flattened range table, an arrow chart), in values_stepped.py; a step or a start
value said in a sentence ("5 °C per press", "the default is 30 minutes") in value_steps.py.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass

from apbot.model.values import unit_of, words_to_number
from apbot.read.values_labels import clock_seconds, clock_tops, minutes_and_seconds
from apbot.read.values_more import further_top
from apbot.read.values_tails import gaps, listed_amounts, listed_tail, worked_example

NUM = (
    r"(?:\d+(?:[.,]\d+)?|one|two|three|four|five|six|seven|eight|nine|ten|twelve|fifteen"
    r"|twenty|thirty|half)"
)
UNIT = (
    r"(?:%|°\s?[CF]|°|degrees?|min(?:ute)?s?|h(?:ou)?rs?|hours?|h|sec(?:ond)?s?|s|rpm|W|watts?"
    r"|kg|lbs?|oz|g|ml|[µμ]l|microlit(?:re|er)s?|L|litres?|cups?|mm|cm|(?:milli|centi)met(?:re|er)s?"
    # a light's colour temperature ("3200 K", "2700 kelvin"); the capital only, since "k" after
    # a figure is as often a thousand ("10k")
    r"|(?-i:K)|kelvins?)"
)
_TIME = r"\d{1,2}:\d{2}"
_DASH = r"\s*(?:–|—|-|to|and|~|until)\s*"
RANGE_RE = re.compile(
    rf"(?<![\w:.])({NUM})\s*({UNIT})?{_DASH}({NUM})\s*({UNIT})?(?![\w:])", re.IGNORECASE
)
# three or more values joined by dashes, the unit after the last: "35 - 40 - 45 - 50 %"; the
# same dash each time ("1–4 – 30–45 min" is two ranges side by side, no chain)
CHAIN_RE = re.compile(
    rf"(?<![\w:.])(?P<run>{NUM}(?P<sep>\s*[-–]\s*){NUM}(?:(?P=sep){NUM})+)\s*(?P<unit>{UNIT})?"
    r"(?![\w:])",
    re.IGNORECASE,
)
# a setting that "stops at 1 h and at 12 h" (no wrap): those are its ends
STOPS_RE = re.compile(
    rf"\bstops?\s+at\s+({NUM})\s*({UNIT})?(?!\w)\s*(?:,\s*)?and\s+(?:at\s+)?({NUM})\s*({UNIT})?"
    r"(?![\w:])",
    re.IGNORECASE,
)
TIME_RANGE_RE = re.compile(rf"(?<![\d:])({_TIME}){_DASH}({_TIME})(?![\d:])")
# "0:30 – 0:45 – 1:00 – 1:15": a chain of clock values one by one, not the range of its first two
TIME_CHAIN_RE = re.compile(
    rf"(?<![\d:])(?P<run>{_TIME}(?P<sep>\s*[-–]\s*){_TIME}(?:(?P=sep){_TIME})+)(?![\d:])"
)
UPTO_RE = re.compile(rf"\bup to\s+({NUM})\s*({UNIT})(?!\w)", re.IGNORECASE)
STEP_RE = re.compile(
    rf"(?:in\s+({NUM})\s*-?\s*({UNIT})?\s*(?:steps|increments|stages|units)(?!\s+of\b)"
    rf"|(?:steps?|increments?|units?)\s+of\s+({NUM})\s*({UNIT})?"
    rf"|(?:each|every)\s+(?:press|touch|turn|click|tap|step)[^.;]*?"
    rf"(?:adds?|removes?|subtracts?|by|changes?[^.;]*?by|raises?|moves?[^.;]*?by)\s+(?:an?\s+|another\s+)?({NUM})?\s*({UNIT})(?!\w)"
    # "Each press moves the start time one hour later": the step, said as how far it moves
    rf"|(?:each|every)\s+(?:press|touch|turn|click|tap)\s+moves?\s+(?:the\s+|it\s+)?(?:[a-z]+\s+){{0,2}}?"
    rf"({NUM})\s*({UNIT})\s+(?:later|earlier|forward|ahead|back)\b)",
    re.IGNORECASE,
)


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
    if t == "K" or low in ("kelvin", "kelvins"):
        return "K"
    info = unit_of(low)
    if info and info[0] == "time":
        return {1: "s", 60: "min", 3600: "h"}[int(info[1])]
    if info and info[0] == "length":  # "millimetres" is mm
        return {0.001: "µm", 1: "mm", 10: "cm"}[info[1]]
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


def gap_pieces(values: list[float], unit: str) -> list[Range]:
    """Climbing numbers as pieces, each run of equal gaps one piece with its gap as the step
    (160, 180, 200, 210, 220 → 160–200 by 20, 200–220 by 10): a scale printed stop by stop."""
    pieces: list[Range] = []
    for low, high in itertools.pairwise(values):
        gap = round(high - low, 6)
        if pieces and pieces[-1].step == gap:
            pieces[-1] = Range(pieces[-1].low, high, unit, gap)
        else:
            pieces.append(Range(low, high, unit, gap))
    return pieces


_UNIT_ONLY = re.compile(UNIT, re.IGNORECASE)
_FOREIGN_UNIT = re.compile(
    r"\s*(?:V|VAC|Hz|kHz|mm|cm|m|nm|µm|mA|mAh|dB|dBA|kWh|VA|bar|MPa|kPa|psi|Pa|lux)(?![\w])"
)  # units no setting of a household appliance is set in: ratings and sizes
# units of a rating or a size ("4 - 14 Ah", "20 - 30 m²") that a charger's or a room
# appliance's setting may still be chosen in when the sentence tells to ("choose … 20 - 200 Ah")
_RATED_UNIT = re.compile(r"\s*(?:Ah|m[²³23]|ft[²2])(?![\w])")
_SET_VERB = re.compile(r"\b(?:set|sets|setting|choose|select|adjust)\b", re.IGNORECASE)


_ASIDE_RE = re.compile(  # "1 (barely warm)": words in brackets, no number and no unit
    # (after the number's unit too: "between 62 cm (lowest) and 127 cm (highest)", set16)
    rf"(?<=\d)(\s*(?:{UNIT})(?!\w))?\s*\((?!\s*{UNIT}\s*\))[^()\d]{{3,30}}\)",
    re.IGNORECASE,
)


# "from 3200 K (warm, like tungsten or halogen lamps) to 5600 K": between a "from" amount and
# its "to", an aside of any words (a gloss of the low end) stays an aside, however long
_FROM_ASIDE_RE = re.compile(
    rf"(\bfrom\s+\d+(?:[.,]\d+)?)(\s*(?:{UNIT})(?!\w))?\s*\((?!\s*{UNIT}\s*\))[^()\d]{{3,60}}\)"
    rf"(?=\s*to\s+\d)",
    re.IGNORECASE,
)


# "5 min … 30 min", "80 … 200 °C": an ellipsis between two lone amounts spans a range; in a
# list ("10, 15, 20 … 60", "0:35, 0:40 … 2:55") it stands for the items left out
_ELLIPSIS_SPAN_RE = re.compile(
    rf"(?<![\d:.])(\d+(?:[.,]\d+)?(?:\s*{UNIT})?)\s+(?:…|\.{{3}})\s+"
    rf"(?=\d+(?:[.,]\d+)?(?:\s*{UNIT})?(?!\d|[.,]\d|\s*,))",
    re.IGNORECASE,
)


def _spanned(m: re.Match[str]) -> str:
    listed = re.search(r"\d\s*\S{0,3}\s*,\s*$", m.string[: m.start()])  # "10, 15, 20 … 60"
    # a bare "1 … 10" may be a key sequence's digits; an amount names its unit
    unit = re.match(rf"\s*\d+(?:[.,]\d+)?\s*{UNIT}(?!\w)", m.string[m.end() :], re.I)
    if listed or not (unit or re.search(r"[^\d\s.,]", m.group(1))):
        return m.group(0)
    left = unit_name(re.sub(r"^[\d.,]+\s*", "", m.group(1)))
    right = unit_name(re.sub(r"^\s*[\d.,]+\s*", "", unit.group(0))) if unit else ""
    if left and right and not _same_kind(left, right):
        return m.group(0)  # "20 min … 180 °C": two settings side by side, no span
    return f"{m.group(1)} – "


def _same_kind(a: str, b: str) -> bool:
    """Whether two canonical units measure the same thing (min and h; g and kg)."""
    return a == b or (is_time_unit(a) and is_time_unit(b)) or rescale(1, a, b) is not None


# "repeat steps 2 to 4", "(steps 1–5 above)": the manual's own numbered steps, no values; a
# reference is said as one ("repeat", "see", "as in", a bracket, "above"), since "set the heat
# in steps 1 to 9" and "in steps 1 to 9 minutes" are levels
_STEPS_SPAN = r"steps\s+\d+\s*(?:to|through|[-–])\s*\d+(?!\d|[.,]\d)"
_STEP_REFS_RE = re.compile(
    r"(?:(?<=\()|\b(?:repeat(?:ing)?|see|follow(?:ing)?|perform|complete|carry\s+out|redo"
    rf"|(?:as|described|given|shown)\s+in)\s+){_STEPS_SPAN}(?!\s*{UNIT}(?!\w))"
    rf"|\b{_STEPS_SPAN}(?=\s+(?:above|below|again|earlier)\b)",
    re.IGNORECASE,
)


def find_ranges(text: str) -> list[Range]:
    """Ranges written in the text (times h:mm in seconds with unit ``s``); a word or two in
    brackets after a number is an aside ("from 1 (barely warm) to 10 (full power)")."""
    if worked_example(text):
        return []
    text = _STEP_REFS_RE.sub(lambda m: re.sub(r"(?i)steps.*", "steps", m.group(0)), text)
    text = _ELLIPSIS_SPAN_RE.sub(_spanned, text)
    out = _ranges(text)
    out += [  # a list's unit is a unit, not the word after it ("pages 2, 4, 6 and 8 show …")
        Range(a, b, unit_name(u), gap)
        for a, b, u, gap in listed_amounts(text)
        if _UNIT_ONLY.fullmatch(u.strip())
    ]
    # a label saying how to read a clock range ("0:01 - 99:59 (min:s)") is no aside to drop
    bare = _ASIDE_RE.sub(
        lambda m: m[0] if minutes_and_seconds(text, m.start()) else m[1] or "", text
    )
    bare = _FROM_ASIDE_RE.sub(lambda m: m[1] + (m[2] or ""), bare)
    return out + [r for r in _ranges(bare) if r not in out] if bare != text else out


def _ranges(text: str) -> list[Range]:
    out: list[Range] = []
    timed = [(m.start(), m.end()) for m in TIME_CHAIN_RE.finditer(text)]
    for m in TIME_CHAIN_RE.finditer(text):
        min_sec = minutes_and_seconds(text, m.end())
        stops: list[float] = [clock_seconds(x, min_sec) for x in re.findall(_TIME, m.group("run"))]
        if stops == sorted(set(stops)):
            between = gaps(stops)
            out.append(
                Range(stops[0], stops[-1], "s", between.pop() if len(between) == 1 else None)
            )
    for m in TIME_RANGE_RE.finditer(text):
        if any(a <= m.start() < b for a, b in timed):
            continue  # a pair of values in a chain of them, not a range
        min_sec = minutes_and_seconds(text, m.end())  # "0:01 - 99:59 (min:s)"
        a, b = clock_seconds(m.group(1), min_sec), clock_seconds(m.group(2), min_sec)
        if a < b:
            out.append(Range(a, b, "s"))
    chains = [(m.start(), m.end()) for m in CHAIN_RE.finditer(text)]
    for m in CHAIN_RE.finditer(text):  # "0.5 - 1 - 1.5 - 2 h": the values one by one
        read = [number(x) for x in re.findall(NUM, m.group("run"))]
        figures = [x for x in read if x is not None]
        if len(figures) != len(read) or figures != sorted(set(figures)):
            continue
        between = gaps(figures)
        step = between.pop() if len(between) == 1 else None
        out.append(Range(figures[0], figures[-1], unit_name(m.group("unit")), step))
    for m in RANGE_RE.finditer(text):
        if TIME_RANGE_RE.search(m.group(0)):
            continue
        if any(a <= m.start() < b for a, b in chains):
            continue  # a pair of values in a chain of them, not a range
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
            elif (q1 := unit_of(first)) and (q2 := unit_of(unit)) and q1[0] != q2[0]:
                continue  # "about 20 s  To 350 °C": two quantities side by side, no range
        if lo is None or hi is None or not lo < hi:
            continue
        if not unit and m.group(0).strip().lower().split()[1:2] == ["and"]:
            continue  # "press A and B": no unit, "and" joins words more often than numbers
        if listed_tail(text, m):
            continue  # "40 %, 50 %, 60 % and 70 %": the last two items of a list, no range
        if unit == "" and (hi > 10_000 or _FOREIGN_UNIT.match(text, m.end())):
            continue  # "220–240 V", "12–32 cm": a rating or a size, not a setting's range
        if unit == "" and _RATED_UNIT.match(text, m.end()) and not _SET_VERB.search(text):
            continue  # "4 - 14 Ah  1 A": a capacity guide, not a capacity to choose
        if unit == "":
            hi = further_top(text, m.end(), hi)  # "1 to 9, or 1 and then 0 for level 10"
        out.append(Range(lo, hi, unit))
    for m in UPTO_RE.finditer(text):
        hi = number(m.group(1))
        if hi:
            out.append(_from_up_to(text, m.start(), hi, unit_name(m.group(2))))
    for m in STOPS_RE.finditer(text):  # "the value stops at 40 °C and at 55 °C": its ends
        lo, hi = number(m.group(1)), number(m.group(3))
        units = {unit_name(u) for u in (m.group(2), m.group(4)) if u}
        if lo is not None and hi is not None and lo < hi and len(units) <= 1:
            found = Range(lo, hi, units.pop() if units else "")
            if found not in out:
                out.append(found)
    # "up to 99:59"; a 12-hour clock's last minute ("up to 12:59") starts at 1:00
    twelve = 12 * 3600 + 59 * 60
    for top, at, min_sec in clock_tops(text):
        if top:
            low = _from_clock(text, at, min_sec)
            out.append(Range(3600 if top == twelve else low if low < top else 0, top, "s"))
    return out


# the low end said before an "up to" in its own clause: "from 30 °C up to 45 °C", "from 2:00
# (TIME 02:00) up to 8:00"; an "up to" alone starts from nothing
_FROM_RE = re.compile(
    rf"\bfrom\s+(?:(\d{{1,2}}:\d{{2}})(?![\d:])|({NUM})\s*({UNIT})?(?![\w:]))", re.IGNORECASE
)


def _from_match(text: str, at: int) -> re.Match[str] | None:
    head = re.split(r"[.;!?](?:\s|$)|:\s", text[:at])[-1]
    found = list(_FROM_RE.finditer(head))
    return found[-1] if found else None


def _from_up_to(text: str, at: int, high: float, unit: str) -> Range:
    """An "up to" amount's range: from the clause's "from" amount in a unit of the same
    kind, else from 0."""
    m = _from_match(text, at)
    low = number(m.group(2)) if m and m.group(2) else None
    first = unit_name(m.group(3)) if m and m.group(3) else unit
    if low is None or not _same_kind(first, unit):
        return Range(0, high, unit)
    if first != unit and is_time_unit(unit):
        high, unit = seconds(high, unit) / seconds(1, first), first
    elif first != unit and (same := rescale(high, unit, first)) is not None:
        high, unit = same, first
    return Range(low, high, unit) if low < high else Range(0, high, unit)


def _from_clock(text: str, at: int, min_sec: bool) -> int:
    """The seconds of a clock figure said "from" before an "up to" clock top, else 0."""
    m = _from_match(text, at)
    return clock_seconds(m.group(1), min_sec) if m and m.group(1) else 0


_FIRST_RE = re.compile(
    rf"\bfirst (?:press|tap|touch|push|click|turn)\b[^.;]*?\b(?:gives|shows|sets|is|selects)\s+"
    rf"({NUM})\s*({UNIT})(?!\w)",
    re.IGNORECASE,
)
MOST_RE = re.compile(
    rf"\b(?:longest|maximum|highest|heaviest|largest|max\.?)\b[^.;]*?\b(?:is|of)\s+({NUM})\s*"
    rf"({UNIT})(?!\w)",
    re.IGNORECASE,
)
# "Tap DEFROST once for every 100 g of food": each tap adds 100 g, the first gives 100 g
_ONCE_FOR_RE = re.compile(
    rf"\bonce\s+(?:for|per)\s+(?:each|every)\s+({NUM})\s*({UNIT})(?!\w)", re.IGNORECASE
)


_SHOWN_HMM_RE = re.compile(  # "until the display shows 9:30", "the display reads 2:45"
    r"\b(?:shows?|showing|reads?|displays?|indicates?)\b[^.;]{0,25}?(?<![\d:.])"
    r"(\d{1,2}):([0-5]\d)(?![\d:])(?!\s*(?:am|pm|a\.m|p\.m|o'clock)\b)",
    re.IGNORECASE,
)


def find_shown_hmm(text: str) -> int | None:
    """The minutes of a setting shown as hours:minutes in an example ("press TIME until the
    display shows 9:30": 30), or None: a setting told in hours that the display writes h:mm
    is a time, set in minutes."""
    m = _SHOWN_HMM_RE.search(text)
    return int(m.group(2)) if m else None


def find_bounds(texts: list[str]) -> Range | None:
    """A range told in two sentences: "the first tap gives 0.5 h" and "the longest
    reservation is 24 h" (the first value is also the step: each tap adds time); a time's
    longest setting alone ("the longest setting is 13 hours") is a range from 0."""
    first = most = None
    for text in texts:
        first = first or _FIRST_RE.search(text) or _ONCE_FOR_RE.search(text)
        most = most or MOST_RE.search(text)
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
        if is_time_unit(unit) and is_time_unit(top):
            high = seconds(high, top) / seconds(1, unit)
        elif (same := rescale(high, top, unit)) is not None:
            high = same  # "once for every 100 g" … "the heaviest setting is 2 kg": 2000 g
        else:
            return None
    return Range(low, high, unit, low) if low < high else None


ON_OFF_RE = re.compile(
    # ("off / on / flashing", "on / off / auto": a third state makes it a selector)
    r"\bon\s*(?:/|or|and)\s*off\b(?!\s*/\s*\w)|\boff\s*(?:/|or|and)\s*on\b(?!\s+again\b)(?!\s*/\s*\w)"
    r"|\btoggles?\b"
    r"|\b(?:enable|disable|activate|deactivate)s?\b[^.]*\b(?:or|and|/)\b"
    r"|\bagain to (?:switch|turn|cancel|deactivate|disable)\b"
    # ("kept when the sealer is switched off and on again": the appliance's power, no toggle)
    r"|\b(?:switch|turn)\w*\s+(?:\w+\s+){0,3}(?:on|off)\s+(?:or|and|/)\s+(?:\w+\s+){0,2}(?:on|off)\b"
    r"(?!\s+again\b)",
    re.IGNORECASE,
)
EACH_PRESS_RE = re.compile(
    r"\bonce\s+(?:for|per)\s+(?:each|every)\s+\d"  # "tap it once for every 100 g"
    # ("each further touch adds one hour": the presses after a first one that only shows it)
    r"|\b(?:each|every|repeated(?:ly)?|successive)\s+"
    r"(?P<further>(?:further|more|additional|subsequent|following|extra)\s+)?(?:press|touch|tap|push"
    # ("every click of the dial changes the temperature": the dial's detents, not presses; "each
    # press of the timer knob" is a press all the same)
    r"|click(?!\w*\s+of\s+the\s+(?:\w+\s+)?(?:dial|knob|wheel|ring|selector|encoder)\b))",
    re.I,
)
