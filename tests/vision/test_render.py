"""Rendering: deterministic, seeded variations, every bundled panel draws."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from apbot.bench.suite import load_suite
from apbot.vision.photo import Camera
from apbot.vision.render import PanelScene, render_state


@pytest.fixture(scope="module")
def suite():  # type: ignore[no-untyped-def]
    return load_suite()


def test_same_seed_same_photo_other_seed_other_photo(suite) -> None:  # type: ignore[no-untyped-def]
    scene = PanelScene.of(suite.get("microwave_1"))
    a = np.asarray(scene.photograph("PL10", ("COOK",), Camera.sample(3, "mild"), 1).image)
    b = np.asarray(scene.photograph("PL10", ("COOK",), Camera.sample(3, "mild"), 1).image)
    c = np.asarray(scene.photograph("PL10", ("COOK",), Camera.sample(4, "mild"), 1).image)
    assert np.array_equal(a, b)
    fresh = PanelScene.of(suite.get("microwave_1"))
    d = np.asarray(fresh.photograph("PL10", ("COOK",), Camera.sample(3, "mild"), 1).image)
    assert np.array_equal(a, d)  # what the scene showed before does not change a photo
    assert a.shape != c.shape or not np.array_equal(a, c)


def test_layout_points_map_into_the_photo_and_back(suite) -> None:  # type: ignore[no-untyped-def]
    appliance = suite.get("air_fryer_2")
    photo = PanelScene.of(appliance).photograph("", (), Camera.sample(9, "strong"))
    box = appliance.layout.controls[0].box
    x0, y0, x1, y1 = photo.photo_box(box)
    lx, ly = photo.layout_point((x0 + x1) / 2, (y0 + y1) / 2)
    assert box[0] <= lx <= box[2] and box[1] <= ly <= box[3]


def test_every_bundled_panel_has_a_scene(suite) -> None:  # type: ignore[no-untyped-def]
    for appliance in suite.appliances:
        scene = PanelScene.of(appliance)
        assert scene.look.main_columns >= 4
        assert 1.0 <= scene.scale <= 10.0


def test_render_state_reaches_the_state(suite, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    out = tmp_path / "kettle.png"
    text = render_state(suite.get("kettle_1"), {"keep_warm": "on"}, out)
    assert out.stat().st_size > 1000 and "WARM" in text
    with pytest.raises(Exception, match="unknown variable"):
        render_state(suite.get("kettle_1"), {"nonsense": "1"}, out)
