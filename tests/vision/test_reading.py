"""Reading displays from photos: exact on clean ones, clear results on bad input."""

from __future__ import annotations

import numpy as np
import pytest

from apbot.bench.suite import load_suite
from apbot.vision.photo import Camera
from apbot.vision.reading import read_display
from apbot.vision.render import PanelScene


@pytest.fixture(scope="module")
def suite():  # type: ignore[no-untyped-def]
    return load_suite()


@pytest.mark.parametrize(
    ("appliance", "main", "lamps"),
    [
        ("microwave_1", "PL10", ("COOK",)),
        ("bread_maker_4", "READY IN 1 h", ("SIZE 2 lb", "CRUST 2", "ADD-IN", "STOP")),
        ("air_conditioner_1", "", ("LIGHT OFF",)),
        ("kettle_1", "40°C", ()),
        ("slow_cooker_1", "", ()),
    ],
)
def test_clean_dot_matrix_displays_read_exactly(suite, appliance, main, lamps) -> None:  # type: ignore[no-untyped-def]
    photo = PanelScene.of(suite.get(appliance)).photograph(main, lamps)
    expected = "  ".join(p for p in (main, *lamps) if p)
    assert read_display(photo.image).text == expected


def test_seven_segments_keep_look_alikes_as_alternatives(suite) -> None:  # type: ignore[no-untyped-def]
    scene = PanelScene.of(suite.get("coffee_machine_5"), style="seg")
    assert scene.look.style == "seg"
    reading = read_display(scene.photograph("POUR", ()).image)
    assert "POUR" in reading.texts


def test_a_mild_photo_reads(suite) -> None:  # type: ignore[no-untyped-def]
    photo = PanelScene.of(suite.get("microwave_1")).photograph(
        "dEF 08:36", (), Camera.sample(11, "mild")
    )
    assert read_display(photo.image).text == "dEF 08:36"


def test_bad_images_give_clear_results() -> None:
    assert read_display(np.zeros((0, 0, 3), np.uint8)).problem == "not a usable image"
    assert read_display("not an image").problem == "not a usable image"
    flat = np.full((200, 300, 3), 128, np.uint8)
    assert read_display(flat).problem == "no display window found"


def test_the_window_is_the_display_not_a_dark_stretch_of_panel(suite) -> None:  # type: ignore[no-untyped-def]
    # under this camera's uneven light a dark part of bread_maker_4's panel looked like a
    # larger window than the display itself
    import zlib

    appliance = suite.get("bread_maker_4")
    camera = Camera.sample(zlib.crc32(b"display/bread_maker_4/dot"), "mild")
    photo = PanelScene.of(appliance, style="dot").photograph("CRUST 3", ("STOP",), camera, 1)
    reading = read_display(photo.image)
    assert reading.text == "CRUST 3  STOP"


@pytest.mark.parametrize(("appliance", "main"), [("rice_cooker_4", "DELAY 0:00"),
                                                 ("kettle_1", "HEATING 40°C")])  # fmt: skip
def test_seven_segment_words_read_as_letters_and_numbers_as_digits(suite, appliance, main) -> None:  # type: ignore[no-untyped-def]
    # 0/O/D, 1/I and 5/S light the same segments: the word's shape ranks DELAY before 0ELAY
    scene = PanelScene.of(suite.get(appliance), style="seg", force=True)
    assert scene.look.style == "seg"
    assert read_display(scene.photograph(main, ()).image).text == main


def test_the_word_shape_cost() -> None:
    from apbot.vision.decode import WORD_SWITCH, _switch

    assert _switch("DEL", "A") == 0.0 and _switch("0:0", "0") == 0.0
    assert _switch("", "0") == 0.0 and _switch("HEAT ", "1") == 0.0
    assert _switch("HEAT", "1") == WORD_SWITCH and _switch("1", "E") == WORD_SWITCH
    assert 0 < _switch("HEATIN", "g") < WORD_SWITCH


def _camera(appliance: str, style: str) -> Camera:
    import zlib

    return Camera.sample(zlib.crc32(f"display/{appliance}/{style}".encode()), "mild")


@pytest.mark.parametrize("appliance", ["air_fryer_4", "coffee_machine_2", "slow_cooker_2"])
def test_a_blank_seven_segment_display_reads_as_nothing(suite, appliance) -> None:  # type: ignore[no-untyped-def]
    # the faint unlit segments and lamp dots under uneven light were read as noise
    scene = PanelScene.of(suite.get(appliance), style="seg", force=True)
    photo = scene.photograph("", (), _camera(appliance, "seg"), frame=1)
    assert read_display(photo.image).text == ""


def test_status_lamps_under_a_seven_segment_row_are_read_as_dots(suite) -> None:  # type: ignore[no-untyped-def]
    # the small dot cells fitted a segment grid a few hundredths better: "HFFF HAPH"
    scene = PanelScene.of(suite.get("kettle_4"), style="seg", force=True)
    photo = scene.photograph("100°C", ("KEEP WARM 0",), _camera("kettle_4", "seg"), frame=1)
    assert read_display(photo.image).text == "100°C  KEEP WARM 0"


def test_a_kept_grid_is_fitted_again_when_a_longer_text_draws_more_cells(suite) -> None:  # type: ignore[no-untyped-def]
    # dishwasher_4 centres its text: the grid kept from "heavy" covered five of the seven
    # cells of "DRY+ & UV", read "RY+ U"
    from apbot.sim.compiled import compiled_model
    from apbot.sim.simulator import Simulator
    from apbot.vision.display_art import visible
    from apbot.vision.mode import camera_for
    from apbot.vision.reading import DisplayCamera

    appliance = suite.get("dishwasher_4")
    scene = PanelScene.of(appliance)
    sim = Simulator(compiled_model(appliance.model))
    sim.reset()
    camera = DisplayCamera()  # keeps each row's grid between photos
    presses = ["press_power", "press_program", "press_option", "press_option", "press_option"]
    for frame, action in enumerate(presses, start=1):
        sim.step(action)
        seen = sim.observe()
        photo = scene.photograph(seen.display, seen.lamps, camera_for(appliance.id), frame=frame)
        assert camera.read(photo.image).text == visible(seen.text)
