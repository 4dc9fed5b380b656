"""Fitting a display row's cell grid: a 5×7 dot matrix or seven-segment cells, placed where
the row's (lit or faintly drawn) elements are, and every element sampled.

Kept apart from :mod:`apbot.vision.decode` (finding rows, choosing the grid) and
:mod:`apbot.vision.cell_texts` (turning samples into characters) because this is geometry
fitting: a search over cell counts, pitches and offsets scored on the image.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from apbot.vision.cv import cv2
from apbot.vision.display_art import EXTRA_DOTS, SEGMENT_LINES
from apbot.vision.glyphs import SEGMENT_NAMES

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


Geometry = dict[tuple[int, int], tuple[str, tuple[float, ...]]]


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


def _seg_samples(detail: np.ndarray, columns: int, width: float, height: float, x0: float,
                 y0: float, points: np.ndarray) -> np.ndarray:  # fmt: skip
    k = np.arange(columns, dtype=np.float32)[:, None]
    xs = x0 + k * 1.3 * width + points[None, :, 0] * width
    ys = y0 + points[None, :, 1] * height + 0 * k
    return _sample(detail, xs, ys).reshape(columns, len(points))
