"""OpenCV, imported once with a clear message when the ``vision`` extra is missing."""

from __future__ import annotations

from typing import Any

INSTALL_HINT = (
    "install the vision extra: pip install -e '.[vision]' (opencv, rapidocr, onnxruntime)"
)


class VisionUnavailable(ImportError):
    """A vision dependency is not installed."""


def _load() -> Any:
    try:
        import cv2 as module
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise VisionUnavailable(f"OpenCV is not available ({exc}); {INSTALL_HINT}") from None
    module.setNumThreads(1)
    return module


cv2: Any = _load()
