"""Labels from detections: symbols beside words, glyphs of several strokes."""

from __future__ import annotations

import numpy as np
from PIL import Image, ImageDraw

from apbot.vision.labels import Label, _edge_symbols, _join_line_symbols
from apbot.vision.panel_art import draw_text


def test_a_symbol_beside_a_word_joins_its_label_and_one_far_away_does_not() -> None:
    word = Label("TIME", (100.0, 100.0, 180.0, 130.0), (90.0, 90.0, 240.0, 140.0))
    beside = Label("−", (195.0, 112.0, 215.0, 117.0), None, ["−"])
    alone = Label("+", (400.0, 110.0, 420.0, 130.0), None, ["+"])
    kept = _join_line_symbols([word, beside, alone])
    assert kept == [word, alone]
    assert word.symbols == ["−"] and word.box[2] == 215.0


def test_a_lone_letter_takes_no_symbol_from_its_neighbour() -> None:
    letter = Label("X", (100.0, 100.0, 130.0, 130.0))
    sign = Label("▶", (140.0, 100.0, 170.0, 130.0), None, ["▶"])
    assert _join_line_symbols([letter, sign]) == [letter, sign]


def test_a_power_sign_above_a_word_on_a_key_is_found() -> None:
    image = Image.new("RGB", (300, 160), (200, 200, 200))
    draw = ImageDraw.Draw(image)
    draw_text(draw, (150, 50), "⏻", 36, (20, 20, 20))
    draw_text(draw, (150, 110), "START", 36, (20, 20, 20))
    label = Label("START", (95.0, 92.0, 205.0, 128.0), (10.0, 10.0, 290.0, 150.0))
    assert "⏻" in _edge_symbols(np.asarray(image), label)
    word_only = Label("START", (95.0, 92.0, 205.0, 128.0), (10.0, 80.0, 290.0, 150.0))
    assert "⏻" not in _edge_symbols(np.asarray(image), word_only)
