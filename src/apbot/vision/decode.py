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

import heapq
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from apbot.vision.cv import cv2
from apbot.vision.display_art import EXTRA_DOTS, SEGMENT_LINES
from apbot.vision.glyphs import SEGMENT_NAMES, dot_candidates, segment_distance_candidates

Candidates = list[tuple[str, float]]


@dataclass
class Row:
    """One decoded row: its style, the candidates per cell (best first), and how sure."""

    style: str
    cells: list[Candidates]
    top: float
    bottom: float
    fit: float
    lit: bool = True
    geometry: tuple[float, ...] = ()
    values: Any = None  # the sampled elements: (cells, 7, 5) dots or (cells, points) segments

    @property
    def text(self) -> str:
        return "".join(c[0][0] for c in self.cells).strip()


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


Geometry = dict[tuple[int, int], tuple[str, tuple[float, ...]]]

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


# --- dot matrix ---------------------------------------------------------------------------------


def _sample(detail: np.ndarray, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """Bilinear samples of ``detail`` at the points (xs, ys)."""
    return cv2.remap(detail, xs.astype(np.float32), ys.astype(np.float32), cv2.INTER_LINEAR,
                     borderMode=cv2.BORDER_REPLICATE)  # fmt: skip


def _dot_grid(columns: int, pitch: float, x0: float, y0: float) -> tuple[np.ndarray, np.ndarray]:
    k = np.arange(columns)[:, None, None]
    row = np.arange(7)[None, :, None]
    col = np.arange(5)[None, None, :]
    xs = x0 + (6 * k + col) * pitch + 0 * row
    ys = y0 + row * pitch + 0 * col + 0 * k
    return xs.astype(np.float32), ys.astype(np.float32)


def _dot_score(detail: np.ndarray, profile: np.ndarray, columns: int, pitch: float, x0: float,
               y0: float) -> float:  # fmt: skip
    """How well a dot grid fits: dot centres bright against the gaps between them, times the
    share of the row's structure that the grid covers (a grid missing a cell fits worse)."""
    xs, ys = _dot_grid(columns, pitch, x0, y0)
    on = _sample(detail, xs.reshape(1, -1), ys.reshape(1, -1)).mean()
    off = _sample(detail, (xs + pitch / 2).reshape(1, -1), (ys + pitch / 2).reshape(1, -1)).mean()
    contrast = float((on - off) / (abs(on) + abs(off) + 1e-6))
    a = max(0, int(x0 - 0.6 * pitch))
    b = min(len(profile), int(x0 + (6 * columns - 2) * pitch + 0.6 * pitch) + 1)
    total = float(profile.sum()) + 1e-6
    return contrast * float(profile[a:b].sum()) / total


def _fit_dots(detail: np.ndarray, top: int, bottom: int, left: float, right: float,
              fixed: tuple[float, ...] | None = None) -> Row | None:  # fmt: skip
    pitch0 = (bottom - top) / 7.0
    if pitch0 < 1.5:
        return None
    band = detail[max(0, top - 2) : bottom + 2]
    profile = np.clip(band.mean(axis=0), 0, None)
    best: tuple[float, int, float, float, float] | None = None
    if fixed is not None:
        columns, pitch, x0, y0 = int(fixed[1]), fixed[2], fixed[3], fixed[4]
        best = (_dot_score(detail, profile, columns, pitch, x0, y0), columns, pitch, x0, y0)
    else:
        guess = max(1, round(((right - left) / pitch0 + 1.2) / 6))
        for columns in range(max(1, guess - 3), guess + 4):
            for scale in (0.98, 1.0, 1.02):
                pitch = (right - left) / max(1.0, 6 * columns - 1.2) * scale
                if not 0.65 < pitch / pitch0 < 1.4:
                    continue
                for dx in np.linspace(-1.2, 1.2, 13):
                    for dy in np.linspace(-0.4, 0.4, 5):
                        x0 = left + (0.4 + dx) * pitch
                        y0 = (top + bottom) / 2 - 3 * pitch + dy * pitch
                        score = _dot_score(detail, profile, columns, pitch, x0, y0)
                        if best is None or score > best[0]:
                            best = (score, columns, pitch, x0, y0)
        if best is not None:  # refine pitch and offsets finely around the best
            _, columns, pitch_c, x_c, y_c = best
            for scale in np.linspace(0.985, 1.015, 7):
                for dx in np.linspace(-0.2, 0.2, 5):
                    for dy in np.linspace(-0.15, 0.15, 3):
                        pitch = pitch_c * scale
                        x0, y0 = x_c + dx * pitch, y_c + dy * pitch
                        score = _dot_score(detail, profile, columns, pitch, x0, y0)
                        if score > best[0]:
                            best = (score, columns, pitch, x0, y0)
    if best is None:
        return None
    score, columns, pitch_x, x0, y0 = best
    xs, ys = _dot_grid(columns, pitch_x, x0, y0)
    values = _sample(detail, xs.reshape(1, -1), ys.reshape(1, -1)).reshape(columns, 7, 5)
    return Row("dot", [], float(top), float(bottom), score, True,
               (score, columns, pitch_x, x0, y0), values)  # fmt: skip


# --- seven segments -----------------------------------------------------------------------------


def _segment_points() -> tuple[list[str], np.ndarray]:
    """Element names and their sample points in cell units (three per segment)."""
    names, points = [], []
    for name in SEGMENT_NAMES:
        ax, ay, bx, by = SEGMENT_LINES[name]
        for t in (0.3, 0.5, 0.7):
            names.append(name)
            points.append((ax + (bx - ax) * t, ay + (by - ay) * t))
    for name, dots in EXTRA_DOTS.items():
        for point in dots:
            names.append(name)
            points.append(point)
    return names, np.array(points, dtype=np.float32)


_SEG_NAMES, _SEG_POINTS = _segment_points()
# points inside a cell where nothing is ever drawn (the two chambers of an 8, off the colon)
_SEG_HOLES = np.array(
    [(x, y) for x in (0.3, 0.38, 0.62, 0.7) for y in (0.22, 0.36, 0.64, 0.78)], np.float32
)


def _fit_segments(detail: np.ndarray, top: int, bottom: int, left: float, right: float,
                  fixed: tuple[float, ...] | None = None) -> Row | None:  # fmt: skip
    height0 = (bottom - top) / 1.0
    width0 = height0 / 1.7
    if width0 < 4:
        return None
    guess = max(1, round(((right - left) / width0 + 0.3) / 1.3))
    best: tuple[float, int, float, float, float, float] | None = None
    if fixed is not None:
        columns, width, height, x0, y0 = int(fixed[1]), fixed[2], fixed[3], fixed[4], fixed[5]
        on = _seg_samples(detail, columns, width, height, x0, y0, _SEG_POINTS).mean()
        off = _seg_samples(detail, columns, width, height, x0, y0, _SEG_HOLES).mean()
        score = float((on - off) / (abs(on) + abs(off) + 1e-6))
        best = (score, columns, width, height, x0, y0)
        guess = -10
    for columns in range(max(1, guess - 1), guess + 2):
        for scale in (0.94, 0.97, 1.0, 1.03):
            width = (right - left) / max(0.5, columns * 1.3 - 0.3) * scale
            height = width * 1.7
            if not 0.6 < height / (bottom - top) < 1.4:
                continue
            for dx in np.linspace(-0.12, 0.12, 5):
                for dy in np.linspace(-0.08, 0.08, 5):
                    x0 = left - 0.05 * width + dx * width
                    y0 = top + ((bottom - top) - height) / 2 + dy * height
                    on = _seg_samples(detail, columns, width, height, x0, y0, _SEG_POINTS).mean()
                    off = _seg_samples(detail, columns, width, height, x0, y0, _SEG_HOLES).mean()
                    score = float((on - off) / (abs(on) + abs(off) + 1e-6))
                    if best is None or score > best[0]:
                        best = (score, columns, width, height, x0, y0)
    if best is None:
        return None
    score, columns, width, height, x0, y0 = best
    values = _seg_samples(detail, columns, width, height, x0, y0, _SEG_POINTS)
    return Row("seg", [], float(top), float(bottom), score, True,
               (score, columns, width, height, x0, y0), values)  # fmt: skip


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


def _seg_samples(detail: np.ndarray, columns: int, width: float, height: float, x0: float,
                 y0: float, points: np.ndarray) -> np.ndarray:  # fmt: skip
    k = np.arange(columns, dtype=np.float32)[:, None]
    xs = x0 + k * 1.3 * width + points[None, :, 0] * width
    ys = y0 + points[None, :, 1] * height + 0 * k
    return _sample(detail, xs, ys).reshape(columns, len(points))


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
