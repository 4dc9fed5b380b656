"""The fields of a walk named by the order the manual lists them in, and field values written
as a run of display codes or as codes glossed by words.

Manuals that walk several fields with one key often print the order once, as an arrow list
("USER (P) -> SEX -> AGE -> HEIGHT -> stored", "Field order: hour → minutes → portion") or as
"SET moves through: unit, month, day, hour". Those are the names the user knows the settings by
("user 2"), where the step itself only says what the display shows ("the memory number"). The
values of such fields are often printed as display codes: a run of one prefix ("P1 -> P2 -> ...
-> P8", "P1 ... P8") is a number from the first to the last; a bracket of codes each glossed
by a word ("(M = male, F = female)") is the words, shown as the codes.
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

from apbot.read.shapes import Evidence
from apbot.read.value_steps import find_step
from apbot.read.values import Range, find_ranges
from apbot.read.walk_fields import field_name

# an arrow list of at least three items: "USER (P) -> SEX -> AGE -> HEIGHT -> stored"
_ARROW_RE = re.compile(r"(?:→|->|>)")
# the list told as what the key moves through: "SET moves through: unit, month, day, hour"
_MOVES_THROUGH_RE = re.compile(
    r"\b(?:moves?|steps?|goes|walks?|cycles?)\s+(?:you\s+)?through(?:\s+the\s+\w+)?\s*:?\s*"
    r"([^.]+)",
    re.I,
)
# "Field order: hour → minutes", "Order of the items: …"
_ORDER_HEAD_RE = re.compile(r"^\s*(?:the\s+)?(?:field|item|setting|menu)?\s*order[^:]*:\s*", re.I)
# the item that ends the walk, no field: "stored", "store", "end", "exit", "done"
_END_ITEM_RE = re.compile(
    r"^(?:stored|store|saved?|end|exit|done|finish(?:ed)?|back|normal\s+display)$", re.I
)
# one field of the list: a word or two, with an optional bracket ("USER (P)")
_ITEM_RE = re.compile(r"^([A-Za-z][A-Za-z-]*(?:\s+[A-Za-z][A-Za-z-]*)?)\s*(?:\([^)]*\))?$")
# a code and its number: "P1", "P 8", "F03"
_CODE_NUM_RE = re.compile(r"(?<![\w-])([A-Za-z]{1,3})\s?(\d{1,3})(?![\w.,]?\d)")
# a run goes on between its ends: "->", "→", "...", "…", "to"
_RUN_GAP_RE = re.compile(r"\.\.\.|…|→|->")
# a bracket of glossed codes: "(M = male, F = female)", "(C: cool, W: warm)"
_GLOSS_RE = re.compile(r"(?<![\w-])([A-Za-z0-9]{1,3})\s*[=:]\s*([a-z][a-z-]{1,15})\b")


def order_names(lines: list[str]) -> list[list[str]]:
    """The field orders a section prints: each a list of field names in walking order (the
    closing "stored" left out)."""
    out: list[list[str]] = []
    for line in lines:
        body = _ORDER_HEAD_RE.sub("", line.strip())
        through = _MOVES_THROUGH_RE.search(body)
        if len(_ARROW_RE.findall(body)) >= 2:
            parts = _ARROW_RE.split(body)
        elif through and through.group(1).count(",") >= 2:
            parts = re.split(r",|\band\b|\bthen\b", through.group(1))
        else:
            continue
        names = [p.strip() for p in parts if p.strip()]
        while names and _END_ITEM_RE.match(names[-1]):
            names.pop()
        items = [_ITEM_RE.match(n) for n in names]
        if len(items) >= 2 and all(items):
            named = ["_".join(m.group(1).lower().split()) for m in items if m]
            if len(set(named)) == len(named):
                out.append(named)
    return out


def code_run_field(shown: str, text: str, at: int) -> dict[str, Any] | None:
    """A field whose values are printed as a run of one display code with numbers ("▲ goes P1
    -> P2 -> ... -> P8", "P1 ... P8"): the numbers from the first to the last."""
    codes = _CODE_NUM_RE.findall(text)
    if not codes or not _RUN_GAP_RE.search(text):
        return None
    prefixes = {p.upper() for p, _ in codes}
    if len(prefixes) != 1:
        return None
    nums = sorted({int(n) for _, n in codes})
    if len(nums) < 2 or nums[-1] - nums[0] < 2:
        return None
    ev = Evidence(ranges=[Range(float(nums[0]), float(nums[-1]), "")], range_at=at)
    return {"name": "setting", "evidence": ev, "label": codes[0][0].upper()}


def glossed_field(text: str) -> dict[str, Any] | None:
    """A field whose codes a bracket glosses with a word each ("(M = male, F = female)"): the
    words are the values the user says, the codes what the display shows."""
    for m in re.finditer(r"\(([^()]*)\)", text):
        pairs = _GLOSS_RE.findall(m.group(1))
        if len(pairs) >= 2 and len(pairs) == len(re.split(r"[,;/]|\bor\b", m.group(1))):
            words = [w for _, w in pairs]
            if len(set(words)) == len(words):
                return {"name": "setting", "values": words, "show": {w: c for c, w in pairs}}
    return None


def first_case_field(text: str, at: int) -> dict[str, Any] | None:
    """A field whose range depends on another setting, told case by case in different units
    ("Range 100-220 cm with kg, 40-87 in with lb or st"): the first case's range, the one the
    factory setting uses; the walk is read instead of stopping here."""
    ranges = find_ranges(text)
    if len(ranges) < 2 or not ranges[0].unit or ranges[1].unit == ranges[0].unit:
        return None
    if not re.search(r"\bwith\b|\bwhen\b|\bin\s+\w+\s+mode\b", text, re.I):
        return None
    return {"name": "setting", "evidence": Evidence(ranges=[ranges[0]], range_at=at)}


def read_coded_field(shown: str, text: str, at: int) -> dict[str, Any] | None:
    """A walk's field that the value readers of ``walk_fields`` leave: a run of display codes,
    glossed codes, or a range told case by case; named by what the display shows."""
    field = code_run_field(shown, text, at) or glossed_field(text) or first_case_field(text, at)
    if field is None:
        return None
    field["name"] = field_name(shown, beside=True) or "setting"
    codes = "|".join(re.escape(c) for c in field.get("show", {}).values())
    shown_as = (
        re.search(rf"\bshows\s+([A-Z][A-Z0-9]{{1,5}})\s+(?:{codes})\b", shown) if codes else None
    )
    if shown_as:  # "The display shows SEX M": the field's word beside its code
        field["label"] = shown_as.group(1)
    return field


# a press's step written as a signed amount beside the key: "▲ (+1 year)", "▼ (-5 min)"
_SIGNED_STEP_RE = re.compile(r"\(\s*[+]\s*(\d+(?:\.\d+)?)\s*([^\d\s)][^)]*)?\)")


def with_step(field: dict[str, Any], text: str, at: int) -> dict[str, Any]:
    """A walk's amount whose step its text gives beside a hold of the pair ("1 cm per touch;
    hold 2 seconds for 10 at a time") or signed beside the key ("▲ (+1 year)"): the press's
    step, read from the clauses that do not speak of holding."""
    ev = field.get("evidence")
    if not isinstance(ev, Evidence) or ev.step is not None or not ev.ranges:
        return field
    step = None
    for clause in re.split(r"[;()]|\.\s", text):
        if not re.search(r"\bhold", clause, re.I):  # "1 cm or 1 inch per touch": the first
            step = step or find_step(re.sub(r"\s+or\s+\d+\s*[a-z]+(?=\s+per\b)", "", clause))
    signed = _SIGNED_STEP_RE.search(text)
    if step is None and signed:
        step = (float(signed.group(1)), ev.ranges[0].unit)
    if step is None:
        return field
    return {**field, "evidence": replace(ev, step=step, step_at=at)}
