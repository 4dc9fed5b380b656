"""A line of named bands ("Largo 40–60 · Adagio 66–76 · Andante 76–108"): a reference chart
that names parts of a scale (tempo markings, wind forces, sizes), not the setting's range.

Reading its first span as the range cut a metronome's 30–280 BPM to 40–60; passed by, the
setting's range comes from the sentence that states it ("The range is 30 BPM to 280 BPM").
"""

from __future__ import annotations

import itertools
import re

# a name, then a span of two figures: "Adagio 66–76", "Force 4 5–8 m/s" is not one (a number
# after the name)
_BAND_RE = re.compile(
    r"(?<![\w.])[A-Z][a-z]{2,}(?:\s+[A-Z][a-z]+)?\s+\d+(?:[.,]\d+)?\s*[–—-]\s*\d+(?:[.,]\d+)?"
)
# what stands between two bands: a middle dot, a bullet, a comma, a semicolon or a slash
_BETWEEN_RE = re.compile(r"\s*[^\w\s]?\s*[·•,;/|]\s*|\s{2,}")
_FIGURES_RE = re.compile(r"\d+(?:[.,]\d+)?")


def named_bands(text: str) -> bool:
    """Whether the line is two or more named spans one after the other, and nothing else of
    note (a separator between each, a trailing separator allowed), that overlap or leave gaps
    (bands of a scale named for what they suit, not the scale cut into its own levels)."""
    found = list(_BAND_RE.finditer(text))
    if len(found) < 2:
        return False
    for a, b in itertools.pairwise(found):
        if not _BETWEEN_RE.fullmatch(text[a.end() : b.start()]):
            return False
    rest = text[: found[0].start()] + text[found[-1].end() :]
    if re.search(r"\w", rest):
        return False
    spans = [[float(x.replace(",", ".")) for x in _FIGURES_RE.findall(m[0])[-2:]] for m in found]
    # "Low 1–3, High 4–6": one scale cut in pieces, end to end, is the setting's own
    return any(b[0] not in (a[1], a[1] + 1) for a, b in itertools.pairwise(spans))


# a display name ending in a count written as one word: "VOICE 1-2-3-4" (a voice counting the
# beats), "COUNT 1-2-3": a name, no span of values
_COUNTED_NAME_RE = re.compile(r"\b[A-Z]{2,}\s+\d(?:-\d){2,}(?![\d.,–-])")


def counted_name(text: str) -> bool:
    """Whether the line prints a display name that ends in a count ("VOICE 1-2-3-4")."""
    return bool(_COUNTED_NAME_RE.search(text))
