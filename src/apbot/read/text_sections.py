"""Sections every manual of a range carries and no setting lives in: safety instructions,
guarantee, disposal, conformity, customer service, packaging, intended use.

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
