"""From sampled elements to texts: split lit from unlit, turn each cell's pattern into
candidate characters, and run a beam over the cells for the most likely texts and a
confidence.

Kept apart from the grid fitting (:mod:`apbot.vision.cell_grids`) because this is the
reading proper: it works on samples only, never on the image.
"""

from __future__ import annotations

import heapq
from typing import Any

import numpy as np

from apbot.vision.cell_grids import _SEG_NAMES, Candidates, Row
from apbot.vision.glyphs import SEGMENT_NAMES, dot_candidates, segment_distance_candidates


def _decode_cells(row: Row, floor: float) -> None:
    """Fill ``row.cells`` from its samples; nothing is lit below ``floor`` (see :func:`_lit`)."""
    values = row.values
    lit, row.lit = _lit(values.ravel(), most=0.9 if row.style == "seg" else 0.5, floor=floor)
    cells: list[Candidates] = []
    for k in range(len(values)):
        probabilities = lit(values[k])
        if row.style == "dot":
            cells.append(dot_candidates(probabilities, limit=3))
            continue
        bits: dict[str, list[float]] = {}
        for name, p in zip(_SEG_NAMES, probabilities.ravel(), strict=True):
            bits.setdefault(name, []).append(float(p))
        per = {name: float(np.mean(v)) for name, v in bits.items()}
        cells.append(_segment_cell(per))
    row.cells = cells


def _segment_cell(bits: dict[str, float]) -> Candidates:
    """Candidates of one seven-segment cell from lit probabilities of its elements."""
    colon, point = bits.get("colon", 0.0), bits.get("point", 0.0)
    segments = {n: bits.get(n, 0.0) for n in SEGMENT_NAMES}
    dark = sum(segments.values())
    if colon > 0.5 and dark < 1.0:
        return [(":", abs(1 - colon) + dark)]
    if point > 0.5 and dark < 1.0:
        return [(".", abs(1 - point) + dark)]
    return segment_distance_candidates(segments, limit=4)


LIT_CONTRAST = 60.0
"""Grey levels a lit element stands above the window's own background, at least. Unlit
elements are drawn faintly (up to ~55 above it in the photos measured); lit ones at 60–240.
Without this floor a blank row whose grid fits badly splits into "background" samples and
faint elements, and the faint ones read as lit (noise instead of the empty text)."""


# --- lit or unlit -------------------------------------------------------------------------------


def _lit(samples: np.ndarray, most: float = 0.5, floor: float = 0.0) -> tuple[Any, bool]:
    """A function giving lit probabilities for sample values, and whether anything is lit.

    Two clusters (Otsu on the samples) when the brighter one is clearly apart: lit elements
    are several times brighter than unlit ones and at least ``floor`` above the background.
    Otherwise nothing is lit (a blank row).
    """
    values = np.sort(samples.astype(np.float64))
    n = len(values)
    best_t, best_var = None, -1.0
    cumulative = np.cumsum(values)
    total = cumulative[-1]
    for i in range(1, n):
        w0, w1 = i / n, (n - i) / n
        m0 = cumulative[i - 1] / i
        m1 = (total - cumulative[i - 1]) / (n - i)
        between = w0 * w1 * (m0 - m1) ** 2
        if between > best_var:
            best_var, best_t = between, (values[i - 1] + values[i]) / 2
    if best_t is None:
        return (lambda v: np.zeros_like(v, dtype=np.float32)), False
    low = values[values <= best_t]
    high = values[values > best_t]
    unlit = float(np.median(low)) if len(low) else 0.0
    bright = float(np.median(high)) if len(high) else 0.0
    separated = bright - unlit > 30 and bright > 1.9 * max(unlit, 1.0) and bright > floor
    if not separated or len(high) > most * n:
        # nothing lit, or "lit" everywhere: a blank row under uneven light, not a text
        return (lambda v: np.zeros_like(v, dtype=np.float32)), False
    midpoint = (unlit + bright) / 2
    softness = max(1.0, (bright - unlit) / 8)

    def probability(v: np.ndarray) -> np.ndarray:
        return np.asarray(1.0 / (1.0 + np.exp(-(v - midpoint) / softness)), dtype=np.float32)

    return probability, True


# --- texts --------------------------------------------------------------------------------------


def _alternatives(rows: list[Row], beam: int) -> list[tuple[str, float]]:
    """The ``beam`` most likely texts (main row, then the status row, two spaces apart)."""
    per_row = []
    for row in rows:
        states: list[tuple[float, str]] = [(0.0, "")]
        shape = row.style == "seg"
        for cell in row.cells:
            best = cell[0][1]
            near = [(c, d) for c, d in cell if d - best <= 1.5][:3]
            grown = [
                (cost + d - best + (_switch(text, c) if shape else 0.0), text + c)
                for cost, text in states
                for c, d in near
            ]
            states = heapq.nsmallest(beam, grown)
        per_row.append([(cost, text.strip()) for cost, text in states])
    combined: list[tuple[float, str]] = [(0.0, "")]
    for row_texts in per_row:
        grown = [
            (cost + c2, "  ".join(p for p in (text, t2) if p))
            for cost, text in combined
            for c2, t2 in row_texts
        ]
        combined = heapq.nsmallest(beam, grown)
    seen: dict[str, float] = {}
    for cost, text in combined:
        seen.setdefault(text, cost)
    return sorted(((t, c) for t, c in seen.items()), key=lambda item: item[1])


WORD_SWITCH = 0.05
"""Cost of a letter next to a digit in one word on seven segments, where ``0``/``O``/``D``,
``1``/``I``, ``5``/``S`` light the same segments: words are letters and numbers digits, so
``DELAY`` and ``0:00`` come before ``0ELAY`` and ``O:OO`` (a label like ``P1`` still reads:
the display rules pick among the alternatives)."""


def _switch(text: str, char: str) -> float:
    """The word-shape cost of appending ``char`` to ``text``."""
    last = text[-1] if text else ""
    if not last.isalnum() or not char.isalnum():
        return 0.0
    if last.isdigit() != char.isdigit():
        return WORD_SWITCH
    if last.isalpha() and char.isalpha() and last.isupper() != char.isupper():
        return WORD_SWITCH / 2  # one case in a word (``b``, ``n``, ``r`` have only one form)
    return 0.0


def _confidence(rows: list[Row]) -> float:
    """How sure the reading is: the smallest margin between a cell's best and next candidate."""
    margins = []
    for row in rows:
        for cell in row.cells:
            if len(cell) > 1:
                margins.append(cell[1][1] - cell[0][1])
    if not margins:
        return 1.0
    return float(min(1.0, min(margins) / 2.0))
