"""What a label found on a panel photo is (:class:`Label`), and the box arithmetic every
label finder shares.

Kept apart from the finders of text labels (:mod:`apbot.vision.labels`) and of symbols
(:mod:`apbot.vision.label_symbols`) so that both, and the grounding that matches labels to
actions (:mod:`apbot.vision.ground`), use one definition.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from apbot.vision.detect import BoxT
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


def _wordy(label: Label) -> bool:
    """Whether a label has a word in it (not a lone character OCR made of a symbol)."""
    return any(len(t) >= 2 and t.isalpha() for t in label.tokens)
