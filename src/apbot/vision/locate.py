"""Finding the display window in a panel photo and straightening it.

A display is a dark rectangular window inside a lighter bezel. In the photo it is a large
dark region, nearly rectangular (a quadrilateral under perspective), not touching the photo's
edge, whose surrounding ring is clearly brighter than its inside. The quadrilateral found is
warped to an upright rectangle for the decoder.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from apbot.vision.cv import cv2


@dataclass(frozen=True)
class Window:
    """The display window: its four corners in the photo (TL, TR, BR, BL) and a score."""

    corners: np.ndarray
    score: float

    @property
    def box(self) -> tuple[float, float, float, float]:
        xs, ys = self.corners[:, 0], self.corners[:, 1]
        return (float(xs.min()), float(ys.min()), float(xs.max()), float(ys.max()))


def gray(image: np.ndarray) -> np.ndarray:
    """Brightness as the display sees it: the largest channel (coloured LEDs stay bright)."""
    if image.ndim == 2:
        return image
    return np.asarray(image.max(axis=2), dtype=np.uint8)


def order_corners(points: np.ndarray) -> np.ndarray:
    """Four points as top-left, top-right, bottom-right, bottom-left."""
    pts = np.asarray(points, dtype=np.float32).reshape(4, 2)
    s, d = pts.sum(axis=1), np.diff(pts, axis=1).ravel()
    return np.array([pts[s.argmin()], pts[d.argmin()], pts[s.argmax()], pts[d.argmax()]])


def find_window(image: np.ndarray) -> Window | None:
    """The most display-like dark window in ``image`` (RGB), or None when there is none."""
    g = gray(image)
    h, w = g.shape
    best: Window | None = None
    for threshold in (60, 85, 40, 110):
        dark = (g < threshold).astype(np.uint8)
        dark = cv2.morphologyEx(dark, cv2.MORPH_CLOSE, np.ones((3, 3), np.uint8))
        contours, _ = cv2.findContours(dark, cv2.RETR_LIST, cv2.CHAIN_APPROX_SIMPLE)
        for contour in contours:
            area = cv2.contourArea(contour)
            if area < 0.002 * h * w or area > 0.6 * h * w:
                continue
            x, y, bw, bh = cv2.boundingRect(contour)
            if x <= 1 or y <= 1 or x + bw >= w - 1 or y + bh >= h - 1:
                continue
            rect = cv2.minAreaRect(contour)
            rect_area = rect[1][0] * rect[1][1]
            if rect_area <= 0 or area / rect_area < 0.92:  # a window's edges are straight
                continue
            corners = _corners(contour, rect)
            score = _score(g, corners, area)
            if score > 0 and (best is None or score > best.score):
                best = Window(corners, score)
        if best is not None:
            return best
    return best


def _corners(contour: np.ndarray, rect: tuple) -> np.ndarray:
    perimeter = cv2.arcLength(contour, True)
    approx = cv2.approxPolyDP(contour, 0.02 * perimeter, True)
    if len(approx) == 4 and cv2.isContourConvex(approx):
        return order_corners(approx.reshape(4, 2))
    return order_corners(cv2.boxPoints(rect))


def _score(g: np.ndarray, corners: np.ndarray, area: float) -> float:
    """How display-like the window is: dark inside, a bright ring around, structure inside."""
    mask = np.zeros(g.shape, np.uint8)
    cv2.fillConvexPoly(mask, corners.astype(np.int32), 1)
    ring_width = max(2, int(0.01 * np.sqrt(area)))
    kernel = np.ones((2 * ring_width + 1, 2 * ring_width + 1), np.uint8)
    ring = cv2.dilate(mask, kernel) - mask
    inner = cv2.erode(mask, np.ones((7, 7), np.uint8))
    if inner.sum() < 50 or ring.sum() < 20:
        return 0.0
    inside = g[inner > 0]
    around = g[ring > 0]
    background = float(np.percentile(inside, 30))
    contrast = float(np.percentile(around, 70)) - background
    detail = float(np.percentile(inside, 97)) - background
    if contrast < 25 or detail < 12:
        return 0.0
    return float(area) * min(1.0, contrast / 60.0)


def straighten(image: np.ndarray, window: Window, height: int = 200) -> np.ndarray:
    """The window warped to an upright rectangle ``height`` pixels tall (grey levels)."""
    tl, tr, br, bl = window.corners
    width_px = float(np.linalg.norm(tr - tl) + np.linalg.norm(br - bl)) / 2
    height_px = float(np.linalg.norm(bl - tl) + np.linalg.norm(br - tr)) / 2
    out_h = int(max(float(height), height_px))
    out_w = int(max(8, round(width_px * out_h / max(1.0, height_px))))
    target = np.array([[0, 0], [out_w - 1, 0], [out_w - 1, out_h - 1], [0, out_h - 1]],
                      dtype=np.float32)  # fmt: skip
    h, w = image.shape[:2]
    x0, y0, x1, y1 = window.box
    left, top = max(0, int(x0) - 2), max(0, int(y0) - 2)
    crop = image[top : min(h, int(y1) + 3), left : min(w, int(x1) + 3)]
    corners = window.corners.astype(np.float32) - np.array([left, top], dtype=np.float32)
    matrix = cv2.getPerspectiveTransform(corners, target)
    return cv2.warpPerspective(gray(crop), matrix, (out_w, out_h), flags=cv2.INTER_LINEAR)
