"""Lists of values read as numbers or names a pad or dial steps through: ◄ ► pads and generic
dials over a named list, printed rows of numbers as ranges, knobs' end stops."""

from __future__ import annotations

import re
from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.end_stops import end_stops
from apbot.read.evidence_context import marked_start
from apbot.read.labels import words
from apbot.read.list_ellipsis import fill_ellipses
from apbot.read.roles_common import clock_list, numeric_list, stepped_noun, token_of
from apbot.read.shapes import Evidence, _fits
from apbot.read.shapes_columns import _next_table_column
from apbot.read.text import Unit
from apbot.read.value_steps import find_step
from apbot.read.values import find_ranges
from apbot.read.values_labels import seconds_said, whole_minutes_said
from apbot.read.values_tails import gaps

LIST_WORDS = {"left", "right", "prev", "previous", "next", "forward"}


def pair_of_names(b: Builder, base: str, pair: dict[str, list[str]]) -> bool:
    """A stepping pair whose sentences give a list of names (◄ ► "move through the cooking
    functions" above a table of them) steps that list as a setting of its own, both ways."""
    if not (pair["up"] and pair["down"]):
        return False
    tokens = [token_of(b, n) for n in pair["up"] + pair["down"]]
    if not all(set(t.split("_")) & LIST_WORDS for t in tokens):
        return False  # + − and ▲ ▼ set amounts (often for other keys); ◄ ► move through lists
    ev = b.evidence(tokens + ([base] if base in b.labels else []))
    if not ev.values:
        named = _named_column(b, tokens)
        if named is not None:
            ev = Evidence(values=[v.lower() for v in named[0]], values_at=named[1])
    if not ev.values or len(ev.values) < 3 or numeric_list(ev.values):
        return False
    noun = base or _list_noun(b, ev) or stepped_noun(b, tokens, None) or "selection"
    var = b.add_discrete(noun, ev.values, noun.upper(), ev)
    eff = {**{a: "next" for a in pair["up"]}, **{a: "prev" for a in pair["down"]}}
    b.feature(
        f"select_{var}", [{"actions": pair["up"] + pair["down"], "variable": var, "effect": eff}]
    )
    b.note(f"variables.{var}.values", ", ".join(b.variables[var]["values"]), ev.values_at)
    return True


_FINE_TUNE_RE = re.compile(  # "MORE and LESS fine-tune the result", "… comes out underdone"
    r"\b(?:fine[- ]?tunes?|adjusts?\s+the\s+result|underdone|overdone|doneness"
    r"|standard\s+setting)\b",
    re.IGNORECASE,
)


def more_less_pair(b: Builder, base: str, pair: dict[str, list[str]]) -> bool:
    """MORE and LESS keys that fine-tune an automatic programme's result ("press MORE for food
    that comes out underdone … pressing the other key returns to the standard setting") set
    a choice of three, less / standard / more, not an amount of another key. They leave the
    pair (+ and − stay); True when nothing is left of it."""
    more = [a for a in pair["up"] if token_of(b, a) == "more"]
    less = [a for a in pair["down"] if token_of(b, a) == "less"]
    if base or len(more) != 1 or len(less) != 1:
        return False
    up, down = "more", "less"
    told = next(
        (i for i in b.context([up, down]) if _FINE_TUNE_RE.search(b.manual.units[i].text)), None
    )
    if told is None:
        return False
    label = (
        f"{b.labels[up].text}/{b.labels[down].text}"
        if up in b.labels and down in b.labels
        else "MORE/LESS"
    )
    ev = Evidence(values=["less", "standard", "more"], initial="standard", values_at=told)
    var = b.add_discrete("adjust", ev.values or [], label, ev)
    b.variables[var]["wrap"] = False
    b.feature(
        f"set_{var}",
        [
            {
                "actions": more + less,
                "variable": var,
                "effect": {more[0]: "next", less[0]: "prev"},
            }
        ],
    )
    b.note(f"variables.{var}.values", "less, standard, more: MORE/LESS fine-tune a result", told)
    pair["up"].remove(more[0])
    pair["down"].remove(less[0])
    return not (pair["up"] or pair["down"])


def dial_list(b: Builder, token: str, cw: list[str], ccw: list[str]) -> bool:
    """A generic dial ("SELECT dial: turn to pick a program, or to change the temperature
    after TEMP") whose sentences name a list of names: turning it alone steps that list."""
    ev = b.evidence([token])
    values = ev.values if ev.values and not numeric_list(ev.values) else None
    at = ev.values_at
    named = _named_column(b, [token]) if values is None else None
    if named is not None:
        values, at = [v.lower() for v in named[0]], named[1]
    if not values or len(values) < 3:
        return False
    found = Evidence(values=values, values_at=at)
    noun = _list_noun(b, found) or "programme"
    var = b.add_discrete(noun, values, noun.upper(), found)
    eff = {**{a: "next" for a in cw}, **{a: "prev" for a in ccw}}
    b.feature(f"select_{var}", [{"actions": cw + ccw, "variable": var, "effect": eff}])
    b.note(f"variables.{var}.values", ", ".join(b.variables[var]["values"]), at)
    return True


def _named_column(b: Builder, tokens: list[str]) -> tuple[list[str], int] | None:
    """A table column of names headed by a noun the keys' own sentences use ("◄ ► move
    through the cooking functions" and a table with a "Function" column)."""
    units = b.manual.units
    said = {
        w[:5]
        for t in tokens
        if t in b.labels
        for i in b.labels[t].mentions
        for w in words(units[i].text)
        if len(w) >= 4
    }
    for i, unit in enumerate(units):
        if not unit.cells or unit.header:
            continue  # only header rows
        for column, cell in enumerate(unit.cells):
            cw = words(cell)
            if len(cw) == 1 and len(cw[0]) >= 4 and cw[0][:5] in said:
                values = _next_table_column(units, i - 1, column)
                if len(values) >= 3:
                    return values, i
    return None


def _list_noun(b: Builder, ev: Evidence) -> str:
    """The header of the table column a list was read from ("Function"), if any."""
    if ev.values_at is None:
        return ""
    units = b.manual.units
    for unit in units[ev.values_at : ev.values_at + 3]:
        if unit.header:
            for cell in unit.header:
                if words(cell) and not re.fullmatch(r"[#n]o?\.?|", cell.strip().lower()):
                    return "_".join(words(cell)[:2])
    return ""


def _nums(values: list[str]) -> list[float]:
    found = [re.match(r"\d+(?:[.,]\d+)?", v.strip()) for v in values]
    return sorted({float(m.group(0).replace(",", ".")) for m in found if m})


def listed_min_sec(b: Builder, key: ActionInfo, at: int | None) -> bool:
    """Whether the clock figures a key's list gives at unit ``at`` are minutes and seconds
    ("0:30 → 1:00 → … 5:00" and "Up to 2 minutes the steps are 30 seconds", or the key's
    time "shown as minutes:seconds")."""
    if at is None:
        return False
    units = b.manual.units
    label = b.labels.get(key.controls[0])
    about = [units[i].text for i in (label.mentions if label else [])]
    if seconds_said([u.text for u in units[at : at + 3]], about):
        return True
    # "The session time is 1 to 10 minutes … Each press adds one minute": 10:00 is ten minutes
    section = [u.text for u in units[max(0, at - 6) : at + 3] if u.heading == units[at].heading]
    figures = re.findall(r"(?<![\d:])\d{1,2}:\d{2}(?![\d:])", units[at].text)
    return whole_minutes_said(figures, section + about)


def list_evidence(ev: Evidence, min_sec: bool = False, said: str = "") -> Evidence:
    """A printed row of numbers as piecewise ranges, exactly those numbers (equal gaps share a
    piece: 20 30 40 60 90 is 20–40 by 10, 40–60 by 20, 60–90 by 30). Clock figures are h:mm,
    or m:ss when ``min_sec`` (the text around them says so); times of day that trail off in
    ``said`` (the row's text: "07:00 → 07:30 → 08:00 …") go on round the whole day."""
    from apbot.read.clock_rows import open_day_row
    from apbot.read.values import gap_pieces, unit_name

    day = None if min_sec else open_day_row(ev.values or [], said)
    if day is not None:
        return Evidence(ranges=[day], range_at=ev.values_at, initial=ev.initial,
                        initial_at=ev.initial_at)  # fmt: skip

    nums = _nums(ev.values or [])
    unit = unit_name(re.sub(r"[\d.,\s]", "", (ev.values or [""])[-1]))
    scale = 60 if min_sec else 3600

    def value_of(figure: str) -> float:
        if ":" not in figure:
            return float(figure.replace(",", "."))
        first, second = figure.split(":")
        return int(first) * scale + int(second) * scale // 60

    if clock_list(ev.values or []):  # h:mm (or m:ss): in seconds
        nums = sorted({value_of(v) for v in ev.values or []})
        unit = "s"
    if clock_list(ev.values or []) or not any(":" in v for v in ev.values or []):
        nums = fill_ellipses(nums, said, value_of)  # "3:00 … 9:00": 4:00 to 8:00 left out
    pieces = gap_pieces(nums, unit)
    initial = ev.initial
    if (
        isinstance(initial, str)
        and re.fullmatch(r"\d{1,2}:\d{2}|\d+(?:[.,]\d+)?", initial)
        and marked_start(initial, said)
    ):
        initial = (value_of(initial), unit)  # "600 (start setting)": a number, as ranges give it
    united = (
        re.fullmatch(r"(\d+(?:[.,]\d+)?)\s*([^\d\s]{1,4})", initial or "")
        if isinstance(initial, str)
        else None
    )
    if (
        united
        and unit
        and unit_name(united.group(2)) == unit
        and float(united.group(1).replace(",", ".")) in nums
    ):
        initial = (value_of(united.group(1)), unit)  # "set to 1500 W": one of the list's amounts
    return Evidence(
        ranges=pieces or [list_range(ev.values or [])],
        range_at=ev.values_at,
        initial=initial,
        initial_at=ev.initial_at,
    )


def list_range(values: list[str]) -> Any:
    from apbot.read.values import Range, unit_name

    nums = _nums(values)
    unit = unit_name(re.sub(r"[\d.,\s]", "", values[-1])) if values else ""
    return Range(nums[0], nums[-1], unit)


def list_step(values: list[str]) -> tuple[float, str] | None:
    nums = _nums(values)
    if len(nums) < 2:
        return None
    diffs = gaps(nums)
    return (min(diffs), "") if diffs else None


def dial_values(b: Builder, token: str) -> bool:
    if token not in b.labels or b.labels[token].line is None:
        return False
    ev = b.evidence([token])
    return bool(ev.values or ev.ranges)


ENDLESS_RE = re.compile(
    r"\bno (?:end )?stops?\b|\bturns? (?:freely|endlessly|all the way round)\b|\bendless\w*"
    r"|\b(?:simply )?continues with the first\b|\bround and round\b"
    r"|\bwithout (?:an? )?(?:end )?stop\b",
    re.IGNORECASE,
)


STOPS_RE = re.compile(  # (not "stops at the end of the heating period": that is the heating)
    r"\bstops? at (?:each|either|both|the) ends?\b(?!\s+of\b)|\bstops? at \S+ and (?:at )?\S+"
    r"|\bend stops?\b|\bwill not turn (?:past|beyond)"
    r"|\bcannot be turned (?:past|beyond)",
    re.IGNORECASE,
)


_IT_RE = re.compile(r"^It\b")
_KNOB_TALK_RE = re.compile(
    r"\b(?:turn\w*|rotat\w*|twist\w*|clicks?|positions?|detents?|marks?|notch\w*|round)\b"
    r"|\b(?:both|either|each|its|the) ends\b|\ball the way\b|\bend stops?\b",
    re.IGNORECASE,
)
"""An "It …" sentence about the knob itself: its turns, positions or ends ("It stops at the end
of the programme" speaks of the wash)."""


def dial_ends(b: Builder, token: str, var: str) -> None:
    """A knob the manual says stops at its ends clamps; one with no end stop goes round."""
    units = b.manual.units
    noun = re.compile(rf"\b{re.escape(token.replace('_', ' '))}\b", re.IGNORECASE)
    named = [i for i, u in enumerate(units) if noun.search(u.text)]
    # "The knob has seven positions. It clicks at each one and stops at both ends."
    named += [
        i + 1
        for i in named
        if i + 1 < len(units)
        and _IT_RE.match(units[i + 1].text)
        and _KNOB_TALK_RE.search(units[i + 1].text)
    ]
    own = set(b.labels[token].mentions if token in b.labels else []) | set(named)
    names = [lab.text for t, lab in b.labels.items() if t != token and lab.line is not None]
    others = {i for t, lab in b.labels.items() if t != token for i in lab.mentions}
    near = b.context([token]) + sorted(named) + _paragraph(units, own, others)
    for i in dict.fromkeys(near):  # "At 0 and at 28 further clicks do nothing": the value
        if i not in others and end_stops(units[i].text):  # stops, an endless knob or not
            b.variables[var]["wrap"] = False
            b.note(f"variables.{var}.wrap", "the setting stops at its ends", i)
            return
    for i in dict.fromkeys(near):
        text = units[i].text
        if i in others and i not in own:
            # "The knob stops at both ends. ④ ECO — …": what comes before another key's name
            cut = min((text.find(n) for n in names if n and n in text), default=-1)
            text = text[: max(cut, 0)]
        elif i not in own:
            said = [k for k in range(max(i - 3, 0), i) if k in own or k in others]
            if said and said[-1] in others and said[-1] not in own:
                continue  # "① PROGRAM selector — …. The knob turns all the way round."
        if ENDLESS_RE.search(text):
            b.variables[var]["wrap"] = True
            b.note(f"variables.{var}.wrap", "the knob has no end stop", i)
            return
        if STOPS_RE.search(text):
            b.variables[var]["wrap"] = False
            b.note(f"variables.{var}.wrap", "the knob stops at its ends", i)
            return


def _paragraph(units: list[Unit], own: set[int], others: set[int]) -> list[int]:
    """The units after each place the knob is named, up to the next control's name, in the same
    section (its marks drawn in a row, then "The knob has a stop at each end.")."""
    out: list[int] = []
    for i in sorted(own):
        for k in range(i + 1, min(i + 6, len(units))):
            if k in others or k in own or units[k].heading != units[i].heading:
                break
            out.append(k)
    return out


AMOUNT_NOUNS = ("temperature", "heat", "power", "speed", "volume", "level", "strength")


def dial_amount(b: Builder, token: str, cw: list[str], ccw: list[str]) -> bool:
    """A generic dial other keys hand values to ("TIMER — hands the knob over to the timer")
    that a section headed by an amount tells to turn by itself ("## Setting the temperature —
    Turn the knob."): turned alone, it sets that amount, read from that section."""
    units = b.manual.units
    turn = re.compile(rf"\b(?:turn|rotate|twist)\w*\b[^.]*?\b{re.escape(token)}\b", re.I)
    for i, unit in enumerate(units):
        if unit.text == unit.heading or not turn.search(unit.text):
            continue
        heading = words(unit.heading)
        noun = next((n for n in AMOUNT_NOUNS if n in heading), None)
        if noun is None or any(noun in words(v.replace("_", " ")) for v in b.variables):
            continue
        section = [k for k, u in enumerate(units) if u.heading == unit.heading]
        ev = Evidence()
        for k in section:
            found = [r for r in find_ranges(units[k].text) if r.unit and _fits(r.unit, [noun])]
            if found and not ev.ranges:
                ev.ranges, ev.range_at = found[:1], k
            step = find_step(units[k].text)
            if step and ev.step is None and _fits(step[1], [noun]):
                ev.step, ev.step_at = step, k
        var = b.add_number(noun, noun.upper(), ev, cyclic=False)
        eff = {**{a: "next" for a in cw}, **{a: "prev" for a in ccw}}
        b.feature(f"set_{var}", [{"actions": cw + ccw, "variable": var, "effect": eff}])
        b.note(f"features.set_{var}", f"turned by itself the {token} sets the {noun}", i)
        return True
    return False
