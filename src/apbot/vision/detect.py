"""Control-element candidates on a panel photo: OCR text boxes and OpenCV shape proposals.

Classical proposals come from contours (ranked by how much they look like a button: a
rectangle, a rounded rectangle or an ellipse of plausible size) and from Hough circles
(dials). Text boxes come from the OCR model. All go through one non-maximum suppression at
IoU 0.85 and are ranked by confidence. Nothing here knows the layout: it sees only pixels.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from apbot.vision.cv import cv2
from apbot.vision.ocr import TextBox, read_lines

BoxT = tuple[float, float, float, float]
NMS_IOU = 0.85
MIN_RIM = 0.45
"""A Hough circle is kept when at least this share of its rim lies on an edge."""


@dataclass(frozen=True)
class Candidate:
    """A box that may be a control: ``kind`` is ``text``, ``shape`` or ``circle``."""

    box: BoxT
    kind: str
    confidence: float
    text: str = ""

    @property
    def centre(self) -> tuple[float, float]:
        return ((self.box[0] + self.box[2]) / 2, (self.box[1] + self.box[3]) / 2)

    @property
    def area(self) -> float:
        return max(0.0, self.box[2] - self.box[0]) * max(0.0, self.box[3] - self.box[1])


@dataclass
class Detection:
    """Everything found on one photo: text lines and control candidates after NMS."""

    texts: list[TextBox]
    candidates: list[Candidate]
    size: tuple[int, int]


def iou(a: BoxT, b: BoxT) -> float:
    """Intersection over union of two boxes."""
    ix = max(0.0, min(a[2], b[2]) - max(a[0], b[0]))
    iy = max(0.0, min(a[3], b[3]) - max(a[1], b[1]))
    inter = ix * iy
    union = (a[2] - a[0]) * (a[3] - a[1]) + (b[2] - b[0]) * (b[3] - b[1]) - inter
    return inter / union if union > 0 else 0.0


def nms(candidates: list[Candidate], threshold: float = NMS_IOU) -> list[Candidate]:
    """Keep the most confident of boxes that overlap by more than ``threshold`` IoU."""
    kept: list[Candidate] = []
    for candidate in sorted(candidates, key=lambda c: -c.confidence):
        if all(iou(candidate.box, k.box) <= threshold for k in kept):
            kept.append(candidate)
    return kept


def shape_proposals(image: np.ndarray) -> list[Candidate]:
    """Button-like contours and dial-like circles, each with a shape confidence."""
    gray = cv2.cvtColor(image, cv2.COLOR_RGB2GRAY)
    h, w = gray.shape
    smooth = cv2.GaussianBlur(gray, (5, 5), 0)
    edges = cv2.Canny(smooth, 30, 90)
    edges = cv2.dilate(edges, np.ones((3, 3), np.uint8))
    contours, _ = cv2.findContours(edges, cv2.RETR_LIST, cv2.CHAIN_APPROX_SIMPLE)
    found: list[Candidate] = []
    image_area = float(h * w)
    for contour in contours:
        x, y, bw, bh = cv2.boundingRect(contour)
        area = float(bw * bh)
        if area < 0.0006 * image_area or area > 0.2 * image_area:
            continue
        if x <= 1 or y <= 1 or x + bw >= w - 1 or y + bh >= h - 1:
            continue
        aspect = max(bw, bh) / max(1, min(bw, bh))
        if aspect > 6:
            continue
        filled = cv2.contourArea(cv2.convexHull(contour)) / area
        if filled < 0.6:
            continue
        perimeter = cv2.arcLength(contour, True)
        circular = 4 * np.pi * cv2.contourArea(cv2.convexHull(contour)) / max(1.0, perimeter**2)
        confidence = 0.5 * min(1.0, filled) + 0.3 * min(1.0, circular * 1.2) + 0.2 / aspect
        found.append(Candidate((float(x), float(y), float(x + bw), float(y + bh)), "shape",
                               float(confidence)))  # fmt: skip
    scale = max(h, w) / 1000.0
    circles = cv2.HoughCircles(smooth, cv2.HOUGH_GRADIENT, dp=1.5, minDist=40 * scale,
                               param1=90, param2=80, minRadius=int(18 * scale),
                               maxRadius=int(min(h, w) * 0.35))  # fmt: skip
    if circles is not None:
        for cx, cy, r in circles[0]:
            box = (float(cx - r), float(cy - r), float(cx + r), float(cy + r))
            if min(box[0], box[1], w - box[2], h - box[3]) < -0.1 * r:
                continue  # a dial lies on the panel: a circle through the photo's edge is noise
            support = _rim_support(edges, float(cx), float(cy), float(r))
            if support < MIN_RIM:
                continue  # the accumulator's guess, not an outline that is there
            found.append(Candidate(box, "circle", 0.5 + 0.5 * support))
    return found


def _rim_support(edges: np.ndarray, cx: float, cy: float, r: float) -> float:
    """The share of a circle's rim that lies on an edge (Hough also votes for circles that
    only touch scattered edges: grids of display dots, rows of keys)."""
    angles = np.linspace(0, 2 * np.pi, 96, endpoint=False)
    xs = np.round(cx + r * np.cos(angles)).astype(int)
    ys = np.round(cy + r * np.sin(angles)).astype(int)
    ok = (xs >= 0) & (ys >= 0) & (xs < edges.shape[1]) & (ys < edges.shape[0])
    return float((edges[ys[ok], xs[ok]] > 0).sum() / len(angles))


def detect(image: np.ndarray) -> Detection:
    """Text lines and control candidates on a panel photo (RGB)."""
    if image.ndim != 3 or image.shape[2] != 3 or min(image.shape[:2]) < 16:
        return Detection(
            [], [], (int(image.shape[1]) if image.ndim > 1 else 0, int(image.shape[0]))
        )
    texts = read_lines(image)
    candidates = [Candidate(t.box, "text", 0.5 + 0.5 * t.score, t.text) for t in texts]
    candidates += shape_proposals(image)
    return Detection(texts, nms(candidates), (int(image.shape[1]), int(image.shape[0])))
