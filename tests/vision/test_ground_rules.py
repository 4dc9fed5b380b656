"""Grounding rules on drawn glyphs and hand-made labels (fast: no OCR)."""

from __future__ import annotations

import numpy as np
from PIL import Image, ImageDraw

from apbot.vision.cv import cv2
from apbot.vision.detect import _rim_support
from apbot.vision.ground import _combination, _eliminate
from apbot.vision.labels import Label, _edge_symbols, _misread_symbols
from apbot.vision.panel_art import draw_text


def _key(text: str, size: int = 40) -> tuple[np.ndarray, tuple[float, float, float, float]]:
    """A dark key with ``text`` printed in white; the key's box."""
    image = Image.new("RGB", (240, 140), (40, 40, 44))
    draw = ImageDraw.Draw(image)
    draw.rounded_rectangle((10, 10, 230, 130), 12, fill=(70, 70, 76))
    draw_text(draw, (120, 70), text, size, (235, 235, 235))
    return np.asarray(image), (10.0, 10.0, 230.0, 130.0)


def test_a_pictogram_read_as_a_character_also_means_its_symbol() -> None:
    image, key = _key("💡", 60)
    label = Label("9", (95.0, 40.0, 145.0, 100.0), key)  # what OCR made of the bulb
    _misread_symbols(image, [label])
    assert label.symbols == ["💡"] and label.text == "9"


def test_a_real_letter_is_not_taken_for_a_symbol() -> None:
    image, key = _key("P", 60)
    label = Label("P", (100.0, 40.0, 140.0, 100.0), key)
    _misread_symbols(image, [label])
    assert label.symbols == []


def test_a_hollow_arrow_beside_a_unit_is_found() -> None:
    image, key = _key("h ▷")
    label = Label("h", (60.0, 45.0, 110.0, 95.0), key)
    assert "▷" in _edge_symbols(image, label)
    image, key = _key("◁ h")
    assert "◁" in _edge_symbols(image, Label("h", (130.0, 45.0, 180.0, 95.0), key))


def test_the_last_unmatched_name_takes_the_last_unclaimed_key() -> None:
    keys = {("power",): False, ("hot",): False, ("mode",): True}
    labels = [
        Label("ON", (10, 10, 40, 30), (0, 0, 50, 40)),
        Label("65°", (110, 10, 140, 30), (100, 0, 150, 40)),
        Label("MODE", (210, 50, 260, 70)),  # a dial's name: turn keys are not eliminated
    ]
    chosen = {("power",): (0, 0.9)}
    taken = {0}
    _eliminate(keys, labels, chosen, taken, [(0, 0, 50, 40)], None)
    assert chosen[("hot",)] == (1, 0.6) and 1 in taken


def test_no_elimination_when_two_names_or_two_keys_are_left() -> None:
    labels = [Label("A", (10, 10, 40, 30), (0, 0, 50, 40)), Label("B", (110, 10, 140, 30),
              (100, 0, 150, 40))]  # fmt: skip
    chosen: dict[tuple[str, ...], tuple[int, float]] = {}
    _eliminate({("x",): False}, labels, chosen, set(), [], None)
    assert chosen == {}  # one name, two free keys: no guess
    _eliminate({("x",): False, ("y",): False}, labels[:1], chosen, set(), [], None)
    assert chosen == {}  # two names, one free key: no guess


def test_a_two_key_hold_name_is_not_a_key_of_its_own() -> None:
    keys = [("prev",), ("next",), ("prev", "next")]
    assert _combination(("prev", "next"), keys)
    assert not _combination(("next",), keys)


def test_a_drawn_circle_has_its_rim_on_edges_and_a_guess_does_not() -> None:
    canvas = np.zeros((200, 200), np.uint8)
    cv2.circle(canvas, (100, 100), 60, 255, 2)
    edges = cv2.dilate(cv2.Canny(canvas, 30, 90), np.ones((3, 3), np.uint8))
    assert _rim_support(edges, 100, 100, 60) > 0.9
    assert _rim_support(edges, 100, 100, 30) < 0.1


def test_a_two_line_label_is_also_one_label() -> None:
    from apbot.vision.labels import _stacked

    dry, time = Label("DRY", (765, 426, 868, 473)), Label("TIME", (754, 474, 875, 525))
    mode = Label("MODE", (478, 451, 602, 496))  # beside, not under
    found = _stacked([dry, time, mode])
    assert [lb.text for lb in found] == ["DRY TIME"]
    assert found[0].box == (754, 426, 875, 525)


def test_a_minus_bar_beside_a_digit_on_a_key() -> None:
    image, key = _key("− 1")
    found = _edge_symbols(image, Label("1", (125.0, 45.0, 160.0, 95.0), key))
    assert "−" in found
    image, key = _key("ADD-IN", 30)  # a hyphen inside a word is no minus key
    assert "−" not in _edge_symbols(image, Label("ADD-IN", (60.0, 55.0, 180.0, 85.0), key))


def test_an_icon_above_a_word_is_not_another_labels_key() -> None:
    from apbot.vision.detect import Candidate, Detection
    from apbot.vision.ground import _target

    word = Label("QUICK MIN", (330.0, 1346.0, 614.0, 1404.0))
    lock_key = (363.0, 1162.0, 580.0, 1291.0)  # key 0 above it, with a label of its own
    detection = Detection([], [Candidate(lock_key, "shape", 0.9)], (1000, 1600))
    assert _target(word, detection, None, False) != word.box  # alone: taken for its icon
    assert _target(word, detection, None, False, [lock_key]) == word.box
