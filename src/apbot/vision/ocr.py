"""Text on a panel photo with RapidOCR (its detection and recognition models ship inside the
PyPI wheel: nothing is downloaded at run time).

One engine per process, created on first use. RapidOCR remembers per-call switches between
calls, so every call here passes ``use_det``, ``use_cls`` and ``use_rec`` explicitly.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np

from apbot.vision.cv import INSTALL_HINT, VisionUnavailable

LIMIT_SIDE = 960
"""Longest side the text detector works at (larger photos are shrunk; ~1.4 s per panel)."""

# characters the recogniser returns for symbols it has no class for
_FIXES = str.maketrans({"十": "+", "一": "-", "—": "-", "–": "-", "−": "-", "丨": "I", "〇": "0"})


@dataclass(frozen=True)
class TextBox:
    """One line of text found on the photo: its box (x0, y0, x1, y1), text and score."""

    box: tuple[float, float, float, float]
    text: str
    score: float

    @property
    def centre(self) -> tuple[float, float]:
        return ((self.box[0] + self.box[2]) / 2, (self.box[1] + self.box[3]) / 2)


@cache
def engine() -> Any:
    """The shared RapidOCR engine (detection limited to :data:`LIMIT_SIDE` pixels)."""
    try:
        from rapidocr import RapidOCR
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise VisionUnavailable(f"RapidOCR is not available ({exc}); {INSTALL_HINT}") from None
    return RapidOCR(
        params={
            "Det.limit_type": "max",
            "Det.limit_side_len": LIMIT_SIDE,
            "Global.log_level": "error",
        }
    )


def clean_text(text: str) -> str:
    """Recognised text with look-alike symbols mapped to what panels print."""
    return " ".join(text.translate(_FIXES).split())


def read_lines(image: np.ndarray) -> list[TextBox]:
    """Every text line on ``image`` (RGB) with its box, best first by position (top-left)."""
    if image.size == 0:
        return []
    result = engine()(image, use_det=True, use_cls=False, use_rec=True)
    boxes = getattr(result, "boxes", None)
    if boxes is None:
        return []
    found = []
    for quad, text, score in zip(boxes, result.txts, result.scores, strict=False):
        quad = np.asarray(quad, dtype=float)
        box = (quad[:, 0].min(), quad[:, 1].min(), quad[:, 0].max(), quad[:, 1].max())
        cleaned = clean_text(str(text))
        if cleaned:
            found.append(TextBox(tuple(float(v) for v in box), cleaned, float(score)))  # type: ignore[arg-type]
    found.sort(key=lambda t: (t.box[1], t.box[0]))
    return found


def read_crop(image: np.ndarray) -> tuple[str, float]:
    """Recognition only, on a crop holding one line of text: (text, score)."""
    if image.size == 0 or min(image.shape[:2]) < 4:
        return "", 0.0
    result = engine()(image, use_det=False, use_cls=False, use_rec=True)
    texts = getattr(result, "txts", None) or ()
    scores = getattr(result, "scores", None) or ()
    if not texts:
        return "", 0.0
    return clean_text(str(texts[0])), float(scores[0]) if scores else 0.0
