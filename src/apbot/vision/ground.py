"""Grounding: each symbolic action name → one box on the panel photo and a skill.

Inputs are what a robot has: the photo and the belief's action names (the manual is not
needed by the rules here). Never the layout's true boxes — those only score the result.

1. Detect text lines and control candidates (:mod:`apbot.vision.detect`); drop what lies in
   the display window (its characters are not labels).
2. Make *labels* (:mod:`apbot.vision.labels`): the text lines inside one control shape
   joined in reading order (``+30`` / ``SEC``), free-standing text, and the symbols of
   controls printed without words or beside a word.
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
from dataclasses import dataclass

import numpy as np

from apbot.vision.detect import BoxT, Candidate, Detection, detect, iou
from apbot.vision.labels import (
    Label,
    _area,
    _centre,
    _controls,
    _inside,
    _union,
    _wordy,
    make_labels,
)
from apbot.vision.locate import Window, find_window
from apbot.vision.vocabulary import label_symbols, name_parts, words_score

MIN_SCORE = 0.6
"""A label must match an action's words at least this well to ground it."""
UNPRINTED_COST = 0.85
"""A key matched on its printed words only (a name word printed nowhere) scores this much less."""


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
    tokens = [t for t in label.tokens if t != "+" or label.text.strip() == "+"]
    score = words_score(words, tokens, label.symbols + label_symbols(label.text))
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
    # a name word printed nowhere ("delay" of delay_up on a key printed "h ▷") is left out
    # of its key's match, at a cost, when the key's other words are printed
    named = {w for key in keys for w in key}
    printed = {w for w in named if any(_score([w], lb, False) >= MIN_SCORE for lb in labels)}
    pairs = []
    for key, turn in keys.items():
        shown = [w for w in key if w in printed]
        partial = 0 < len(shown) < len(key)
        for index, label in enumerate(labels):
            score = _score(list(key), label, turn)
            if partial:
                score = max(score, UNPRINTED_COST * _score(shown, label, turn))
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
    claimed = [_target(labels[i], detection, window, keys[key]) for key, (i, _) in chosen.items()]
    _eliminate(keys, labels, chosen, taken, claimed, window)
    for action, (skill, parts) in list(parsed.items()):
        both = tuple(parts[0])
        if skill == "hold" and len(parts) == 1 and both not in chosen:
            for i in range(1, len(both)):
                if both[:i] in chosen and both[i:] in chosen:
                    parsed[action] = (skill, [list(both[:i]), list(both[i:])])
                    break
    claimed = [_target(labels[i], detection, window, keys[key]) for key, (i, _) in chosen.items()]
    keyed = [lb.control for lb in labels if lb.control is not None]
    result: dict[str, Grounded] = {}
    missing: dict[str, str] = {a: "a wait touches no control" for a in waits}
    dial = _only_dial(detection, window, claimed)
    turned = {tuple(p[0]) for k, p in parsed.values() if k.startswith("turn") and p != [[]]}
    lone_turn = next(iter(turned)) if len(turned) == 1 and not any(
        k.startswith("turn") and p == [[]] for k, p in parsed.values()
    ) else None  # fmt: skip
    for action, (skill, parts) in parsed.items():
        if parts == [[]]:  # "turn_cw", "press_knob": the panel's dial, if it has one
            if dial is None:
                missing[action] = "the name names no control and the panel shows no one dial"
            else:
                result[action] = Grounded(action, skill, [dial], "(the dial)", 0.7)
            continue
        boxes, names, scores = [], [], []
        for part in parts:
            hit = chosen.get(_owner(tuple(part), parts, chosen, keys, labels))
            if hit is None:
                break
            label = labels[hit[0]]
            boxes.append(_target(label, detection, window, skill.startswith("turn"), keyed))
            names.append(label.text)
            scores.append(hit[1])
        if len(boxes) != len(parts):
            wanted = " / ".join(" ".join(p) for p in parts)
            if skill.startswith("turn") and dial is not None and lone_turn == tuple(parts[0]):
                result[action] = Grounded(action, skill, [dial], "(the dial)", 0.65)
                continue  # the one dial is the only thing to turn (its name not printed)
            missing[action] = f"no label on the panel matches {wanted!r}"
            continue
        result[action] = Grounded(action, skill, boxes, " + ".join(names), min(scores))
    return Grounding(result, missing, labels, window, detection.size,
                     time.perf_counter() - started)  # fmt: skip


def _eliminate(keys: dict[tuple[str, ...], bool], labels: list[Label],
               chosen: dict[tuple[str, ...], tuple[int, float]], taken: set[int],
               claimed: list[BoxT], window: Window | None) -> None:  # fmt: skip
    """The one key name nothing matched and the one labelled control nothing claimed belong
    together (``hot`` and a key printed ``65°``, ``grind`` and ``BEANS/GROUND``): a panel has
    no key without a use, and a name with no key cannot be pressed. Only one to one, and only
    labels on a key or with a word or symbol, off the display, not dial ticks, and outside
    every control already claimed."""
    unmatched = [
        k
        for k, turn in keys.items()
        if k and not turn and k not in chosen and not _combination(k, keys)
    ]
    if len(unmatched) != 1:
        return
    free = []
    for index, label in enumerate(labels):
        if index in taken or label.tick:
            continue
        if not (label.control is not None or _wordy(label) or label.symbols):
            continue
        place = label.control or label.box
        if window is not None and _inside(_centre(place), window.box, 4):
            continue
        if any(_inside(_centre(place), box, 2) or _inside(_centre(box), place) for box in claimed):
            continue
        free.append(index)
    keyed = [i for i in free if labels[i].control is not None]
    for tier in ([i for i in keyed if _wordy(labels[i])], keyed, free):
        if tier:  # the likeliest kind of place first: a named key, any key, any label
            if len(tier) == 1:
                chosen[unmatched[0]] = (tier[0], MIN_SCORE)
                taken.add(tier[0])
            return


def _owner(part: tuple[str, ...], parts: list[list[str]],
           chosen: dict[tuple[str, ...], tuple[int, float]],
           keys: dict[tuple[str, ...], bool], labels: list[Label]) -> tuple[str, ...]:  # fmt: skip
    """The key a part of a two-key hold names: a key of its own, or (``rinse`` of
    ``hold_rinse_and_presoak``) the smallest other key holding all its words, whose label
    then wins over a caption that matches the short name better."""
    if len(parts) < 2 or (part in chosen and labels[chosen[part][0]].control is not None):
        return part  # one key, or a part whose own label is printed on a key
    wider = [k for k in chosen if k != part and len(k) > len(part) and set(part) <= set(k)
             and not keys.get(k, False)]  # fmt: skip
    return min(wider, key=len) if wider else part


def _combination(key: tuple[str, ...], keys: Iterable[tuple[str, ...]]) -> bool:
    """Whether ``key`` is two other keys' words one after the other (a two-key hold)."""
    others = set(keys) - {key}
    return any(key[:i] in others and key[i:] in others for i in range(1, len(key)))


def _target(label: Label, detection: Detection, window: Window | None, turn: bool,
            keyed: Sequence[BoxT] = ()) -> BoxT:  # fmt: skip
    """The box to touch for a label: its control, a dial it names, the shape above it (not
    a key of another label: ``keyed``)."""
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
    if not any(ch.isalnum() for ch in label.text):
        return label.box  # a printed symbol is itself the place to touch
    above = [
        c
        for c in shapes
        if abs(c.centre[0] - lx) < 0.6 * max(c.box[2] - c.box[0], label.box[2] - label.box[0])
        and 0 < ly - c.centre[1] < 4 * height + (c.box[3] - c.box[1])
        and not any(_inside(c.centre, lb) for lb in [label.box])
        and _area(c.box) < 30 * _area(label.box)
        and c.box[3] - c.box[1] < 3 * height  # a pictogram, not a dial or a slider's track
        and label.box[1] - c.box[3] < 1.5 * height  # just above the word
        and not any(iou(c.box, k) > 0.5 for k in keyed)
        # another key (text on it) or a letter of another label (inside its text) is no icon
        and not any(_inside(t.centre, c.box) or _inside(c.centre, t.box) for t in detection.texts)
    ]
    if above:
        nearest = min(above, key=lambda c: ly - c.centre[1])
        return _union([nearest.box, label.box])
    return label.box


def _only_dial(detection: Detection, window: Window | None, claimed: Sequence[BoxT] = ()
               ) -> BoxT | None:  # fmt: skip
    """The panel's dial when one circle stands out (the largest, clearly larger than any
    other); a circle on a control already claimed by its label is a round key, not a dial."""
    circles = sorted(
        (
            c
            for c in _controls(detection, window)
            if (c.kind == "circle" or _round(c))
            and not any(_inside(_centre(b), c.box) for b in claimed)
        ),
        key=lambda c: -(c.box[2] - c.box[0]),
    )
    if not circles:
        return None
    if (
        len(circles) > 1
        and (circles[1].box[2] - circles[1].box[0]) > 0.8 * (circles[0].box[2] - circles[0].box[0])
        and not _inside(circles[1].centre, circles[0].box)
    ):
        return None
    return circles[0].box


def _round(candidate: Candidate) -> bool:
    w, h = candidate.box[2] - candidate.box[0], candidate.box[3] - candidate.box[1]
    return 0.8 < w / max(1.0, h) < 1.25


def ground_photo(image: np.ndarray, actions: Iterable[str]) -> Grounding:
    """:func:`ground` for any iterable of action names (kept in order)."""
    return ground(image, list(actions))
