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
from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np

from apbot.vision.cv import cv2
from apbot.vision.detect import BoxT, Candidate, Detection
from apbot.vision.icons import classify, classify_ink
from apbot.vision.locate import Window
from apbot.vision.ocr import read_crop
from apbot.vision.vocabulary import label_tokens


@dataclass
class Label:
    """Printed text or a symbol, and the control it is printed on (when one was found)."""

    text: str
    box: BoxT
    control: BoxT | None = None
    symbols: list[str] = field(default_factory=list)
    tick: bool = False

    @property
    def tokens(self) -> list[str]:
        return label_tokens(self.text)


def _inside(point: tuple[float, float], box: BoxT, pad: float = 0.0) -> bool:
    return box[0] - pad <= point[0] <= box[2] + pad and box[1] - pad <= point[1] <= box[3] + pad


def _overlap(a: BoxT, b: BoxT) -> float:
    """Area shared by two boxes."""
    return max(0.0, min(a[2], b[2]) - max(a[0], b[0])) * max(0.0, min(a[3], b[3]) - max(a[1], b[1]))


def _area(box: BoxT) -> float:
    return max(0.0, box[2] - box[0]) * max(0.0, box[3] - box[1])


def _centre(box: BoxT) -> tuple[float, float]:
    return ((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)


def _union(boxes: Iterable[BoxT]) -> BoxT:
    boxes = list(boxes)
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes),
            max(b[3] for b in boxes))  # fmt: skip


# --- labels -------------------------------------------------------------------------------------


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


def _misread_symbols(image: np.ndarray, labels: list[Label]) -> None:
    """A pictogram OCR read as a character or two (💡 as ``9``, + as ``X``, ☀ as ``米``, ▷ as
    ``D``): when the glyph matches one symbol template clearly better than any other, the
    label means that symbol too (its text is kept)."""
    from apbot.vision.icons import ink_of, rank_ink

    for label in labels:
        text = label.text.replace(" ", "")
        if label.symbols or not 0 < len(text) <= 2:
            continue
        if label.control is not None and _area(label.control) < 12 * _area(label.box):
            bx0, by0, bx1, by1 = label.control  # the whole key face: OCR may box part of it
            mx, my = 0.18 * (bx1 - bx0), 0.18 * (by1 - by0)
            x0, y0, x1, y1 = int(bx0 + mx), int(by0 + my), int(bx1 - mx), int(by1 - my)
            m = 0
        else:
            x0, y0, x1, y1 = (int(v) for v in label.box)
            m = max(2, int(0.1 * (y1 - y0)))
        crop = image[max(0, y0 - m) : y1 + m, max(0, x0 - m) : x1 + m]
        if crop.size == 0 or min(crop.shape[:2]) < 8:
            continue
        ranked = rank_ink(ink_of(crop))
        if len(ranked) < 2:
            continue
        (symbol, best), (_, second) = ranked[0], ranked[1]
        digits = text.isdigit()  # a real digit must look far more like the symbol
        if best >= (0.85 if digits else 0.72) and best - second >= (0.2 if digits else 0.06):
            label.symbols.append(symbol)


def _wordy(label: Label) -> bool:
    """Whether a label has a word in it (not a lone character OCR made of a symbol)."""
    return any(len(t) >= 2 and t.isalpha() for t in label.tokens)


def _join_line_symbols(labels: list[Label]) -> list[Label]:
    """A symbol found on its own just beside a word on the same line (``TIME −`` when OCR
    kept only ``TIME``) belongs to that word's label, not to a control of its own."""
    words = [lb for lb in labels if _wordy(lb)]
    kept = []
    for label in labels:
        if label.tokens or not label.symbols or label in words:
            kept.append(label)
            continue
        cy = _centre(label.box)[1]
        host, host_gap = None, 0.0
        for word in words:
            x0, y0, x1, y1 = word.box
            gap = max(x0 - label.box[2], label.box[0] - x1)
            same_control = label.control is None or label.control == word.control
            near = y0 <= cy <= y1 and gap < 1.0 * (y1 - y0) and same_control
            if near and (host is None or gap < host_gap):
                host, host_gap = word, gap
        if host is None:
            kept.append(label)
        else:
            host.symbols += [s for s in label.symbols if s not in host.symbols]
            host.box = _union([host.box, label.box])
    return kept


def _shape_symbols(image: np.ndarray, shapes: list[Candidate], labels: list[Label]) -> None:
    """Buttons with no text on them: the symbol printed inside (⏻ on a round key)."""
    taken = [label.box for label in labels]
    seen: list[BoxT] = []
    for shape in shapes:
        if any(_overlap(shape.box, t) > 0 for t in taken) or any(
            _inside(_centre(shape.box), s) for s in seen
        ):
            continue
        x0, y0, x1, y1 = shape.box
        mx, my = 0.18 * (x1 - x0), 0.18 * (y1 - y0)
        crop = image[int(y0 + my) : int(y1 - my), int(x0 + mx) : int(x1 - mx)]
        if crop.size == 0:
            continue
        symbol, score = classify(crop, minimum=0.6)
        if symbol:
            seen.append(shape.box)
            text, confidence = read_crop(crop)
            if confidence >= 0.9 and text.isdigit() and len(text) <= 2 and score < 0.85:
                labels.append(Label(text, shape.box, shape.box))  # a keypad digit the
                continue  # page-wide OCR missed, not a pictogram that looks a bit like it
            labels.append(Label(symbol, shape.box, shape.box, [symbol]))


def _symbol_labels(image: np.ndarray, shapes: list[Candidate], labels: list[Label],
                   line: float, window: Window | None) -> None:  # fmt: skip
    """Symbols printed without words (⏻, +, 🔒 …): ink blobs of about a label's size that no
    text line covers, each classified against the symbol templates; a blob on a control shape
    gets that shape as its control."""
    gray = cv2.cvtColor(image, cv2.COLOR_RGB2GRAY)
    size = int(max(15, 4 * line)) | 1
    background = cv2.medianBlur(gray, min(size, 255) if size < 255 else 255)
    ink = (cv2.absdiff(gray, background) > 45).astype(np.uint8)
    raw = ink.copy()
    join = max(3, int(0.35 * line)) | 1
    ink = cv2.morphologyEx(ink, cv2.MORPH_CLOSE, np.ones((join, join), np.uint8))
    count, _, stats, _ = cv2.connectedComponentsWithStats(ink, 8)
    printed = [label.box for label in labels]
    budget = 25
    for i in range(1, count):
        x, y, w, h, _ = (int(v) for v in stats[i])
        box = (float(x), float(y), float(x + w), float(y + h))
        if not (0.6 * line <= max(w, h) <= 5 * line) or max(w, h) > 10 * max(1, min(w, h)):
            continue
        if w < h and max(w, h) > 4 * max(1, min(w, h)):
            continue  # a tall thin line is an edge, not a symbol
        if window is not None and _inside(_centre(box), window.box, 4):
            continue
        if any(_overlap(box, p) > 0.2 * _area(box) for p in printed):
            continue
        symbol, _ = classify_ink(raw[y : y + h, x : x + w] > 0)
        text = ""
        if not symbol and budget > 0 and max(w, h) >= line:
            budget -= 1
            text, confidence = read_crop(
                image[max(0, y - 6) : y + h + 6, max(0, x - 6) : x + w + 6]
            )
            if confidence < 0.85 or len(text) > 2:
                text = ""
        if not (symbol or text):
            continue
        owner = [
            s.box for s in shapes if _inside(_centre(box), s.box) and _area(s.box) < 30 * _area(box)
        ]
        control = min(owner, key=_area) if owner else None
        labels.append(Label(text or symbol, box, control, [symbol] if symbol else []))


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


def _edge_symbols(image: np.ndarray, label: Label) -> list[str]:
    """Arrows and signs printed with a word on one key (``TEMP ▲``, ``◀ PROG``, ``⏻ START``,
    ``↕ SWING``), inside the label's box or just beside it on its line (OCR often boxes the
    word only). Ink blobs whose columns overlap are one glyph (⏻ is an arc and a bar); a
    glyph about a capital's height is checked against those symbols' templates (letters fit
    badly), and a triangle must be solid."""
    x0, y0, x1, y1 = label.box
    height = y1 - y0
    if label.control is not None:  # a key: anywhere on it (⏻ above START/STOP)
        cx0, cy0, cx1, cy1 = label.control
        mx, my = 0.06 * (cx1 - cx0), 0.06 * (cy1 - cy0)
        ex0, ey0, ex1, ey1 = cx0 + mx, cy0 + my, cx1 - mx, cy1 - my
    elif _wordy(label):  # beside the word on its line
        ex0, ex1 = x0 - 1.3 * height, x1 + 1.3 * height
        ey0, ey1 = y0 - 0.15 * height, y1 + 0.15 * height
    else:
        ex0, ey0, ex1, ey1 = label.box
    ix0, iy0 = max(0, int(min(ex0, x0))), max(0, int(min(ey0, y0)))
    crop = image[iy0 : int(max(ey1, y1)) + 1, ix0 : int(max(ex1, x1)) + 1]
    if crop.size == 0 or min(crop.shape[:2]) < 8:
        return []
    from apbot.vision.icons import ink_of, rank_ink

    ink = ink_of(crop).astype(np.uint8)
    count, parts, stats, _ = cv2.connectedComponentsWithStats(ink, 8)
    sizes = [int(stats[i][3]) for i in range(1, count) if stats[i][4] >= 12]
    if not sizes:
        return []
    height = float(np.median(sizes))  # a letter's height
    blobs = [
        i
        for i in range(1, count)
        if stats[i][4] >= 12 and stats[i][3] < 2.5 * height and stats[i][2] < 2.5 * height
    ]
    group = {i: i for i in blobs}

    def root(i: int) -> int:
        while group[i] != i:
            i = group[i]
        return i

    for n, i in enumerate(blobs):  # columns overlap and rows touch: one glyph
        xi, yi, wi, hi, _ = (int(v) for v in stats[i])
        for j in blobs[n + 1 :]:
            xj, yj, wj, hj, _ = (int(v) for v in stats[j])
            gap_y = max(yi - (yj + hj), yj - (yi + hi))
            if min(xi + wi, xj + wj) > max(xi, xj) and gap_y < 0.4 * height:
                group[root(j)] = root(i)
    members: dict[int, list[int]] = {}
    for i in blobs:
        members.setdefault(root(i), []).append(i)
    glyphs = list(members.values())
    found = []
    for glyph in glyphs:
        gx0 = min(int(stats[i][0]) for i in glyph)
        gx1 = max(int(stats[i][0] + stats[i][2]) for i in glyph)
        gy0 = min(int(stats[i][1]) for i in glyph)
        gy1 = max(int(stats[i][1] + stats[i][3]) for i in glyph)
        w, h = gx1 - gx0, gy1 - gy0
        if h < 0.6 * height and w < 0.6 * height:
            continue
        mask = np.isin(parts[gy0:gy1, gx0:gx1], glyph)
        short = len(label.text.replace(" ", "")) <= 2  # "1" of a key printed "− 1"
        if short and h <= 0.3 * w and w >= 0.4 * height and mask.mean() >= 0.6:
            if "−" not in found:
                found.append("−")  # a solid bar beside a digit: the minus sign OCR dropped
            continue
        fill = mask.sum() / float(w * h)
        symbol, _ = classify_ink(mask, minimum=0.85, among=EDGE_SYMBOLS + STROKE_SYMBOLS)
        if not symbol and fill < 0.35:  # an outlined triangle: thin strokes, mostly empty
            ranked = rank_ink(mask)
            best, score = ranked[0] if ranked else ("", 0.0)
            if best in HOLLOW_SYMBOLS and score >= 0.65 and score - ranked[1][1] >= 0.06:
                symbol = best
        if not symbol:
            continue
        if symbol in EDGE_SYMBOLS and not 0.42 <= fill <= 0.7:
            continue  # the arrows are solid triangles; letters are strokes
        if symbol not in found:
            found.append(symbol)
    return found


EDGE_SYMBOLS = "▲▼◀▶◄►"
"""Solid arrows printed beside a word on a key (``TEMP ▲``, ``◀ PROG``)."""
HOLLOW_SYMBOLS = "◁▷"
"""Outlined arrows printed beside a word or a unit (``◁ h``, ``h ▷``)."""
STROKE_SYMBOLS = "⏻↕↔"
"""Line-drawn symbols printed beside a word (``⏻ START/STOP``, ``↕ SWING``)."""


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
