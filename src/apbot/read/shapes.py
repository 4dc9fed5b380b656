"""Shapes a manual's units take that the reader looks for: the words of roles and settings,
what evidence about a control holds, and small tests on units (a keypad range, a column of
advice, a section that only mentions values, a unit family). Reading the table column or the
bullets after a unit is shapes_columns.py's job."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.labels import words
from apbot.read.quantity_units import QUANTITY_FAMILIES, _quantity_units
from apbot.read.text import Unit
from apbot.read.values import Range

LAMP_LIST_RE = re.compile(
    r"^\W*(?:the\s+)?(?:[\w-]+\s+){0,2}(?:lamps?|indicators?|symbols?|icons?|LEDs?|lights)\b"
    r"(?:\s*\([^)]*\))?\s*:",
    re.IGNORECASE,
)
UP_WORDS = {"up", "plus", "more", "increase", "inc", "higher", "add", "right", "next", "forward"}
DOWN_WORDS = {"down", "minus", "less", "decrease", "dec", "lower", "left", "prev", "previous"}
POWER_TOKENS = {"power", "on_off", "onoff", "on", "power_on_off", "standby"}
STOP_WORDS = {"stop", "cancel", "clear", "reset", "off", "end"}
GENERIC_DIALS = {"dial", "knob", "select", "selector", "jog", "wheel", "control"}
SETTING_NOUNS = (
    "temperature", "humidity", "timer", "time", "delay", "level", "power", "speed", "volume",
    "weight", "programme", "program", "mode", "setting", "heat", "strength", "size",
)  # fmt: skip
CHOICE_WORDS = {"programme", "program", "prog", "menu", "mode", "function", "cycle", "course",
                "dial", "knob", "selector", "select"}  # fmt: skip
GROUP_NOUNS = ("programme", "program", "menu", "mode", "function", "cycle", "course", "preset")
GROUP_PLURALS = "|".join(f"{w}s?" for w in GROUP_NOUNS)  # in a pattern: "programmes?|…"
RUNNING_RE = re.compile(
    r"\b(?:while|during|when)\b[^.]*\b(?:running|cooking|operat\w*|works?|working|heating|"
    r"washing|in progress|runs)\b[^.]*\b(?:only|ignored|not respond|do not work|disabled|no effect"
    r"|locked|inactive)\b|\bonly\b[^.]*\bwork\w*\b[^.]*\bwhile\b",
    re.IGNORECASE,
)


ORDER_RE = re.compile(r"\bin (?:this|the following|that) order\b", re.I)
# "Press AUTO COOK until the menu you want is displayed (see table)": only for the key it names
TABLE_POINTER_RE = re.compile(r"\(see (?:the )?table\)|\bthe table below\b", re.I)


@dataclass
class Evidence:
    values: list[str] | None = None
    values_at: int | None = None
    ranges: list[Range] = field(default_factory=list)
    range_at: int | None = None
    step: tuple[float, str] | None = None
    step_at: int | None = None
    toggle_at: int | None = None
    each_press_at: int | None = None
    initial: Any = None
    initial_at: int | None = None
    keypad_at: int | None = None  # a sentence of its context speaks of the number keys
    longest: tuple[Range, int] | None = None  # "the longest setting is 13 hours", alone
    shows: dict[str, str] | None = None  # each value's figure printed for it ("warm": "3000K")
    shown_hmm: tuple[int, int] | None = None  # (minutes, unit): "the display shows 9:30"


_TIMER_WORDS = frozenset({"timer", "delay", "preset", "reserve", "finish"})


def _all_names(items: list[str], text: str) -> bool:
    """Five or more short names that make up the whole line."""
    covered = sum(len(v) for v in items)
    return len(items) >= 5 and max(map(len, items)) <= 24 and covered >= 0.7 * len(text)


def _keyish(items: list[str], others: set[str], own: set[str], text: str = "") -> bool:
    """A list naming two or more keys (other keys, the key itself, symbols such as + and −) —
    unless the arrows come back round to its first item ("AUTO → STERI+DRY → STERI → DRY →
    STORE → AUTO"): keys pressed one after another never wrap, values a key steps through do,
    so a cycle is a list of values even where some share a name with a key."""
    named = sum(
        v.lower() in others or v.upper() in own or not re.search(r"[^\W_]", v) for v in items
    )
    return named >= 2 and not (named < len(items) and comes_round(items, text))


# the arrows a cycle is drawn with: "AUTO → DRY → AUTO", "P1 ► P2 ► P1"
CYCLE_ARROW = r"\s*(?:→|->|⟶|►|▶)\s*"


def comes_round(items: list[str], text: str) -> bool:
    """The text steps from the list's last item back to its first by an arrow ("… → STORE →
    AUTO" after "AUTO → …")."""
    if len(items) < 3 or not text:
        return False
    first, last = (re.escape(v.strip()) for v in (items[0], items[-1]))
    return bool(re.search(rf"(?<!\w){last}{CYCLE_ARROW}{first}(?!\w)", text, re.IGNORECASE))


def _without(text: str, labels: list[str]) -> str:
    """The text with these key names (printed in capitals) taken out."""
    for label in labels:
        if re.search(r"[A-Z]", label):
            text = text.replace(label, " ")
    return text


_KEYPAD_WORDS = re.compile(r"\b(?:numbers?|numeric|digits?|keypad|numerals?)\b", re.IGNORECASE)


def _cell_key(cell: str) -> str:
    """A table cell as a key's printed name compares (no markup, case or end dots, nor the
    letter a lettered legend puts before the name: "(C) SPEED")."""
    return re.sub(r"^\s*\([A-Za-z]\)\s+(?=\S)|[*_`]+", "", cell).strip(" .:").upper()


def _keypad(r: Range, text: str) -> bool:
    """ "0 – 9: number keys" (or "keys 0-9", "0–9 buttons") names the keypad, and "pads 1 to 6"
    ("buttons 1–4") some of its keys, not a setting's range."""
    if r.unit:
        return False
    span = rf"{r.low:g}\s*(?:-|–|—|to)\s*{r.high:g}"
    if re.search(
        rf"\b(?:keys|buttons|pads)\s+{span}\b|\b{span}\s+(?:keys|buttons|pads)\b", text, re.I
    ):
        return True
    if r.low != 0 or r.high != 9:
        return False
    return bool(
        _KEYPAD_WORDS.search(text)
        # "0-9, AWAY, OFF": the digit keys listed with the other keys
        or re.search(r"(?<![\w.])0\s*[-–—]\s*9\s*,\s*[A-Z*#]|[A-Z*#]\s*,\s*0\s*[-–—]\s*9\b", text)
        or re.search(r"\b(?:keys|buttons|pads)\s+0\s*(?:-|–|—|to)\s*9\b", text, re.I)
        or re.search(r"\b0\s*(?:-|–|—|to)\s*9\s+(?:keys|buttons|pads)\b", text, re.I)
    )


def _numeric_items(items: list[str]) -> bool:
    """Every item is a number, perhaps with a short unit ("40", "35 %", "2h")."""
    return bool(items) and all(
        re.fullmatch(r"\s*\d+(?:[.,]\d+)?\s*(?:[^\s\d]{0,4}|[A-Za-z]{1,8})\s*", i) for i in items
    )


RUN_RE = re.compile(r"\d+(?:[.,]\d+)?(?:\s*[·•]\s*(?:\|\s*)?\d+(?:[.,]\d+)?){2,}")
ASIDE_HEADING = re.compile(
    r"\b(?:safety|safeguards?|warnings?|cautions?|precautions?|trouble-?\s?shooting|faults?"
    r"|fault finding|problems?|error codes?|maintenance|warranty|guarantee"
    # cleaning the appliance is care; a cleaner's own "Cleaning modes" is what it is set to do
    r"|cleaning(?!\s+(?:modes?|programm?e?s?|cycles?|levels?|settings?|options?|functions?"
    r"|power|types?|patterns?|paths?|areas?|zones?|schedules?)\b)"
    r"|disposal|customer)\b"
    # recipes to make by hand ("RECIPES", "Tips and recipes"), not the appliance's own stored
    # ones, which its keys choose ("Automatic recipes: POPCORN → POTATO → …")
    r"|^(?!.*\b(?:auto(?:matic)?|preset|programmed|built-in|stored|one-touch)\s+recipes)"
    r".*\brecipes\b"
    # worked key sequences, values in passing ("EXAMPLES", "PROGRAMMING EXAMPLES"); not a
    # setting's own examples ("Power level examples": its list)
    r"|^[\W\d.]*(?:\w+ing\s+|worked\s+)?examples\b"
    # "care" only as the section's own word ("Care", "Care and cleaning", "Cleaning and care"),
    # never inside a programme's name ("Easy Care", "Baby care")
    r"|^[\W\d.]*care\b(?!\s+(?:programs?|programmes?|cycles?|modes?|settings?)\b)"
    r"|\b(?:and|&)\s+care\b",
    re.IGNORECASE,
)
EXAMPLE_RE = re.compile(r"^\s*(?:examples?|e\.\s?g\.|for (?:example|instance))\b", re.IGNORECASE)


ADVICE_WORDS = frozenset({"suggested", "recommended", "typical", "advised", "usual", "ideal"})


_ADVICE_PROSE_RE = re.compile(  # "45 to 55 % is a sensible target", "ideally 40–60 %"
    r"\b(?:suggested|recommended|typical|advised|ideal|ideally|sensible|advisable|comfortable"
    r"|healthy)\b",
    re.IGNORECASE,
)


_WAIT_RE = re.compile(  # "Leave for one to two hours", "let it stand for 5–10 minutes"
    r"(?:^|[.;:]\s+|^\d+[.)]?\s+)(?:then\s+)?(?:leave|wait|let\s+(?:it|them|the\s+\w+)\s+"
    r"(?:stand|rest|soak|cool))\b[^.;]{0,20}?\bfor\b",
    re.IGNORECASE,
)


def is_wait(text: str) -> bool:
    """A sentence telling the user to wait ("3. Leave for one to two hours, then …"): its
    times are a wait, not the limits of a setting named nearby."""
    return bool(_WAIT_RE.search(text))


def _without_advice(unit: Unit) -> str:
    """A unit's text without the cells of columns headed as advice ("Suggested °C": what suits
    a food, not the limits of the setting); a sentence of advice ("in most homes 45 to 55 % is
    a sensible target") gives no limits at all."""
    if not unit.cells:
        return "" if _ADVICE_PROSE_RE.search(unit.text) else unit.text
    if len(unit.header) != len(unit.cells):
        return unit.text
    return " | ".join(
        cell
        for head, cell in zip(unit.header, unit.cells, strict=True)
        if not set(words(head)) & ADVICE_WORDS
    )


def _same_word(a: str, b: str) -> bool:
    """The same word, or one word inflected ("timer"/"timers", "programme"/"programmes",
    "temperature"/"temp"), not merely sharing a start ("cook"/"cookware")."""
    short, long = sorted((a, b), key=len)
    if long.startswith(short[:6]) and len(short) >= 6:
        return True
    rest = long[len(short) :] if long.startswith(short) else None
    abbreviation = short in ("temp", "prog", "func", "prep")
    return rest is not None and (rest in ("", "s", "es", "ing", "ed", "er", "ers") or abbreviation)


def _aside(units: list[Unit], i: int) -> bool:
    """A unit that names values in passing, never a setting's list of them: a worked example
    ("Example: it is 9 pm. You choose BASIC, 2.0 LB."), or a sentence under a safety,
    troubleshooting, care or warranty heading ("Select UV, DRY or STORE" as a remedy). Ranges
    are still read there."""
    unit = units[i]
    if EXAMPLE_RE.match(unit.text):
        return True
    before = units[i - 1] if i else None
    if (
        before is not None
        and EXAMPLE_RE.match(before.text)
        and not unit.bullet
        and not unit.cells
        and unit.line - before.line <= 1
    ):
        return True  # the example's next sentence
    return bool(unit.heading) and bool(ASIDE_HEADING.search(unit.heading))


def _fits(unit: str, tokens: list[str]) -> bool:
    """A range's unit can belong to the control: no minutes for a temperature, no degrees for a
    timer, no watts for a volume (the sentence after a key often gives a neighbouring
    setting's range)."""
    expected = set(_quantity_units(tokens))
    timeish = {"s", "min", "h"}
    if not expected and unit and {"power", "wattage"} & {w for t in tokens for w in words(t)}:
        # a power is a level, a percentage or watts, never degrees or a time ("TEMP replaces
        # the power setting by a temperature, 60–240 °C" speaks of another setting)
        return unit not in ("°C", "°F", *timeish)
    if not expected or not unit:
        return True
    if expected & {"°C"}:
        return unit in ("°C", "°F", "") or (unit == "W" and _heat_only(tokens))
    if expected & {"min"}:
        return unit in timeish
    if expected & {"%"}:
        return unit == "%"
    for canonical, family in QUANTITY_FAMILIES.items():
        if canonical in expected:
            return unit in family
    return True


def _heat_only(tokens: list[str]) -> bool:
    """A control named for heat, not for a temperature ("heat selector", "HEAT"): a heater's heat
    is as often its output in watts ("750 W / 1500 W") as a temperature."""
    ws = {w for t in tokens for w in words(t.replace("_", " "))}
    return "heat" in ws and not ws & {"temp", "temperature", "time", "timer"}


def _value_text(value: str) -> str:
    text = re.sub(r"\s+", " ", value.strip().lower())
    text = re.sub(r"(?<=\d)['’′]$", "", text)  # "Quick 15'": a minute mark, not part of the name
    return text.strip(" .,;:")


def adjuster_direction(info: ActionInfo) -> tuple[str, str] | None:
    """(base, "up"|"down") for a stepping key: ``temp_up`` → (temp, up), ``minus`` → ("", down)."""
    if info.skill != "press" or info.digit is not None:
        return None
    parts = info.token.split("_")
    for i, part in enumerate(parts):
        core = re.sub(r"\d+$", "", part)
        suffix = part[len(core) :]
        if core in UP_WORDS or core in DOWN_WORDS:
            base = "_".join(parts[:i] + parts[i + 1 :]) + suffix
            if core == "add" and (base or not suffix):
                continue  # add30, add_in: not a stepping key
            return base, "up" if core in UP_WORDS else "down"
    return None
