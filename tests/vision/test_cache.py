"""The on-disk grounding cache: same photo and names → the stored grounding; damage → again."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from apbot.bench.suite import bundled_suite_dir, load_appliance
from apbot.vision import cache
from apbot.vision.cache import cache_key, cached_ground, from_json, to_json
from apbot.vision.ground import ground
from apbot.vision.photo import Camera
from apbot.vision.render import PanelScene


@pytest.fixture(scope="module")
def photo_and_names() -> tuple[np.ndarray, list[str]]:
    kettle = load_appliance(bundled_suite_dir() / "kettle_1")
    scene = PanelScene.of(kettle)
    photo = scene.photograph("100°C", (), Camera.sample(7, "mild"))
    return np.asarray(photo.image), list(kettle.model.actions)


def _counting(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    calls: list[int] = []

    def counted(image: Any, actions: Any) -> Any:
        calls.append(1)
        return ground(image, actions)

    monkeypatch.setattr(cache, "ground", counted)
    return calls


def test_round_trip(photo_and_names: tuple[np.ndarray, list[str]]) -> None:
    image, names = photo_and_names
    found = ground(image, names)
    again = from_json(to_json(found))
    assert again.actions == found.actions and again.ungrounded == found.ungrounded
    assert again.labels == found.labels and again.size == found.size
    assert found.window is not None and again.window is not None
    assert np.allclose(again.window.corners, found.window.corners)


def test_second_call_reads_the_disk(
    photo_and_names: tuple[np.ndarray, list[str]], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    image, names = photo_and_names
    monkeypatch.setenv("APBOT_CACHE_DIR", str(tmp_path))
    calls = _counting(monkeypatch)
    first = cached_ground(image, names)
    second = cached_ground(image, names)
    assert len(calls) == 1 and second.actions == first.actions
    assert len(list((tmp_path / "grounding").glob("*.json"))) == 1
    other = image.copy()
    other[0, 0] = 255 - other[0, 0]  # another photo: another key
    assert cache_key(other, names) != cache_key(image, names)
    assert cache_key(image, names[:1]) != cache_key(image, names)


def test_damaged_file_is_grounded_again(
    photo_and_names: tuple[np.ndarray, list[str]], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    image, names = photo_and_names
    monkeypatch.setenv("APBOT_CACHE_DIR", str(tmp_path))
    calls = _counting(monkeypatch)
    cached_ground(image, names)
    (path,) = (tmp_path / "grounding").glob("*.json")
    path.write_text('{"format": 1, "actions": [{"action": 3}]}')
    found = cached_ground(image, names)
    assert len(calls) == 2 and set(found.actions) | set(found.ungrounded) == set(names)


def test_off_keeps_nothing(
    photo_and_names: tuple[np.ndarray, list[str]], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    image, names = photo_and_names
    monkeypatch.setenv("APBOT_CACHE_DIR", "off")
    monkeypatch.setenv("HOME", str(tmp_path))
    calls = _counting(monkeypatch)
    cached_ground(image, names)
    cached_ground(image, names)
    assert len(calls) == 2 and not list(tmp_path.rglob("*.json"))
