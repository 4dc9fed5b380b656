"""Whose a sentence, a table row or a list is: this control's or another's (a row's naming cell,
a press of another key, a step in another unit, the key's own name before its values). Small
tests the evidence reader puts to one piece of text; their own job, apart from the reading.
"""

from __future__ import annotations

import re

from apbot.read.shapes import _cell_key, _fits
from apbot.read.text import Unit
from apbot.read.value_steps import find_step
from apbot.read.values import unit_name


def _named_only(item: str, text: str) -> bool:
    """ "ONLY" printed in capitals as part of a name in capitals ("… → COOL ONLY → …") in a
    sentence in lower case: the value's own name, not a word saying where a list applies."""
    m = re.search(rf"(?<!\w){re.escape(item.strip())}(?!\w)", text, re.I)
    if not m or text.upper() == text:
        return False
    return bool(re.search(r"\bONLY\b", m.group(0))) and m.group(0).upper() == m.group(0)


def _fitting_step(text: str, tokens: list[str]) -> tuple[float, str] | None:
    """The step of this setting's unit ("Temperature steps: 5 °C … Time: 0:30 to 24:00 in
    30-minute steps"): a step in another unit is another setting's, even in the same line."""
    for piece in [text, *re.split(r"(?<=[.;])\s+", text)]:
        step = find_step(piece)
        if step and _fits(step[1], tokens):
            return step
    return None


# a legend's circled number: "③", "❹"
_CIRCLED = r"[\u2460-\u2473\u2776-\u277f]"


def lead_cell(cells: tuple[str, ...]) -> str:
    """A row's first cell that names something: a legend's circled or plain number ("④ |
    PUMP | Changes the speed: LO → MED → HI") only counts the rows."""
    for cell in cells[:2]:
        if not re.fullmatch(rf"\s*(?:{_CIRCLED}|\(?\d{{1,2}}[.)]?)\s*", cell):
            return cell
    return cells[0]


def lead_names(cell: str) -> list[str]:
    """What a row's naming cell may name: the whole cell, the name after the legend's number
    ("(5) REPEAT") and the name before a dash or colon that glosses it ("HEAT — heater OFF →
    ECO → FULL": a legend row's key is HEAT)."""
    bare = _LEGEND_MARK_RE.sub("", cell, count=1)
    head = re.match(r"\s*([^\s—–:][^—–:]{0,24}?)\s*(?:\s[—–-]|:)\s+\S", bare)
    return [cell, bare] + ([head.group(1)] if head and not head.group(1).isdigit() else [])


# the number or letter a legend puts before a part's name: "③", "(5)", "5.", "(C)"
_LEGEND_MARK_RE = re.compile(rf"^\s*(?:{_CIRCLED}|\(?\d{{1,2}}[.)]|\([A-Za-z]\))\s+")


def names_another(cells: tuple[str, ...], other_keys: set[str]) -> bool:
    """The row's naming cell names another key, alone or glossed ("③ | HEAT — heater …")."""
    return any(_cell_key(n) in other_keys for n in lead_names(lead_cell(cells)))


# a table column of keys: "Key", "Buttons", "Key(s)", "Key / element"
_KEY_NOUN = r"(?:key|button|control|element|symbol|part)(?:s|\(s\))?"
_KEY_HEAD = re.compile(rf"^\W*{_KEY_NOUN}(?:\s*/\s*{_KEY_NOUN})?\W*$", re.I)


_PRESS_VERB = r"\b(?:press|touch|tap|push)(?:es|ing)?\s+(?:and\s+hold\s+)?(?:the\s+)?"


def _presses_another(text: str, others: list[str], own: set[str]) -> bool:
    """The sentence tells to press another key ("Touch + to raise or – to lower the temperature
    by 5 °C with each touch") and never names this one: its "each press" is that key's."""

    def pressed(labels: list[str] | set[str]) -> bool:
        names = "|".join(re.escape(x) for x in sorted(labels, key=len, reverse=True) if x)
        if not names:
            return False
        return bool(re.search(rf"{_PRESS_VERB}(?:{names})(?!\w)", text, re.I))

    symbols = [*others, *("+", "-", "–", "▲", "▼")]
    named = any(re.search(rf"(?<!\w){re.escape(o)}(?!\w)", text, re.I) for o in own if o)
    return pressed(symbols) and not named  # ("Press WASH, RINSE or SPIN": RINSE's too)


def _after_own(text: str, own: set[str]) -> str:
    """What a sentence says after its last naming of this key ("Press HOURS, then press ▲ or
    ▼." → ", then press ▲ or ▼."): the keys pressed there are pressed after it, so an "each
    press" told next is theirs."""
    ends = [
        m.end() for o in own if o for m in re.finditer(rf"(?<!\w){re.escape(o)}(?!\w)", text, re.I)
    ]
    return text[max(ends) :] if ends else text


def _without_own_name(items: list[str], own: set[str]) -> list[str]:
    """Values quoted as the display prints them, the key's own name in front of each ("The
    display reads COLOR 1, COLOR 2 or COLOR 3." for COLOR): the values are what follows it."""
    for name in own:
        if not name or len(items) < 2:
            continue
        lead = re.compile(rf"^{re.escape(name)}\s+(\S.*)$", re.IGNORECASE)
        rest = [lead.match(item.strip()) for item in items]
        if all(rest):
            return [m.group(1) for m in rest if m]
    return items


_UNIT_ITEM = re.compile(r"\s*\d+(?:[.,]\d+)?\s*(°\s?[cf]|%|mins?|h|s|w|g|kg|ml)\s*", re.IGNORECASE)


def _foreign_units(items: list[str], tokens: list[str]) -> bool:
    """A list whose items carry a unit this control's setting cannot have ("95 → 90 → 85 °C"
    in a sentence that also presses TIMER): another setting's values, as a range in that
    unit would be."""
    for item in items:
        m = _UNIT_ITEM.fullmatch(item)
        if m and not _fits(unit_name(m.group(1)), tokens):
            return True
    return False


def _with_rows(units: list[Unit], i: int) -> str:
    """A table's row with the rows under it ("| 0:30 to 5:00 | 30 seconds |" then "| 5:00 to
    30:00 | 1 minute |"): a range told in pieces, a row a piece."""
    texts = [units[i].text]
    for unit in units[i + 1 : i + 5]:
        if not unit.cells or unit.header != units[i].header:
            break
        texts.append(unit.text)
    return " ".join(texts)


def _with_items(units: list[Unit], i: int) -> str:
    """A sentence with the list items right under it ("Press + … it." then "- from 0:00 to
    1:00 each press …", "- from 1:00 to 24:00 …"): a step told in pieces, an item a piece."""
    texts = [units[i].text]
    for unit in units[i + 1 : i + 5]:
        if not unit.bullet or unit.step is not None or unit.cells:
            break
        texts.append(unit.text)
    return " ".join(texts)


def _item_run(units: list[Unit], i: int) -> tuple[str, int]:
    """A list item with the items beside it ("- 1 to 10 minutes in 1-minute clicks," then "-
    then 10 to 120 minutes in 5-minute clicks."): the run of items a step told in pieces
    spans, and the unit leading them ("turn the SPEED knob to set the time:")."""
    lo = i
    while lo > 0 and lo > i - 4 and _plain_item(units[lo - 1]):
        lo -= 1
    hi = i + 1
    while hi < len(units) and hi < i + 5 and _plain_item(units[hi]):
        hi += 1
    return " ".join(u.text for u in units[lo:hi]), lo - 1


def _plain_item(unit: Unit) -> bool:
    return unit.bullet and unit.step is None and not unit.cells
