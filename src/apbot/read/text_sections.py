"""Text that is not about this appliance's settings: sections every manual of a range carries
(safety instructions, guarantee, disposal, conformity, customer service, packaging, intended
use), sentences about the room it stands in, and paragraphs for a sister model.

Real manuals are up to ten times longer than their operating chapters. The boilerplate around
them names keys ("never press and hold POWER while moving it"), temperatures ("5 °C to 35 °C
ambient"), modes ("demonstration mode") and other models; read as evidence it steals values
and ranges from the settings. A section is dropped only when its heading is made of such
words alone: "Safety first", "2. Important safety instructions", "Warranty and service",
"Explanation of the warning symbols" go; "Child safety lock", "Specifications and guarantee",
"Before you call for service" stay.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import TYPE_CHECKING

from apbot.read.text_pages import _plain_heading

if TYPE_CHECKING:  # (text.py imports this module)
    from apbot.read.text import Unit

_CORE = frozenset(
    [
        "safety",
        "safeguards",
        "safeguard",
        "warning",
        "warnings",
        "caution",
        "cautions",
        "precautions",
        "warranty",
        "guarantee",
        "disposal",
        "recycling",
        "environment",
        "environmental",
        "conformity",
        "declaration",
        "compliance",
        "customer",
        "packaging",
        "licence",
        "license",
        "licences",
        "licenses",
        "open-source",
        "trademarks",
        "intended",
        "about",
        "conventions",
    ]
)
_FILLER = frozenset(
    [
        "important",
        "general",
        "notes",
        "note",
        "instructions",
        "information",
        "first",
        "your",
        "for",
        "the",
        "a",
        "of",
        "and",
        "on",
        "to",
        "in",
        "use",
        "using",
        "limited",
        "service",
        "services",
        "symbols",
        "symbol",
        "explanation",
        "electrical",
        "package",
        "eu",
        "ce",
        "ukca",
        "fcc",
        "notice",
        "notices",
        "this",
        "manual",
        "read",
        "before",
        "brief",
    ]
)


# the label of a warning box set inside any chapter ("WARNING", "Caution!", "Important note")
_BOX_WORDS = frozenset(
    [
        "warning",
        "caution",
        "danger",
        "important",
        "note",
        "notes",
        "notice",
        "attention",
        "tip",
        "tips",
        "hint",
        "hints",
    ]
)
# a key a sentence tells the user to work ("hold LOCK for 3 seconds", "press START/STOP")
_WORK_KEY_RE = re.compile(
    r"\b(?:press|presses|pressing|hold|holding|turn|turning|tap|touch|push|rotate|select)\b"
    r"(?:\s+(?:and|then|down|in|or|the|briefly|again|once|twice)){0,4}"
    r"\s+[\"'“]?(?!(?:OFF|ON|NOT|NEVER)\b)[A-Z][A-Z0-9+/&-]+\b"
)
_MODELS_RE = re.compile(r"\bmodels?\s+[A-Z]{1,4}-?\d{2,}", re.IGNORECASE)
_NEGATED_RE = re.compile(r"\b(?:never|not|don't|avoid)\b", re.IGNORECASE)
_KEY_RE = re.compile(r"\b[A-Z][A-Z0-9+/&-]+\b")
_RANGE_UNIT_RE = re.compile(
    r"\d+(?:[.,]\d+)?\s*(?:°\s*[CF]\s*)?(?:to|-|–|—|…|\.\.\.)\s*\d+(?:[.,]\d+)?\s*"
    r"(?:°\s*[CF]|%|min|minutes?|hours?|h|seconds?|s|rpm|W|kW|ml|l|g)\b"
)


def box_label(heading: str) -> bool:
    """A heading made of warning-box words alone ("CAUTION", "Important note"): the label of a
    box set inside whatever chapter it stands in, never a chapter of its own."""
    words = re.findall(r"[a-z][a-z'-]*", heading.lower())
    return bool(words) and all(w in _BOX_WORDS for w in words)


def works_key(text: str) -> bool:
    """A sentence telling the user to work a panel key ("hold LOCK for 3 seconds"), not one
    warning against it ("never press POWER while moving it")."""
    return bool(_WORK_KEY_RE.search(text)) and not _NEGATED_RE.search(text)


def operating(text: str) -> bool:
    """A sentence that works a panel key ("hold LOCK for 3 seconds") or gives a key a range
    with a unit ("TEMP sets 100 to 230 °C"): a setting, whatever heading it stands under."""
    if sum(c.islower() for c in text) < len(text) // 4:
        return False  # a line in capitals: a shouted warning or a heading, not an instruction
    if _MODELS_RE.search(text):
        return False  # "on models AX-400 and AX-450 press RESET": other models of the range
    if works_key(text):
        return True
    return bool(_RANGE_UNIT_RE.search(text) and _KEY_RE.search(text))


def drop_boilerplate(units: list[Unit], original: list[str]) -> list[Unit]:
    """The units without the chapters that are boilerplate. A chapter runs from its heading to
    the next heading-like line (one the parser joined into a paragraph counts too), warning
    boxes inside it belonging to it; it is dropped only when its heading names a boilerplate
    chapter and none of its sentences works a key or gives a key a range."""
    chapters: list[tuple[str, list[Unit]]] = []
    always: set[int] = set()
    previous = None
    for k, unit in enumerate(units):
        title = None
        if previous is None or unit.heading != previous.heading:
            title = unit.heading
        else:
            title = _run_in_heading(unit, units[k + 1].line if k + 1 < len(units) else 0, original)
            if title is not None and not unit.text.startswith(title):
                always.add(id(unit))  # text of the chapter before the heading runs in with it
        previous = unit
        if title is not None and not (chapters and box_label(title)):
            chapters.append((title, []))
        if not chapters:
            chapters.append(("", []))
        chapters[-1][1].append(unit)
    kept: list[Unit] = []
    for title, members in chapters:
        if boilerplate_heading(title) and not any(operating(u.text) for u in members):
            kept.extend(u for u in members if id(u) in always)
            continue
        kept.extend(members)
    return kept


def _run_in_heading(unit: Unit, next_line: int, original: list[str]) -> str | None:
    """A heading-like line the parser ran into this unit ("3 INSTALLATION" after a page
    break): the unit starts a new chapter (and is kept whole when text of the chapter before
    runs in with the heading)."""
    last = max(unit.line, min(next_line, unit.line + 8))
    for number in range(unit.line, last + 1):
        if not 0 < number <= len(original):
            break
        line = original[number - 1].strip().lstrip("#").strip()
        if line and line != unit.text and line in unit.text and _plain_heading(line):
            return line
    return None


def boilerplate_heading(heading: str) -> bool:
    """A heading whose words are all boilerplate words, one of them a core word ("IMPORTANT
    SAFEGUARDS", "11 Disposal and guarantee"); a warning box's label alone ("CAUTION") is not a
    chapter, and a chapter on first use is about operating ("Intended use and first use")."""
    words = re.findall(r"[a-z][a-z'-]*", heading.lower().replace("&", " and "))
    if box_label(heading) or re.search(r"\bfirst\s+(?:use|time|operation)", heading.lower()):
        return False
    return (
        bool(words)
        and any(w in _CORE for w in words)
        and all(w in _CORE or w in _FILLER for w in words)
    )


_SURROUNDINGS_RE = re.compile(
    r"\b(?:ambient|surroundings|frost-free)\b|\bstorage\s+(?:temperature|conditions)\b"
    r"|\b(?:store|stored|keep|kept)\s+(?:(?:the|this|your)\s+)?(?:appliance|unit|machine|device"
    r"|product)\b",
    re.IGNORECASE,
)


def surroundings(text: str) -> bool:
    """A sentence about where the appliance stands or is kept ("an ambient temperature
    between 5 °C and 35 °C", "store the appliance frost-free, 0 to 40 °C"): its ranges are
    the room's, not a setting's. A sentence working a key ("press WARM to keep the appliance
    warm for 1 to 12 hours") is about that key's setting."""
    return bool(_SURROUNDINGS_RE.search(text)) and not works_key(text)


# "Model XY-300 only:", "ZR-2000W and ZR-2100 only —": a lead naming models, by the word
# "model" or by a type number (letters and digits joined by a hyphen); not "Cottons 40 only:"
_OTHER_MODEL_RE = re.compile(
    r"^(?=[^:.]{0,40}?(?:\bmodels?\b|\b[A-Za-z]+-\d+[A-Za-z]*\b|\b\d+-[A-Za-z]+\b))"
    r"[^:.]{1,40}?\bonly\s*[:—–]",
    re.IGNORECASE,
)


def other_model(units: list[Unit], i: int) -> bool:
    """A sentence of a paragraph led by "Model XY-300 only:" (a sister model of the range):
    what it says about keys and values is not about this appliance's other keys."""
    k = i
    while k >= 0:
        unit = units[k]
        if unit.cells:
            return False
        if _OTHER_MODEL_RE.match(unit.text):
            return True
        if k == 0 or unit.bullet or units[k - 1].heading != unit.heading:
            return False
        if units[k - 1].line < unit.line - 1 or i - k >= 4:
            return False  # a blank line before it: another paragraph
        k -= 1
    return False


# "[BM-14] The BM-14 timer goes up to 15 hours.": a sentence led by a type number in square
# brackets; "BM-10 · BM-12 · BM-14": a line naming two or more types of one family
_TYPE = r"[A-Z]{2,5}-\d{2,4}[A-Z]{0,3}"
_TAG_LEAD_RE = re.compile(rf"^\[({_TYPE})\]\s")
_TYPE_RE = re.compile(rf"(?<![\w-])({_TYPE})(?![\w-])")


# a line that introduces the types as models ("Models BM-10 · BM-12", "Type PK-06 / PK-08")
_MODEL_WORD_RE = re.compile(r"\b(?:models?|types?|versions?|variants?)\b", re.I)
_COVER_LINES = 12  # a range's types stand on the cover, among a manual's first lines


def _families(lines: list[str]) -> set[str]:
    """Type numbers the manual names side by side with a sister of the same letters ("Models
    BM-10 · BM-12 · BM-14", "PK-06 / PK-06B / PK-08"): the models a manual of a range covers.
    The line must stand on the cover or call them models, types or versions — a list of codes
    further in ("Codes EH-01, EH-02 and EH-03 may appear") names faults, not models."""
    found: set[str] = set()
    said = [line for line in lines if line.strip()]
    for n, line in enumerate(said):
        types = _TYPE_RE.findall(line)
        if len(types) < 2 or (n >= _COVER_LINES and not _MODEL_WORD_RE.search(line)):
            continue
        for t in types:
            prefix = t.split("-")[0]
            if sum(1 for u in types if u != t and u.split("-")[0] == prefix):
                found.add(t)
    return found


def drop_tagged_models(
    units: list[Unit], original: list[str], keys: Sequence[str] = ()
) -> list[Unit]:
    """The units without paragraphs a manual of several models marks as one model's own
    ("[BM-10] The BM-10 has no LOAF key…", "[PK-08] OOLONG jumps to 88 °C."): the text left
    untagged is what every model of the range does, the tagged remarks a sister's extras or
    lacks, which read as evidence give keys the sister's values and ranges. The tag must be a
    type the manual names beside a sister (so an error code "[E-01]" never counts); the
    sentences after a tagged one in its paragraph go with it. Where the panel's own ``keys``
    (the action names' words) show it is one of the tagged models — a key only that model's
    paragraphs name — its paragraphs are its own and stay."""
    families = _families(original) if any(_TAG_LEAD_RE.match(u.text) for u in units) else set()
    if not families:
        return units
    marks: list[str | None] = []  # the model each unit is tagged with, None for all models
    tagged: Unit | None = None
    for unit in units:
        lead = _TAG_LEAD_RE.match(unit.text)
        if lead and lead.group(1) in families and not unit.cells:
            tagged = unit
            marks.append(lead.group(1))
            continue
        if (
            tagged is not None
            and not unit.cells
            and not unit.bullet
            and unit.heading == tagged.heading
            and not _new_paragraph(original, tagged.line, unit.line)
            and not _own_line(original, unit)
        ):
            tagged = unit
            marks.append(marks[-1])
            continue
        tagged = None
        marks.append(None)
    own = _own_model(units, marks, keys)
    return [u for u, mark in zip(units, marks, strict=True) if mark is None or mark == own]


def _own_model(units: list[Unit], marks: list[str | None], keys: Sequence[str]) -> str | None:
    """The one tagged model whose paragraphs alone name a key of the panel ("[YG-30] The YG-30
    also has a FLAVOUR key" on a panel with FLAVOUR), or None."""
    found: set[str] = set()
    for key in {k.replace("_", " ") for k in keys if len(k) >= 3}:
        pattern = re.compile(rf"(?<!\w){re.escape(key)}(?!\w)", re.I)
        named = {mark for u, mark in zip(units, marks, strict=True) if pattern.search(u.text)}
        if None not in named:
            found |= {m for m in named if m is not None}
    return found.pop() if len(found) == 1 else None


def _own_line(original: list[str], unit: Unit) -> bool:
    """A sentence starting a line of its own after a line ending a sentence: a paragraph of
    its own though no blank line parts them (as a flattened PDF prints paragraphs), not the
    rest of the tagged one."""
    if not 2 <= unit.line <= len(original):
        return False
    line = " ".join(original[unit.line - 1].split())
    before = original[unit.line - 2].rstrip()
    return line.startswith(" ".join(unit.text.split())[:12]) and before.endswith((".", "!", "?"))


def _new_paragraph(original: list[str], after: int, line: int) -> bool:
    """A blank line between two 1-based lines: the second starts another paragraph."""
    return any(not original[k - 1].strip() for k in range(after + 1, line) if k <= len(original))
