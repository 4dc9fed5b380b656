"""Seeded camera variations: a clean rendering turned into something like a photo.

A :class:`Camera` fixes what stays put while a robot stands in front of a panel (viewpoint,
scale, lighting, glare, focus, JPEG quality); each frame adds its own sensor noise. The same
seed always gives the same camera, so every figure is reproducible, and a camera knows the
homography from clean-rendering pixels to photo pixels (the scorer and the panel
environment need it; a reader never sees it).
"""

from __future__ import annotations

import io
import random
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from PIL import Image, ImageFilter

Matrix = np.ndarray
LEVELS = ("clean", "mild", "strong")


@dataclass(frozen=True)
class Camera:
    """One viewpoint and its imaging conditions. ``level``: ``clean`` (none at all), ``mild``
    or ``strong``."""

    level: str = "clean"
    gain: float = 1.0
    gradient: tuple[float, float] = (0.0, 0.0)
    tint: tuple[float, float, float] = (1.0, 1.0, 1.0)
    glare: tuple[float, float, float, float] | None = None  # x, y (fractions), radius, strength
    blur: float = 0.0
    corners: tuple[float, ...] = (0.0,) * 8  # corner offsets as fractions of width/height
    noise: float = 0.0
    jpeg: int | None = None
    zoom: float = 1.0
    seed: int = 0

    @classmethod
    def sample(cls, seed: int, level: str = "mild") -> Camera:
        """A camera drawn from ``seed``: ``mild`` is an ordinary phone photo in a kitchen,
        ``strong`` a poor one (dim or uneven light, glare, blur, a slanted view, noise)."""
        if level == "clean":
            return cls(seed=seed)
        if level not in LEVELS:
            raise ValueError(f"unknown variation level {level!r}; use {', '.join(LEVELS)}")
        rng = random.Random(f"camera/{seed}/{level}")
        k = 1.0 if level == "mild" else 1.8
        glare = (
            (rng.uniform(0.1, 0.9), rng.uniform(0.1, 0.9), rng.uniform(0.1, 0.3),
             rng.uniform(0.1, 0.25) * k)
            if rng.random() < 0.6
            else None
        )  # fmt: skip
        return cls(
            level=level,
            gain=rng.uniform(1 - 0.15 * k, 1 + 0.1 * k),
            gradient=(rng.uniform(-0.12, 0.12) * k, rng.uniform(-0.12, 0.12) * k),
            tint=(rng.uniform(0.95, 1.05), rng.uniform(0.95, 1.05), rng.uniform(0.95, 1.05)),
            glare=glare,
            blur=rng.uniform(0.0, 0.8 * k),
            corners=tuple(rng.uniform(-0.025, 0.025) * k for _ in range(8)),
            noise=rng.uniform(1.0, 4.0 * k),
            jpeg=rng.randint(int(92 - 20 * k), 95),
            zoom=rng.uniform(0.85, 1.15),
            seed=seed,
        )

    def homography(self, width: int, height: int) -> Matrix:
        """Clean-image pixels → photo pixels (3×3), for an image of this size."""
        src = np.array([[0, 0], [width, 0], [width, height], [0, height]], dtype=float)
        offsets = np.array(self.corners, dtype=float).reshape(4, 2) * [width, height]
        return homography(src, src + offsets)

    def photograph(self, clean: Image.Image, frame: int = 0) -> Image.Image:
        """The photo this camera takes of ``clean`` (``frame`` seeds the sensor noise)."""
        image = clean.convert("RGB")
        if self.level == "clean":
            return image
        width, height = image.size
        inverse = np.linalg.inv(self.homography(width, height))
        inverse /= inverse[2, 2]
        coefficients = tuple(float(v) for v in inverse.ravel()[:8])
        image = image.transform((width, height), Image.Transform.PERSPECTIVE, coefficients,
                                Image.Resampling.BILINEAR, fillcolor=(70, 68, 64))  # fmt: skip
        if self.blur > 0.05:
            image = image.filter(ImageFilter.GaussianBlur(self.blur))
        gain, glow = _light_maps(self, width, height)
        pixels = np.asarray(image, dtype=np.float32)
        pixels *= gain
        pixels += glow
        pixels += _noise(self, frame, height, width)
        np.clip(pixels, 0, 255, out=pixels)
        image = Image.fromarray(pixels.astype(np.uint8))
        return _jpeg(image, self.jpeg)

    def photograph_region(self, photo: Image.Image, crop: Image.Image,
                          region: tuple[int, int, int, int], clean_size: tuple[int, int],
                          frame: int) -> Image.Image:  # fmt: skip
        """``photo`` (an earlier photo of the same clean image) with the clean ``region``
        replaced by ``crop`` and photographed again: warp, blur, light, new noise, JPEG."""
        width, height = clean_size
        matrix = self.homography(width, height)
        rx0, ry0, rx1, ry1 = region
        corners = apply(matrix, np.array([[rx0, ry0], [rx1, ry0], [rx1, ry1], [rx0, ry1]]))
        px0 = max(0, int(np.floor(corners[:, 0].min())))
        py0 = max(0, int(np.floor(corners[:, 1].min())))
        px1 = min(photo.size[0], int(np.ceil(corners[:, 0].max())))
        py1 = min(photo.size[1], int(np.ceil(corners[:, 1].max())))
        if px1 - px0 < 4 or py1 - py0 < 4:
            return photo.copy()
        shift_in = np.array([[1, 0, rx0], [0, 1, ry0], [0, 0, 1]], dtype=float)
        shift_out = np.array([[1, 0, -px0], [0, 1, -py0], [0, 0, 1]], dtype=float)
        local = shift_out @ matrix @ shift_in
        inverse = np.linalg.inv(local)
        inverse /= inverse[2, 2]
        coefficients = tuple(float(v) for v in inverse.ravel()[:8])
        size = (px1 - px0, py1 - py0)
        patch = crop.convert("RGB").transform(size, Image.Transform.PERSPECTIVE, coefficients,
                                              Image.Resampling.BILINEAR)  # fmt: skip
        mask = Image.new("L", crop.size, 255).transform(
            size, Image.Transform.PERSPECTIVE, coefficients, Image.Resampling.NEAREST
        )
        if self.blur > 0.05:
            patch = patch.filter(ImageFilter.GaussianBlur(self.blur))
        gain, glow = _light_maps(self, width, height)
        pixels = np.asarray(patch, dtype=np.float32)
        pixels *= gain[py0:py1, px0:px1]
        if glow.shape[0] > 1:
            pixels += glow[py0:py1, px0:px1]
        pixels += _noise(self, frame, py1 - py0, px1 - px0, (py0, px0))
        np.clip(pixels, 0, 255, out=pixels)
        patch = Image.fromarray(pixels.astype(np.uint8))
        patch = _jpeg(patch, self.jpeg)
        margin = max(2, int(2 * self.blur) + 2)
        mask = mask.crop((0, 0, size[0], size[1])).point(lambda v: 255 if v > 250 else 0)
        inner = mask.filter(ImageFilter.MinFilter(2 * margin + 1))
        result = photo.copy()
        result.paste(patch, (px0, py0), inner)
        return result


@lru_cache(maxsize=8)
def _light_maps(camera: Camera, width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """The camera's gain per pixel and channel (lighting, tint) and its additive glare."""
    gx, gy = camera.gradient
    xs = np.linspace(-0.5, 0.5, width, dtype=np.float32)
    ys = np.linspace(-0.5, 0.5, height, dtype=np.float32)
    light = camera.gain * (1.0 + gx * xs[None, :] + gy * ys[:, None])
    gain = light[..., None] * np.array(camera.tint, dtype=np.float32)
    glow = np.zeros((1, 1, 1), dtype=np.float32)
    if camera.glare is not None:
        cx, cy, size, strength = camera.glare
        radius = size * max(width, height)
        gxs = np.exp(-((np.arange(width, dtype=np.float32) - cx * width) ** 2) / (2 * radius**2))
        gys = np.exp(-((np.arange(height, dtype=np.float32) - cy * height) ** 2) / (2 * radius**2))
        glow = (255.0 * strength * np.outer(gys, gxs))[..., None].astype(np.float32)
    return gain.astype(np.float32), glow


_TILE = 509  # a prime, so that shifted tiles do not line up with a panel's regular grids


@lru_cache(maxsize=4)
def _noise_tile(seed: int, sigma: float) -> np.ndarray:
    rng = np.random.default_rng([seed, 11])
    return rng.standard_normal((_TILE, _TILE, 3), dtype=np.float32) * np.float32(sigma)


def _noise(camera: Camera, frame: int, height: int, width: int,
           origin: tuple[int, int] = (0, 0)) -> np.ndarray:  # fmt: skip
    """Sensor noise for one frame: a seeded noise tile, shifted per frame, covering the image.
    ``origin`` (row, column) gives a region's noise: the same pixels as the whole frame's."""
    tile = _noise_tile(camera.seed, camera.noise)
    rng = np.random.default_rng([camera.seed, frame, 7])
    dy, dx = (int(v) for v in rng.integers(0, _TILE, 2))
    rows = (np.arange(height) + dy + origin[0]) % _TILE
    columns = (np.arange(width) + dx + origin[1]) % _TILE
    return tile[rows[:, None], columns[None, :]]


def homography(src: np.ndarray, dst: np.ndarray) -> Matrix:
    """The 3×3 homography taking the four points ``src`` to ``dst``."""
    rows = []
    for (x, y), (u, v) in zip(src, dst, strict=True):
        rows.append([x, y, 1, 0, 0, 0, -u * x, -u * y, -u])
        rows.append([0, 0, 0, x, y, 1, -v * x, -v * y, -v])
    _, _, vt = np.linalg.svd(np.array(rows, dtype=float))
    h = vt[-1].reshape(3, 3)
    return h / h[2, 2]


def apply(matrix: Matrix, points: np.ndarray) -> np.ndarray:
    """``points`` (N×2) mapped by the homography ``matrix``."""
    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    ones = np.ones((len(pts), 1))
    mapped = np.hstack([pts, ones]) @ matrix.T
    return mapped[:, :2] / mapped[:, 2:3]


def _jpeg(image: Image.Image, quality: int | None) -> Image.Image:
    """``image`` after a JPEG round trip at ``quality`` (None: as it is): a camera's artefacts."""
    if quality is None:
        return image
    buffer = io.BytesIO()
    image.save(buffer, format="JPEG", quality=quality)
    buffer.seek(0)
    return Image.open(buffer).convert("RGB")
