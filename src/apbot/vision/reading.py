"""Reading the display from a panel photo: locate the window once, decode every photo.

A robot standing in front of one appliance sees its display at the same place in every
photo, so :class:`DisplayCamera` finds the window on the first photo that shows one and then
only straightens and decodes that region (a crop, never whole-image OCR). The result keeps
every likely text (:class:`ImageReading.alternatives`) with a confidence; the agent's display
reader settles look-alikes against the belief's display rules.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from apbot.vision.decode import Geometry, decode_window
from apbot.vision.locate import Window, find_window, straighten


@dataclass
class ImageReading:
    """What a photo's display shows: the best text, the alternatives (text, cost), how sure,
    and the photo itself. ``problem`` says why nothing could be read (no display found)."""

    text: str
    alternatives: list[tuple[str, float]] = field(default_factory=list)
    confidence: float = 0.0
    problem: str = ""
    photo: Any = None

    @property
    def texts(self) -> list[str]:
        """The alternatives' texts, most likely first."""
        return [text for text, _ in self.alternatives] or [self.text]


def as_array(image: Any) -> np.ndarray | None:
    """An RGB uint8 array from a PIL image or array; None when it is not an image."""
    try:
        array = np.asarray(image)
    except Exception:
        return None
    if array.ndim == 2:
        array = np.stack([array] * 3, axis=2)
    if array.ndim != 3 or array.shape[2] < 3 or array.size == 0 or array.dtype == object:
        return None
    return np.ascontiguousarray(array[:, :, :3]).astype(np.uint8, copy=False)


class DisplayCamera:
    """Reads the display of one appliance seen from one viewpoint, photo after photo.

    ``keep_grid`` also reuses each row's fitted cell grid while it still fits a new photo
    about as well as the photo it was fitted on (otherwise the row is fitted again).
    """

    def __init__(self, window: Window | None = None, keep_grid: bool = True) -> None:
        self.window = window
        self.geometry: Geometry | None = {} if keep_grid else None

    def read(self, image: Any) -> ImageReading:
        """The display text of one photo (never raises on a bad photo: ``problem`` says)."""
        array = as_array(image)
        if array is None or min(array.shape[:2]) < 16:
            return ImageReading("", problem="not a usable image", photo=image)
        if self.window is None:
            self.window = find_window(array)
            if self.window is None:
                return ImageReading("", problem="no display window found", photo=image)
        decoded = decode_window(straighten(array, self.window), known=self.geometry)
        return ImageReading(
            decoded.text, decoded.alternatives, decoded.confidence, decoded.problem, image
        )


def read_display(image: Any) -> ImageReading:
    """Read the display of a single photo (locating the window in it)."""
    return DisplayCamera().read(image)
