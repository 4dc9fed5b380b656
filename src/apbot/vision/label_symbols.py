"""Symbols printed on a panel (⏻, ▲, 🔒, +): on keys with no text, as ink blobs of a label's
size, beside a word on a key (``TEMP ▲``, ``h ▷``, ``− 1``), and where OCR made a character
of a pictogram; each matched against the icon templates (:mod:`apbot.vision.icons`).

Kept apart from the text labels (:mod:`apbot.vision.labels`) because finding pictograms is
template matching on ink, while text labels come from OCR lines grouped per control.
"""

from __future__ import annotations

import numpy as np

from apbot.vision.cv import cv2
from apbot.vision.detect import BoxT, Candidate
from apbot.vision.icons import classify, classify_ink
from apbot.vision.label_geometry import Label, _area, _centre, _inside, _overlap, _union, _wordy
from apbot.vision.locate import Window
from apbot.vision.ocr import read_crop


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
