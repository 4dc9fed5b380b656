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
from typing import TYPE_CHECKING

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
        "demonstration",
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
        "energy",
        "saving",
        "contents",
        "package",
        "eu",
        "ce",
        "ukca",
        "fcc",
        "notice",
        "notices",
        "software",
        "source",
        "open",
        "mode",
        "shop",
        "shops",
        "only",
        "this",
        "manual",
        "read",
        "before",
        "brief",
    ]
)


def boilerplate_heading(heading: str) -> bool:
    """A heading whose words are all boilerplate words, one of them a core word ("IMPORTANT
    SAFEGUARDS", "11 Disposal and guarantee")."""
    words = re.findall(r"[a-z][a-z'-]*", heading.lower().replace("&", " and "))
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
    the room's, not a setting's."""
    return bool(_SURROUNDINGS_RE.search(text))


# "Model XY-300 only:", "ZR-2000W and ZR-2100 only —": a lead naming models by number
_OTHER_MODEL_RE = re.compile(
    r"^(?:(?:the\s+)?models?\s+)?(?=[^:.]{0,40}?\d)[^:.]{1,40}?\bonly\s*[:—–]", re.IGNORECASE
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
