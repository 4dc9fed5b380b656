"""Grounding from a photo with the offline OCR model (the slowest vision tests: a few s)."""

from __future__ import annotations

import numpy as np
import pytest

from apbot.bench.suite import load_suite
from apbot.vision.ground import ground
from apbot.vision.render import PanelScene
from apbot.vision.score import score_grounding


def test_a_clean_keypad_panel_grounds_its_actions() -> None:
    appliance = load_suite().get("microwave_1")
    photo = PanelScene.of(appliance).photograph("", ())
    found = ground(np.asarray(photo.image), list(appliance.model.actions))
    tally, wrong = score_grounding(found, appliance.model, appliance.layout, photo)
    assert tally.precision == 1.0, wrong
    assert tally.recall >= 0.9, wrong
    assert found.window is not None  # the display was located too


def test_no_photo_or_a_blank_one_grounds_nothing_and_says_why() -> None:
    actions = ["press_power", "hold_lock"]
    empty = ground(np.zeros((0, 0, 3), np.uint8), actions)
    assert empty.actions == {} and set(empty.ungrounded) == set(actions)
    assert ground(None, actions).ungrounded["press_power"] == "no usable panel photo"
    blank = ground(np.full((300, 400, 3), 200, np.uint8), actions)
    assert blank.actions == {}
    assert "no label" in blank.ungrounded["press_power"]


@pytest.mark.parametrize("name", ["wait_5s"])
def test_waits_are_not_grounded(name: str) -> None:
    found = ground(np.full((100, 100, 3), 90, np.uint8), [name])
    assert found.ungrounded[name] == "a wait touches no control"


def test_a_panel_of_blank_keys_grounds_nothing_by_name() -> None:
    from PIL import Image, ImageDraw

    image = Image.new("RGB", (640, 360), (60, 60, 64))
    draw = ImageDraw.Draw(image)
    for i in range(4):
        draw.rounded_rectangle((40 + 150 * i, 200, 160 + 150 * i, 260), 12, fill=(110, 110, 116))
    draw.ellipse((260, 40, 380, 160), fill=(120, 120, 120), outline=(20, 20, 20), width=4)
    found = ground(np.asarray(image), ["press_menu", "press_start"])
    assert found.actions == {}
    assert all("no label" in why for why in found.ungrounded.values())


@pytest.mark.parametrize(
    "appliance",
    [
        "blender_1",  # an I / O switch legend the text detector missed
        "coffee_machine_2",  # HOT WATER and STRENGTH read as one line
        "washing_machine_5",  # 'spin' printed round the programme dial, the spin dial 'RPM'
    ],
)
def test_the_panels_image_mode_failed_on_ground_fully(appliance: str) -> None:
    from apbot.vision.environment import PanelEnvironment
    from apbot.vision.mode import camera_for

    model = load_suite().get(appliance)
    photo = PanelEnvironment(model, camera_for(appliance, 0), PanelScene.of(model)).reset()
    found = ground(np.asarray(photo.image), list(model.model.actions))
    tally, wrong = score_grounding(found, model.model, model.layout, photo)
    assert tally.precision == 1.0 and tally.recall == 1.0, wrong
