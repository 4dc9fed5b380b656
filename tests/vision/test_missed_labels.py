"""Labels the page-wide text detector got wrong: a sparse switch legend it missed, one line
made of two keys' labels, a ring of programme names around a dial (recognition on crops)."""

from __future__ import annotations

import numpy as np
from PIL import Image, ImageDraw

from apbot.vision.detect import Candidate, Detection
from apbot.vision.labels import Label, _mark_ticks, _missed_lines, _split_shared
from apbot.vision.panel_art import draw_text


def test_a_sparse_switch_legend_is_read_and_its_glyphs_are_no_symbols() -> None:
    image = Image.new("RGB", (420, 200), (30, 30, 32))
    draw_text(ImageDraw.Draw(image), (210, 70), "I / O", 44, (235, 235, 225))
    clock = Label("⏲", (228.0, 52.0, 257.0, 88.0), None, ["⏲"])  # the O taken for a clock
    labels = _missed_lines(np.asarray(image), [clock], 40.0, None)
    assert clock not in labels
    assert [lb.text.replace(" ", "") for lb in labels] in (["1/0"], ["I/O"], ["1/O"], ["I/0"])


def test_nothing_is_added_where_the_text_was_already_read() -> None:
    image = Image.new("RGB", (420, 200), (30, 30, 32))
    draw_text(ImageDraw.Draw(image), (210, 70), "I / O", 44, (235, 235, 225))
    read = Label("I/O", (160.0, 50.0, 260.0, 90.0))
    assert _missed_lines(np.asarray(image), [read], 40.0, None) == [read]


def _two_keys_one_line() -> tuple[np.ndarray, Label, list[Candidate]]:
    image = Image.new("RGB", (620, 260), (25, 25, 27))
    draw = ImageDraw.Draw(image)
    keys = []
    for cx in (190.0, 470.0):
        draw.ellipse((cx - 40, 40, cx + 40, 120), outline=(230, 230, 230), width=4)
        keys.append(Candidate((cx - 40, 40.0, cx + 40, 120.0), "circle", 0.9))
    draw_text(draw, (190, 160), "HOT WATER", 30, (235, 235, 225))
    draw_text(draw, (470, 160), "STRENGTH", 30, (235, 235, 225))
    merged = Label("HOT WATER STRENGTH", (100.0, 145.0, 550.0, 185.0))
    return np.asarray(image), merged, keys


def test_one_line_under_two_keys_is_cut_between_them() -> None:
    image, merged, keys = _two_keys_one_line()
    labels = _split_shared(image, [merged], keys, 30.0)
    assert [lb.text for lb in labels] == ["HOT WATER", "STRENGTH"]
    assert 270 < labels[0].box[2] <= labels[1].box[0] < 400


def test_a_line_under_one_key_stays_whole() -> None:
    image, merged, keys = _two_keys_one_line()
    assert _split_shared(image, [merged], keys[:1], 30.0) == [merged]


def test_words_all_round_a_dial_are_its_positions_even_at_full_size() -> None:
    dial = Candidate((100.0, 100.0, 300.0, 300.0), "circle", 0.9)
    size = (20.0, 10.0)
    ring = [
        Label(word, (x - size[0], y - size[1], x + size[0], y + size[1]))
        for word, (x, y) in {"cotton": (90, 270), "baby": (90, 130), "spin": (330, 200)}.items()
    ]
    name = Label("PROGRAM", (160.0, 380.0, 240.0, 400.0))  # under the dial: its name
    _mark_ticks(Detection([], [dial], (400, 420)), [*ring, name])
    assert all(lb.tick for lb in ring) and not name.tick


def test_one_word_beside_a_dial_is_not_taken_for_a_position() -> None:
    dial = Candidate((100.0, 100.0, 300.0, 300.0), "circle", 0.9)
    beside = Label("spin", (310.0, 190.0, 350.0, 210.0))
    _mark_ticks(Detection([], [dial], (400, 420)), [beside])
    assert not beside.tick
