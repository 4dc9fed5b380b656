"""Grounding: each symbolic action name → one box on the panel photo and a skill.

Inputs are what a robot has: the photo and the belief's action names (the manual is not
needed by the rules here). Never the layout's true boxes — those only score the result.

1. Detect text lines and control candidates (:mod:`apbot.vision.detect`); drop what lies in
   the display window (its characters are not labels).
2. Make *labels*: the text lines inside one control shape joined in reading order (``+30`` /
   ``SEC``), free-standing text, and the symbols of controls printed without words
   (:mod:`apbot.vision.icons`, plus recognition of single characters such as ``P``).
3. Parse each action name into a skill and the words naming its control(s)
   (``hold_up_down`` → hold, two controls ``up`` and ``down``).
4. Score every (action words, label) pair (fuzzy words, synonyms, symbols), then assign
   greedily, best first, one label per control: actions naming the same words share it
   (``press_lock`` and ``hold_lock``), different words never do.
5. From a label to the thing to touch: the control shape it is printed on, else the shape
   just above it (a label printed under an icon), the dial it names for a turn, else the
   label itself (a printed soft-touch pad).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np

from apbot.vision.cv import cv2
from apbot.vision.detect import BoxT, Candidate, Detection, detect
from apbot.vision.icons import classify
from apbot.vision.locate import Window, find_window
from apbot.vision.ocr import read_crop
from apbot.vision.vocabulary import label_tokens, name_parts, words_score

MIN_SCORE = 0.6
"""A label must match an action's words at least this well to ground it."""


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


@dataclass
class Grounded:
    """Where to act for one action: box(es) in photo pixels, the point(s), and the skill."""

    action: str
    skill: str
    boxes: list[BoxT]
    label: str
    score: float

    @property
    def points(self) -> list[tuple[float, float]]:
        return [((b[0] + b[2]) / 2, (b[1] + b[3]) / 2) for b in self.boxes]


@dataclass
class Grounding:
    """The grounding of a whole panel: grounded actions, the ones that could not be, why."""

    actions: dict[str, Grounded]
    ungrounded: dict[str, str]
    labels: list[Label]
    window: Window | None
    size: tuple[int, int]
    seconds: float = 0.0


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
    _symbol_labels(image, shapes, labels, line, window)
    _mark_ticks(detection, labels)
    for label in labels:
        label.symbols += _edge_symbols(image, label)
    return labels


def _symbol_labels(image: np.ndarray, shapes: list[Candidate], labels: list[Label],
                   line: float, window: Window | None) -> None:  # fmt: skip
    """Symbols printed without words (⏻, +, 🔒 …): ink blobs of about a label's size that no
    text line covers, each classified against the symbol templates; a blob on a control shape
    gets that shape as its control."""
    gray = cv2.cvtColor(image, cv2.COLOR_RGB2GRAY)
    size = int(max(15, 4 * line)) | 1
    background = cv2.medianBlur(gray, min(size, 255) if size < 255 else 255)
    ink = (cv2.absdiff(gray, background) > 45).astype(np.uint8)
    join = max(3, int(0.35 * line)) | 1
    ink = cv2.morphologyEx(ink, cv2.MORPH_CLOSE, np.ones((join, join), np.uint8))
    count, _, stats, _ = cv2.connectedComponentsWithStats(ink, 8)
    printed = [label.box for label in labels]
    budget = 25
    for i in range(1, count):
        x, y, w, h, _ = (int(v) for v in stats[i])
        box = (float(x), float(y), float(x + w), float(y + h))
        if not (0.6 * line <= max(w, h) <= 5 * line) or max(w, h) > 4 * max(1, min(w, h)):
            continue
        if window is not None and _inside(_centre(box), window.box, 4):
            continue
        if any(_overlap(box, p) > 0.2 * _area(box) for p in printed):
            continue
        pad = 2
        crop = image[max(0, y - pad) : y + h + pad, max(0, x - pad) : x + w + pad]
        symbol, _ = classify(crop)
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
    """A symbol printed beside a word (``TEMP ▲``): the first and last ink blobs of the label
    box, checked against the symbol templates."""
    x0, y0, x1, y1 = (int(v) for v in label.box)
    crop = image[max(0, y0) : y1, max(0, x0) : x1]
    if crop.size == 0 or crop.shape[1] < 8:
        return []
    from apbot.vision.icons import ink_of

    ink = ink_of(crop)
    columns: list[bool] = list(np.asarray(ink).any(axis=0).tolist())  # type: ignore[arg-type]
    runs = []
    start = None
    for x, on in enumerate(columns):
        if on and start is None:
            start = x
        elif not on and start is not None:
            runs.append((start, x))
            start = None
    if start is not None:
        runs.append((start, len(columns)))
    if len(runs) < 2:
        return []
    found = []
    for a, b in (runs[0], runs[-1]):
        symbol, score = classify(crop[:, a:b], minimum=0.72)
        if symbol and symbol not in "½" and score >= 0.72:
            found.append(symbol)
    return found


def _mark_ticks(detection: Detection, labels: list[Label]) -> None:
    """Text around a dial (not under it) is a tick label, not a control's name."""
    for circle in (c for c in detection.candidates if c.kind == "circle"):
        cx, cy = circle.centre
        r = (circle.box[2] - circle.box[0]) / 2
        for label in labels:
            lx, ly = _centre(label.box)
            d = float(np.hypot(lx - cx, ly - cy))
            if r * 0.9 < d < r * 1.9 and ly < cy + 1.1 * r:
                label.tick = True


# --- matching and assignment --------------------------------------------------------------------


@dataclass
class _Wanted:
    key: tuple[str, ...]  # the words naming one control
    actions: list[str]
    turn: bool


def _groups(actions: Sequence[str]) -> tuple[dict[str, tuple[str, list[list[str]]]], list[str]]:
    """Each action's skill and control word lists (two lists for a two-control hold)."""
    parsed: dict[str, tuple[str, list[list[str]]]] = {}
    waits = []
    for action in actions:
        skill, words = name_parts(action)
        if skill == "wait":
            waits.append(action)
            continue
        parts = [words]
        if "and" in words:
            i = words.index("and")
            parts = [words[:i], words[i + 1 :]]
        parsed[action] = (skill, [p for p in parts if p] or [words])
    return parsed, waits


def _score(words: list[str], label: Label, turn: bool) -> float:
    score = words_score(words, label.tokens, label.symbols)
    if label.tick:
        score -= 0.3
    if turn and label.control is None:
        score -= 0.05
    return score


def ground(image: np.ndarray | None, actions: Sequence[str]) -> Grounding:
    """Ground every action name on a panel photo (RGB array). Never raises on a bad photo:
    an empty or unreadable one grounds nothing, and says so."""
    import time

    started = time.perf_counter()
    if image is None or not isinstance(image, np.ndarray) or image.ndim != 3 or image.size == 0:
        reason = "no usable panel photo"
        return Grounding({}, {a: reason for a in actions}, [], None, (0, 0))
    detection = detect(image)
    window = find_window(image)
    labels = make_labels(image, detection, window)
    parsed, waits = _groups(actions)
    # two-control holds whose words were not split by "and": try every split
    for action, (skill, parts) in list(parsed.items()):
        if skill == "hold" and len(parts) == 1 and len(parts[0]) >= 2:
            words = parts[0]
            whole = max((_score(words, lb, False) for lb in labels), default=0.0)
            best_split, best = None, whole + 0.05
            for i in range(1, len(words)):
                a = max((_score(words[:i], lb, False) for lb in labels), default=0.0)
                b = max((_score(words[i:], lb, False) for lb in labels), default=0.0)
                if min(a, b) > best:
                    best_split, best = [words[:i], words[i:]], min(a, b)
            if best_split is not None:
                parsed[action] = (skill, best_split)
    keys: dict[tuple[str, ...], bool] = {}
    for skill, parts in parsed.values():
        for part in parts:
            keys[tuple(part)] = keys.get(tuple(part), False) or skill.startswith("turn")
    pairs = []
    for key, turn in keys.items():
        for index, label in enumerate(labels):
            score = _score(list(key), label, turn)
            if score >= MIN_SCORE:
                pairs.append((score, key, index))
    pairs.sort(key=lambda p: (-p[0], p[1]))
    chosen: dict[tuple[str, ...], tuple[int, float]] = {}
    taken: set[int] = set()
    for score, key, index in pairs:
        if key in chosen or index in taken:
            continue
        chosen[key] = (index, score)
        taken.add(index)
    result: dict[str, Grounded] = {}
    missing: dict[str, str] = {a: "a wait touches no control" for a in waits}
    for action, (skill, parts) in parsed.items():
        boxes, names, scores = [], [], []
        for part in parts:
            hit = chosen.get(tuple(part))
            if hit is None:
                break
            label = labels[hit[0]]
            boxes.append(_target(label, detection, window, skill.startswith("turn")))
            names.append(label.text)
            scores.append(hit[1])
        if len(boxes) != len(parts):
            wanted = " / ".join(" ".join(p) for p in parts)
            missing[action] = f"no label on the panel matches {wanted!r}"
            continue
        result[action] = Grounded(action, skill, boxes, " + ".join(names), min(scores))
    return Grounding(result, missing, labels, window, detection.size,
                     time.perf_counter() - started)  # fmt: skip


def _target(label: Label, detection: Detection, window: Window | None, turn: bool) -> BoxT:
    """The box to touch for a label: its control, a dial it names, the shape above it."""
    shapes = _controls(detection, window)
    lx, ly = _centre(label.box)
    height = label.box[3] - label.box[1]
    if turn:
        circles = [c for c in shapes if c.kind == "circle" or _round(c)]
        near = [c for c in circles if abs(c.centre[0] - lx) < (c.box[2] - c.box[0])
                and c.centre[1] <= ly + height]  # fmt: skip
        if near:
            return min(near, key=lambda c: np.hypot(c.centre[0] - lx, c.centre[1] - ly)).box
    if label.control is not None:
        return label.control
    above = [
        c
        for c in shapes
        if abs(c.centre[0] - lx) < 0.6 * max(c.box[2] - c.box[0], label.box[2] - label.box[0])
        and 0 < ly - c.centre[1] < 4 * height + (c.box[3] - c.box[1])
        and not any(_inside(c.centre, lb) for lb in [label.box])
        and _area(c.box) < 30 * _area(label.box)
    ]
    if above:
        nearest = min(above, key=lambda c: ly - c.centre[1])
        return _union([nearest.box, label.box])
    return label.box


def _round(candidate: Candidate) -> bool:
    w, h = candidate.box[2] - candidate.box[0], candidate.box[3] - candidate.box[1]
    return 0.8 < w / max(1.0, h) < 1.25


def ground_photo(image: np.ndarray, actions: Iterable[str]) -> Grounding:
    """:func:`ground` for any iterable of action names (kept in order)."""
    return ground(image, list(actions))
