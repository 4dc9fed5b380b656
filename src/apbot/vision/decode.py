"""Decoding a straightened display window: find its rows of cells, read every segment or dot.

Every element of a display (segment, dot) is drawn whether lit or not — faintly when unlit —
so the cell grid can be fitted to the image even when little is lit. For each row of cells
the decoder fits both a 5×7 dot grid and a seven-segment grid and keeps the one that explains
the image better, samples every element, splits lit from unlit (two clusters, or none lit
when they are not apart), and turns each cell's pattern into candidate characters. A beam
over the cells gives the most likely texts, so look-alikes (``5``/``S``) stay alternatives
for the belief's display rules to settle.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from apbot.vision.cell_grids import Candidates as Candidates
from apbot.vision.cell_grids import Geometry as Geometry
from apbot.vision.cell_grids import Row as Row
from apbot.vision.cell_grids import _fit_dots, _fit_segments
from apbot.vision.cell_texts import LIT_CONTRAST as LIT_CONTRAST
from apbot.vision.cell_texts import WORD_SWITCH as WORD_SWITCH
from apbot.vision.cell_texts import _alternatives, _confidence, _decode_cells
from apbot.vision.cell_texts import _switch as _switch
from apbot.vision.cv import cv2


@dataclass
class Decoded:
    """What a display window shows: the best text, ranked alternatives, and a confidence."""

    text: str
    alternatives: list[tuple[str, float]] = field(default_factory=list)
    confidence: float = 0.0
    rows: list[Row] = field(default_factory=list)
    problem: str = ""


def decode_window(window: np.ndarray, beam: int = 48, known: Geometry | None = None) -> Decoded:
    """Read a straightened display window (grey levels, upright). ``known`` keeps the cell
    grid fitted for each row band, so later photos of the same display skip the fitting."""
    if window.size == 0 or min(window.shape[:2]) < 12:
        return Decoded("", problem="the display window is too small to read")
    g = window.astype(np.float32)
    h = g.shape[0]
    size = max(5, int(h * 0.14)) | 1
    background = cv2.morphologyEx(g, cv2.MORPH_OPEN, np.ones((size, size), np.uint8))
    detail = cv2.GaussianBlur(g - background, (0, 0), 0.6)
    bands = _bands(detail)
    if not bands:
        return Decoded("", confidence=0.5, problem="no cells found on the display")
    rows = [
        row for top, bottom in bands if (row := _read_band(detail, top, bottom, known)) is not None
    ]
    rows = [r for r in rows if r.fit > 0.15]
    if not rows:
        return Decoded("", confidence=0.5, problem="no cells found on the display")
    for row in rows:
        _decode_cells(row, LIT_CONTRAST)
    ordered = sorted(rows, key=lambda r: r.top)  # the main row on top, status rows below
    alternatives = _alternatives(ordered, beam)
    text = alternatives[0][0] if alternatives else ""
    confidence = _confidence(ordered)
    return Decoded(text, alternatives, confidence, ordered)


# --- rows ---------------------------------------------------------------------------------------


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(start, end) of each run of True in a 1-D mask (end exclusive)."""
    padded = np.concatenate([[False], mask, [False]])
    edges = np.flatnonzero(padded[1:] != padded[:-1])
    return [(int(a), int(b)) for a, b in zip(edges[::2], edges[1::2], strict=True)]


def _bands(detail: np.ndarray) -> list[tuple[int, int]]:
    """Horizontal bands that hold a row of cells (top, bottom)."""
    h, w = detail.shape
    margin = int(0.03 * w)
    kernel = max(3, h // 8)
    local = cv2.blur(detail[:, margin : w - margin], (kernel, 1))
    profile = local.max(axis=1)
    edge = max(1, int(0.02 * h))
    profile[:edge] = 0
    profile[-edge:] = 0
    floor = float(np.percentile(profile, 10))
    peak = float(np.percentile(profile, 98))
    if peak - floor < 1.5:
        return []
    runs = _runs(profile > floor + max(1.5, 0.06 * (peak - floor)))
    if not runs:
        return []
    merged = [list(runs[0])]
    for start, end in runs[1:]:
        height = max(merged[-1][1] - merged[-1][0], end - start)
        if start - merged[-1][1] <= max(2, 0.08 * height):
            merged[-1][1] = end
        else:
            merged.append([start, end])
    tallest = max(b - a for a, b in merged)
    return [(a, b) for a, b in merged if b - a >= max(5, 0.2 * tallest)]


DOT_PREFERENCE = 0.1
"""How much better a segment grid must fit a row than a dot grid to win. A segment grid
also fits a row of small dot-matrix cells roughly (its strokes lie along each blurred 5×7
block, its holes inside it), while a dot grid fits segment strokes badly: segment rows win
by 0.3 or more, small dot rows (status lamps under a segment row) lose to segments by a
few hundredths."""


def _read_band(detail: np.ndarray, top: int, bottom: int, known: Geometry | None = None
               ) -> Row | None:  # fmt: skip
    key = (round(top / 4), round(bottom / 4))
    band = detail[max(0, top - 2) : bottom + 2]
    profile = band.mean(axis=0)
    edge = max(2, int(0.015 * len(profile)))
    profile[:edge] = 0
    profile[-edge:] = 0
    floor = float(np.percentile(profile, 10))
    peak = float(np.percentile(profile, 98))
    cols = np.flatnonzero(profile > floor + 0.15 * (peak - floor))
    if len(cols) < 3:
        return None
    left, right = float(cols[0]), float(cols[-1] + 1)
    if known is not None and key in known:
        style, fixed = known[key]
        fit = _fit_dots if style == "dot" else _fit_segments
        again = fit(detail, top, bottom, 0.0, 1.0, fixed)
        if (
            again is not None
            and again.fit >= 0.85 * fixed[0]
            and _covers(style, fixed, left, right)
        ):
            return again  # the grid still fits this photo and spans the row
        del known[key]
    options = [_fit_dots(detail, top, bottom, left, right), _fit_segments(detail, top, bottom,
                                                                          left, right)]  # fmt: skip
    fitted = [o for o in options if o is not None]
    if not fitted:
        return None
    best = max(fitted, key=lambda r: r.fit + (DOT_PREFERENCE if r.style == "dot" else 0.0))
    if known is not None:
        known[key] = (best.style, best.geometry)
    return best


def _covers(style: str, fixed: tuple[float, ...], left: float, right: float) -> bool:
    """Whether a kept grid spans the row's cells now seen from ``left`` to ``right`` (a
    display that centres its text draws more cells for a longer one)."""
    if style == "dot":
        columns, pitch, x0 = fixed[1], fixed[2], fixed[3]
        start, end, cell = x0, x0 + (6 * columns - 2) * pitch, 6 * pitch
    else:
        columns, width, x0 = fixed[1], fixed[2], fixed[4]
        start, end, cell = x0, x0 + (1.3 * columns - 0.3) * width, 1.3 * width
    return left > start - 0.5 * cell and right < end + 0.5 * cell
