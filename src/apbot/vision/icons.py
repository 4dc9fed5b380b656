"""Recognising the common appliance symbols printed without words (⏻, +, −, ▲, 🔒 …).

Each symbol of a small standard set (IEC-style power, arrows, plus/minus, lock, bulb, timer,
cup…) is drawn once as a template; a glyph cut from the photo is binarised, cropped to its
ink, scaled to the template size and compared by intersection over union. The templates are
drawn with the same routines as the renderer, so on our rendered panels this is
near-perfect; on real panels it is a weak baseline, which is what the optional vision-LLM
verifier is for.
"""

from __future__ import annotations

from functools import cache

import numpy as np
from PIL import Image, ImageDraw

from apbot.vision.cv import cv2
from apbot.vision.panel_art import draw_text

SYMBOLS = "⏻−+▲▼◀▶◄►▷◁✕🔒🔓🔑💡⏱⏲⌚☀½☕❄↕↔"
SIZE = 32


def _normalise(ink: np.ndarray) -> np.ndarray | None:
    """Ink (boolean) cropped to its bounding box and scaled into a SIZE square (aspect kept)."""
    ys, xs = np.nonzero(ink)
    if len(xs) < 6:
        return None
    crop = ink[ys.min() : ys.max() + 1, xs.min() : xs.max() + 1].astype(np.uint8) * 255
    h, w = crop.shape
    scale = (SIZE - 4) / max(h, w)
    resized = cv2.resize(crop, (max(1, round(w * scale)), max(1, round(h * scale))),
                         interpolation=cv2.INTER_AREA)  # fmt: skip
    canvas = np.zeros((SIZE, SIZE), np.uint8)
    rh, rw = resized.shape
    y0, x0 = (SIZE - rh) // 2, (SIZE - rw) // 2
    canvas[y0 : y0 + rh, x0 : x0 + rw] = resized
    return canvas > 100


@cache
def templates() -> dict[str, np.ndarray]:
    """Every symbol drawn once, normalised."""
    table = {}
    for symbol in SYMBOLS:
        image = Image.new("RGB", (96, 96), (0, 0, 0))
        draw_text(ImageDraw.Draw(image), (48, 48), symbol, 60, (255, 255, 255))
        normal = _normalise(np.asarray(image).max(axis=2) > 100)
        if normal is not None:
            table[symbol] = normal
    return table


def ink_of(crop: np.ndarray) -> np.ndarray:
    """The printed glyph pixels of a crop (RGB or grey): far from the crop's background."""
    gray = crop if crop.ndim == 2 else cv2.cvtColor(crop, cv2.COLOR_RGB2GRAY)
    background = float(np.median(gray))
    spread = np.abs(gray.astype(np.float32) - background)
    threshold = max(40.0, float(np.percentile(spread, 99)) * 0.5)
    return spread > threshold


def classify(crop: np.ndarray, minimum: float = 0.55, among: str = SYMBOLS) -> tuple[str, float]:
    """The symbol a crop shows and the match (IoU), or ("", best) when none fits well;
    ``among`` limits the symbols considered."""
    return classify_ink(ink_of(crop), minimum, among)


def classify_ink(ink: np.ndarray, minimum: float = 0.55, among: str = SYMBOLS) -> tuple[str, float]:
    """:func:`classify` on a glyph mask already cut from its background."""
    ranked = rank_ink(ink, among)
    if not ranked:
        return "", 0.0
    best, best_score = ranked[0]
    return (best, best_score) if best_score >= minimum else ("", best_score)


def rank_ink(ink: np.ndarray, among: str = SYMBOLS) -> list[tuple[str, float]]:
    """Every symbol of ``among`` with its match (IoU) to a glyph mask, best first."""
    normal = _normalise(ink)
    if normal is None:
        return []
    dilated = cv2.dilate(normal.astype(np.uint8), np.ones((3, 3), np.uint8)) > 0
    scored = []
    for symbol in templates():
        if symbol not in among:
            continue
        inter = (dilated & _dilated(symbol)).sum()
        union = (dilated | _dilated(symbol)).sum()
        scored.append((symbol, float(inter / union) if union else 0.0))
    return sorted(scored, key=lambda item: -item[1])


@cache
def _dilated(symbol: str) -> np.ndarray:
    return cv2.dilate(templates()[symbol].astype(np.uint8), np.ones((3, 3), np.uint8)) > 0
