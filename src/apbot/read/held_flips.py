"""A hold that flips a setting between two values the display prints: "hold 2 s: KM/H <-> MPH",
"Hold MODE and SET together for 3 seconds. The display shows 24H or 12H".

Small panels give a key's hold a second job, and the legend writes that job as the two values
with a two-way arrow, or the section says the display shows one value or the other. The hold
then toggles a setting of those two values, named by the section that treats it ("5.1 Speed
unit (KM/H or MPH)", "5.3 Clock format"). Before, the values went to the key's press (a key's
legend line is its context) and a two-key hold was taken for the child lock.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_common import label_of, var_name
from apbot.read.roles_holdcell import _own_rows

# a value as a small display prints it: a short token with a capital or a digit ("KM/H", "12H")
_VALUE = r"(?=[^\s,;:]*[A-Z0-9])[A-Za-z0-9/.°%-]{1,8}"
_TWO_WAY = r"\s*(?:<->|<=>|↔|⇄|⟷)\s*"
# the hold's clause of a legend line: "hold 2 s on the speed screen: KM/H <-> MPH"
_HOLD_FLIP = re.compile(
    rf"\bhold\b[^;:.()]{{0,50}}[:–—-]\s*(?:[a-z]+\s+){{0,2}}({_VALUE}){_TWO_WAY}({_VALUE})(?=[\s;,.)]|$)",
    re.IGNORECASE,
)
# a two-key hold's sentence, or the one after it: "shows 24H or 12H", "24H <-> 12H"
_SHOWN_FLIP = re.compile(
    rf"\b(?:shows?|displays?|reads?)\s+({_VALUE})\s+or\s+({_VALUE})\b|({_VALUE}){_TWO_WAY}({_VALUE})"
)
_TOGETHER = re.compile(r"\b(?:hold|held|holding)\b.*\btogether\b|\btogether\b.*\bhold", re.I)
_NUMBER = re.compile(r"^\s*(?:\d+(?:\.\d+)*\.?|[A-Z]\.)\s+")


def held_flip(b: Builder, key: ActionInfo) -> tuple[str, list[str], int] | None:
    """What this hold flips: the setting's name, its two values as printed, and the unit that
    says so; None when the manual gives no such two values for it."""
    if key.skill != "hold":
        return None
    if len(key.controls) == 1:
        for i in _own_rows(b, key):
            m = _HOLD_FLIP.search(b.manual.units[i].text)
            if m:
                return _named(b, [m.group(1), m.group(2)], i), [m.group(1), m.group(2)], i
        return _held_then_shown(b, key)
    units = b.manual.units
    labels = [b.labels[c] for c in key.controls if c in b.labels]
    if len(labels) != len(key.controls):
        return None
    for i in sorted(set.intersection(*(set(lab.mentions) for lab in labels))):
        if not _TOGETHER.search(units[i].text):
            continue
        for at in (i, i + 1):
            if at >= len(units) or units[at].heading != units[i].heading:
                continue
            m = _SHOWN_FLIP.search(units[at].text)
            if m and not re.search(r"\block\b", units[at].text, re.I):
                pair = [v for v in m.groups() if v][:2]
                return _named(b, pair, i), pair, at
    return None


def _held_then_shown(b: Builder, key: ActionInfo) -> Flip | None:
    """A sentence that holds the key, then the display's two values with a two-way arrow, in it
    or the next sentence of its section ("Hold AC for 3 seconds. The frequency shown changes:
    50Hz ↔ 60Hz."): the hold flips those two (settings31). Only the two-way arrow counts ("shows
    A or B" after a hold may be the press's list); a lock's sentence flips no setting."""
    label = b.labels[key.controls[0]].text if key.controls[0] in b.labels else ""
    if not label:
        return None
    held = re.compile(rf"\bhold(?:\s+down)?\s+(?:the\s+)?{re.escape(label)}(?!\w)", re.I)
    units = b.manual.units
    for i in b.labels[key.controls[0]].mentions:
        m = held.search(units[i].text)
        if m is None or units[i].cells:
            continue
        for at in (i, i + 1):
            if at >= len(units) or units[at].heading != units[i].heading or units[at].cells:
                continue
            text = units[at].text[m.end() :] if at == i else units[at].text
            flip = re.search(rf"({_VALUE}){_TWO_WAY}({_VALUE})(?=[\s;,.)]|$)", text)
            if flip and not re.search(r"\block\b", units[at].text, re.I):
                pair = [flip.group(1), flip.group(2).rstrip(".")]  # ("… 60Hz."): the end's
                return _named(b, pair, i) or _heading_less(b, pair, label, i), pair, at
    return None


def _heading_less(b: Builder, pair: list[str], label: str, at: int) -> str:
    """The section's heading less its number, its figures, the values' units and the key's
    name ("7 AC FREQUENCY 50 / 60 HZ" for AC, 50Hz ↔ 60Hz: frequency); "" for none."""
    heading = _NUMBER.sub("", b.manual.units[at].heading or "")
    printed = {w for v in pair for w in words(re.sub(r"[\d.,]+", " ", v))} | set(words(label))
    said = [
        w for w in words(re.sub(r"\([^)]*\)", " ", heading))
        if not re.search(r"\d", w) and w not in printed and w not in ("and", "the", "of")
    ]  # fmt: skip
    return "_".join(said) if 1 <= len(said) <= 3 else ""


def _named(b: Builder, pair: list[str], at: int) -> str:
    """The setting's name: a heading that prints both values ("Speed unit (KM/H or MPH)"), else
    the heading over the unit that said it, less its number and brackets; "" for none."""
    headings = [u.heading for u in b.manual.units if u.heading]
    for heading in [
        *(h for h in headings if all(v in h for v in pair)),
        b.manual.units[at].heading,
    ]:
        name = re.sub(r"\([^)]*\)", " ", _NUMBER.sub("", heading or ""))
        said = [w for w in words(name) if w not in ("and", "the", "of")]
        if 1 <= len(said) <= 3:
            return "_".join(said)
    return ""


Flip = tuple[str, list[str], int]


def assign_flips(b: Builder, keys: list[ActionInfo], paired: set[str]) -> dict[str, Flip]:
    """Add the toggle of every hold among ``keys`` that flips two values, and of a stepping
    pair's hold that flips two outside the list it steps ("hold 2 s on the speed screen: KM/H
    <-> MPH; in the list: previous size (hold 2 s)"); returns the flips added."""
    flips = {k.name: flip for k in keys if (flip := held_flip(b, k)) is not None}
    for info in b.infos:
        if info.name in paired and (flip := held_flip(b, info)) is not None:
            flips_to(b, info, flip)
            flips[info.name] = flip
    for key in keys:
        if key.name in flips:
            flips_to(b, key, flips[key.name])
    return flips


# an amount printed with its measuring unit ("50Hz", "230 V"): the figure is the value
_AMOUNT = re.compile(r"(\d+(?:\.\d+)?)\s*(hz|khz|v|w|kw|a|ma)", re.IGNORECASE)


def flips_to(b: Builder, key: ActionInfo, flip: Flip) -> None:
    """The hold toggles a setting of the two values, named as the manual treats it. Two amounts
    in one measuring unit ("50Hz ↔ 60Hz") are the figures, shown as printed (settings31): the
    user says "sixty hertz", the display prints 60Hz."""
    amounts = [_AMOUNT.fullmatch(v) for v in flip[1]]
    values = flip[1]
    if all(amounts) and len({m.group(2).lower() for m in amounts if m}) == 1:
        values = [m.group(1) for m in amounts if m]
    var = b.add_discrete(flip[0] or var_name(b, key), values, label_of(b, key.controls[0]), None)
    b.note(f"variables.{var}.values", ", ".join(flip[1]), flip[2])
    if values != flip[1]:
        b.variables[var]["show"] = dict(zip(values, flip[1], strict=True))
    b.feature(var, [{"actions": [key.name], "variable": var, "effect": "toggle"}])


def flipped_values(flips: dict[str, Flip], values: list[str] | None, at: int | None) -> bool:
    """Whether a press's list is a hold's flip read from the same legend line: the hold's."""
    said = [v.lower() for v in values or []]
    return at is not None and any(
        f[2] == at and [v.lower() for v in f[1]] == said for f in flips.values()
    )
