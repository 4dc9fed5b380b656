"""Groundings kept on disk: the same photo and action names ground the same way every time.

Grounding a panel (OCR, shapes, symbols) takes seconds; a benchmark run grounds every
appliance again in every worker process. The key is the photo's pixels (so the appliance,
its display look and the camera's parameters are all in it), the action names, and the
grounding code's version (a digest of this package's source). A damaged or foreign file is
ignored and the photo grounded again. ``APBOT_CACHE_DIR`` moves the cache (default
``~/.cache/apbot``; ``off`` disables it), the same setting as for read manuals.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
from collections.abc import Sequence
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from apbot.vision.ground import Grounded, Grounding, ground
from apbot.vision.labels import Label
from apbot.vision.locate import Window

CACHE_ENV = "APBOT_CACHE_DIR"
FORMAT = 1


@lru_cache(maxsize=1)
def vision_version() -> str:
    """A digest of the vision package's source (any change may change a grounding)."""
    folder = Path(__file__).resolve().parent
    digest = hashlib.sha256()
    for path in sorted(folder.glob("*.py")):
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def cache_dir() -> Path | None:
    """Where groundings are kept, or None when caching is off."""
    setting = os.environ.get(CACHE_ENV, "").strip()
    if setting.lower() == "off":
        return None
    return Path(setting).expanduser() if setting else Path.home() / ".cache" / "apbot"


def cache_key(image: np.ndarray, actions: Sequence[str]) -> str:
    """The key of one grounding: the photo's pixels, the action names, the code's version."""
    digest = hashlib.sha256()
    digest.update(f"{FORMAT}/{vision_version()}/{image.shape}/{image.dtype}".encode())
    digest.update(np.ascontiguousarray(image).tobytes())
    digest.update(json.dumps(list(actions)).encode())
    return digest.hexdigest()


def cached_ground(image: np.ndarray, actions: Sequence[str]) -> Grounding:
    """:func:`~apbot.vision.ground.ground`, from the disk cache when it holds the answer."""
    folder = cache_dir()
    usable = isinstance(image, np.ndarray) and image.ndim == 3 and image.size > 0
    if folder is None or not usable:
        return ground(image, actions)
    path = folder / "grounding" / f"{cache_key(image, actions)}.json"
    found = load(path)
    if found is not None and set(found.actions) | set(found.ungrounded) == set(actions):
        return found
    result = ground(image, actions)
    store(path, result)
    return result


def to_json(grounding: Grounding) -> dict[str, Any]:
    return {
        "format": FORMAT,
        "actions": [
            {
                "action": g.action,
                "skill": g.skill,
                "boxes": [list(b) for b in g.boxes],
                "label": g.label,
                "score": g.score,
            }
            for g in grounding.actions.values()
        ],
        "ungrounded": grounding.ungrounded,
        "labels": [
            {
                "text": lb.text,
                "box": list(lb.box),
                "control": list(lb.control) if lb.control is not None else None,
                "symbols": lb.symbols,
                "tick": lb.tick,
            }
            for lb in grounding.labels
        ],
        "window": None
        if grounding.window is None
        else {"corners": grounding.window.corners.tolist(), "score": grounding.window.score},
        "size": list(grounding.size),
        "seconds": grounding.seconds,
    }


def _box(value: Any) -> tuple[float, float, float, float]:
    x0, y0, x1, y1 = (float(v) for v in value)
    return (x0, y0, x1, y1)


def from_json(data: dict[str, Any]) -> Grounding:
    """A grounding from :func:`to_json`'s form; raises ``ValueError``/``KeyError``/``TypeError``
    on anything else."""
    if data.get("format") != FORMAT:
        raise ValueError(f"grounding cache format {data.get('format')!r}, expected {FORMAT}")
    actions = {
        str(g["action"]): Grounded(
            str(g["action"]),
            str(g["skill"]),
            [_box(b) for b in g["boxes"]],
            str(g["label"]),
            float(g["score"]),
        )
        for g in data["actions"]
    }
    labels = [
        Label(
            str(lb["text"]),
            _box(lb["box"]),
            None if lb["control"] is None else _box(lb["control"]),
            [str(s) for s in lb["symbols"]],
            bool(lb["tick"]),
        )
        for lb in data["labels"]
    ]
    raw = data["window"]
    window = None
    if raw is not None:
        corners = np.asarray(raw["corners"], dtype=np.float32)
        if corners.shape != (4, 2):
            raise ValueError("a display window needs four corners")
        window = Window(corners, float(raw["score"]))
    width, height = (int(v) for v in data["size"])
    ungrounded = {str(k): str(v) for k, v in dict(data["ungrounded"]).items()}
    return Grounding(actions, ungrounded, labels, window, (width, height), float(data["seconds"]))


def load(path: Path) -> Grounding | None:
    """A cached grounding, or None when missing or damaged."""
    try:
        return from_json(json.loads(path.read_text(encoding="utf-8")))
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return None


def store(path: Path, grounding: Grounding) -> None:
    """Write atomically (workers may ground the same panel at once); a cache that cannot be
    written is no error — the grounding is simply not kept."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        with os.fdopen(handle, "w", encoding="utf-8") as file:
            json.dump(to_json(grounding), file, ensure_ascii=False)
        os.replace(temporary, path)
    except OSError:
        return
