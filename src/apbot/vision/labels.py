"""Labels on a panel photo: printed text grouped per control, and symbols printed without
words or beside them, each with the control it is printed on.

Text lines inside one control shape are joined in reading order (``+30`` / ``SEC``); two-line
labels also count as one; free-standing text stays a label of its own. Symbols come from the
icon templates (:mod:`apbot.vision.icons`): on keys with no text, as ink blobs of a label's
size, beside a word on a key (``TEMP ▲``, ``h ▷``, ``− 1``), and where OCR made a character
of a pictogram. Small text around a dial is marked as its tick labels.
"""

from __future__ import annotations

import itertools

import numpy as np

from apbot.vision.cv import cv2
from apbot.vision.detect import Candidate, Detection
from apbot.vision.label_geometry import Label as Label
from apbot.vision.label_geometry import _area as _area
from apbot.vision.label_geometry import _centre as _centre
from apbot.vision.label_geometry import _inside as _inside
from apbot.vision.label_geometry import _overlap as _overlap
from apbot.vision.label_geometry import _union as _union
from apbot.vision.label_geometry import _wordy as _wordy
from apbot.vision.label_symbols import EDGE_SYMBOLS as EDGE_SYMBOLS
from apbot.vision.label_symbols import HOLLOW_SYMBOLS as HOLLOW_SYMBOLS
from apbot.vision.label_symbols import STROKE_SYMBOLS as STROKE_SYMBOLS
from apbot.vision.label_symbols import _edge_symbols as _edge_symbols
from apbot.vision.label_symbols import _join_line_symbols as _join_line_symbols
from apbot.vision.label_symbols import _misread_symbols as _misread_symbols
from apbot.vision.label_symbols import _shape_symbols as _shape_symbols
from apbot.vision.label_symbols import _symbol_labels as _symbol_labels
from apbot.vision.locate import Window
from apbot.vision.ocr import read_crop


def _controls(detection: Detection, window: Window | None) -> list[Candidate]:
    """Shape and circle candidates that can be controls (not the display, not the panel)."""
    w, h = detection.size
    found = []
    for c in detection.candidates:
        if c.kind == "text":
            continue
        if window is not None and _inside(c.centre, window.box, 4):
            continue
        if _area(c.box) > 0.12 * w * h:
            continue
        found.append(c)
    return found


def make_labels(image: np.ndarray, detection: Detection, window: Window | None) -> list[Label]:
    """Labels from text lines (grouped per control) and from symbol-only controls."""
    texts = [t for t in detection.texts if window is None or not _inside(t.centre, window.box, 4)]
    line = float(np.median([t.box[3] - t.box[1] for t in texts])) if texts else 12.0
    shapes = sorted(
        (
            c
            for c in _controls(detection, window)
            if c.kind == "shape" and min(c.box[2] - c.box[0], c.box[3] - c.box[1]) >= 1.2 * line
        ),
        key=lambda c: _area(c.box),
    )
    used: set[int] = set()
    labels: list[Label] = []
    for shape in shapes:
        inside = [
            i
            for i, t in enumerate(texts)
            if i not in used and _inside(t.centre, shape.box) and _area(t.box) < _area(shape.box)
        ]
        if not inside:
            continue
        if _area(shape.box) > 40 * sum(_area(texts[i].box) for i in inside):
            continue  # a big frame around several labels, not one control
        used.update(inside)
        ordered = sorted(inside, key=lambda i: (round(texts[i].box[1] / 8), texts[i].box[0]))
        text = " ".join(texts[i].text for i in ordered)
        labels.append(Label(text, _union(texts[i].box for i in ordered), shape.box))
    for i, t in enumerate(texts):
        if i not in used:
            labels.append(Label(t.text, t.box))
    labels = _split_shared(image, labels, _controls(detection, window), line)
    labels += _stacked(labels)
    _misread_symbols(image, labels)
    _shape_symbols(image, shapes, labels)
    _symbol_labels(image, shapes, labels, line, window)
    labels = _missed_lines(image, labels, line, window)
    labels = _join_line_symbols(labels)
    _mark_ticks(detection, labels)
    for label in labels:
        label.symbols += [s for s in _edge_symbols(image, label) if s not in label.symbols]
    return labels


def _split_shared(image: np.ndarray, labels: list[Label], controls: list[Candidate],
                  line: float) -> list[Label]:  # fmt: skip
    """One text line that OCR made of the labels of two neighbouring keys (``HOT WATER`` and
    ``STRENGTH`` under two round keys): when two or more keys sit just above a free line,
    within its width, the line is cut at the widest blank gap between each pair of keys and
    each piece read again. A piece that does not read clearly keeps the line whole."""
    out: list[Label] = []
    for label in labels:
        pieces = _pieces(image, label, controls, line) if label.control is None else None
        out += pieces or [label]
    return out


def _pieces(image: np.ndarray, label: Label, controls: list[Candidate], line: float
            ) -> list[Label] | None:  # fmt: skip
    x0, y0, x1, y1 = label.box
    height = y1 - y0
    if len(label.text.split()) < 2 or height > 2 * line:
        return None
    above = sorted(
        (
            c
            for c in controls
            if x0 <= c.centre[0] <= x1
            and -0.2 * height <= y0 - c.box[3] <= 2.5 * height
            and (c.box[2] - c.box[0]) < 0.7 * (x1 - x0)
        ),
        key=lambda c: c.centre[0],
    )
    xs: list[float] = []
    for c in above:  # one key per position (a ring and its dot are one key)
        if not xs or c.centre[0] - xs[-1] > 1.5 * height:
            xs.append(c.centre[0])
    if len(xs) < 2:
        return None
    crop = image[int(y0) : int(y1) + 1, int(x0) : int(x1) + 1]
    from apbot.vision.icons import ink_of

    columns = np.asarray(np.asarray(ink_of(crop)).any(axis=0), dtype=bool)
    ink = [bool(v) for v in columns]
    cuts = []
    for a, b in itertools.pairwise(xs):
        lo, hi = int(a - x0), int(b - x0)
        gaps = [(e - s, (s + e) // 2) for s, e in _spans([not v for v in ink[lo:hi]])]
        if not gaps:
            return None
        width, middle = max(gaps)
        if width < 0.25 * height:
            return None  # letters run on between the keys: one label after all
        cuts.append(lo + middle)
    edges = [0, *cuts, len(ink)]
    pieces = []
    for a, b in itertools.pairwise(edges):
        pad = max(3, int(0.2 * height))
        text, confidence = read_crop(
            image[
                max(0, int(y0) - pad) : int(y1) + pad, max(0, int(x0) + a - pad) : int(x0) + b + pad
            ]
        )
        if confidence < 0.8 or not text:
            return None
        pieces.append(Label(text, (x0 + a, y0, x0 + b, y1)))
    return pieces


def _stacked(labels: list[Label]) -> list[Label]:
    """Two-line labels (``DRY`` over ``TIME``) as one more label: word lines of about one
    size, one under the other, centred alike and close, on no detected key. The single lines
    stay labels too (either may be a name of its own)."""
    loose = [lb for lb in labels if lb.control is None and _wordy(lb)]
    found = []
    for upper in loose:
        ux0, uy0, ux1, uy1 = upper.box
        for lower in loose:
            lx0, ly0, lx1, ly1 = lower.box
            height = min(uy1 - uy0, ly1 - ly0)
            if lower is upper or max(uy1 - uy0, ly1 - ly0) > 1.5 * height:
                continue
            centred = abs((ux0 + ux1) - (lx0 + lx1)) / 2 < 0.25 * max(ux1 - ux0, lx1 - lx0)
            if centred and -0.3 * height <= ly0 - uy1 < 0.6 * height:
                found.append(Label(f"{upper.text} {lower.text}", _union([upper.box, lower.box])))
    return found


def _missed_lines(image: np.ndarray, labels: list[Label], line: float,
                  window: Window | None) -> list[Label]:  # fmt: skip
    """Short legends the page-wide text detector missed (a switch printed ``I / O``: thin,
    widely spaced glyphs): a row of two or more glyph-sized ink blobs that no text label
    covers is read again as one crop; when it reads clearly as text with a letter, digit or
    slash in it, it becomes a text label and the symbols made of its glyphs (``O`` taken for
    a clock face) go."""
    gray = cv2.cvtColor(image, cv2.COLOR_RGB2GRAY)
    size = int(max(15, 4 * line)) | 1
    background = cv2.medianBlur(gray, min(size, 255))
    ink = (cv2.absdiff(gray, background) > 45).astype(np.uint8)
    reach = max(3, int(1.2 * line)) | 1
    joined = cv2.morphologyEx(ink, cv2.MORPH_CLOSE, np.ones((3, reach), np.uint8))
    count, _, stats, _ = cv2.connectedComponentsWithStats(joined, 8)
    words = [lb.box for lb in labels if lb.tokens and not lb.symbols]
    found: list[Label] = []
    for i in range(1, count):
        x, y, w, h, _ = (int(v) for v in stats[i])
        box = (float(x), float(y), float(x + w), float(y + h))
        if not (0.6 * line <= h <= 2.5 * line and 1.5 * h <= w <= 8 * line):
            continue
        if window is not None and _inside(_centre(box), window.box, 4):
            continue
        if any(_overlap(box, b) > 0.1 * _area(box) for b in words):
            continue
        parts, _, part_stats, _ = cv2.connectedComponentsWithStats(ink[y : y + h, x : x + w], 8)
        glyphs = [k for k in range(1, parts) if part_stats[k][3] >= 0.5 * h]
        if len(glyphs) < 2:
            continue
        text, confidence = max(  # the recogniser's confidence moves with the margin
            (
                read_crop(image[max(0, y - pad) : y + h + pad, max(0, x - pad) : x + w + pad])
                for pad in (max(4, int(0.3 * h)), max(5, int(0.4 * h)))
            ),
            key=lambda read: read[1],
        )
        if (
            confidence < 0.9
            or len(text.replace(" ", "")) < 2
            or not any(c.isalnum() or c == "/" for c in text)
        ):
            continue
        found.append(Label(text, box))
    if not found:
        return labels
    kept = [
        lb
        for lb in labels
        if lb.tokens or not any(_inside(_centre(lb.box), f.box, 2) for f in found)
    ]
    return kept + found


def _spans(flags: list[bool]) -> list[tuple[int, int]]:
    """(start, end) of each run of True."""
    spans, start = [], None
    for i, flag in enumerate([*flags, False]):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            spans.append((start, i))
            start = None
    return spans


def _mark_ticks(detection: Detection, labels: list[Label]) -> None:
    """Small text around a dial (not under it, not on a control of its own) is a tick label,
    not a control's name."""
    heights = [lb.box[3] - lb.box[1] for lb in labels if lb.control is None or lb.text]
    typical = float(np.median(heights)) if heights else 0.0
    for circle in (c for c in detection.candidates if c.kind == "circle"):
        cx, cy = circle.centre
        r = (circle.box[2] - circle.box[0]) / 2
        ring = []
        for label in labels:
            if label.control is not None and _area(label.control) < 4 * _area(label.box):
                continue
            if label.control is not None and (
                not _inside(circle.centre, label.control)
                or _area(circle.box) < 1.5 * _area(label.control)
            ):
                continue  # printed on a key of its own (round or beside the dial): its name
            lx, ly = _centre(label.box)
            d = float(np.hypot(lx - cx, ly - cy))
            if r * 0.9 < d < r * 1.9 and ly < cy + 1.1 * r:
                ring.append(label)
                if (label.box[3] - label.box[1]) < 0.85 * typical:
                    label.tick = True
        if len({_angle_step(lb, cx, cy) for lb in ring}) >= 3:
            for label in ring:  # three or more words around one dial: its positions, whatever
                label.tick = True  # their size (a programme dial printed ``cotton`` … ``spin``)


def _angle_step(label: Label, cx: float, cy: float) -> int:
    """The direction of a label from a dial's centre, in steps of 30 degrees."""
    lx, ly = _centre(label.box)
    return round(float(np.degrees(np.arctan2(ly - cy, lx - cx))) / 30.0)
