"""The display character sets: distinct dot patterns, seven-segment look-alikes."""

from __future__ import annotations

import numpy as np

from apbot.vision.glyphs import (
    SEGMENTS,
    dot_candidates,
    dot_pattern,
    rom_chars,
    seven_segment_candidates,
    seven_segment_ok,
)


def test_every_rom_character_has_its_own_pattern() -> None:
    seen = {dot_pattern(c).tobytes(): c for c in rom_chars()}
    assert len(seen) == len(rom_chars())


def test_a_clean_pattern_reads_back_as_its_character() -> None:
    for char in "A5:°h🔒":
        best, distance = dot_candidates(dot_pattern(char).astype(np.float32))[0]
        assert (best, distance) == (char, 0.0)


def test_seven_segment_look_alikes_stay_candidates() -> None:
    assert set(seven_segment_candidates(SEGMENTS["5"])) >= {"5", "S"}
    assert set(seven_segment_candidates(SEGMENTS["0"])) >= {"0", "O"}
    assert seven_segment_ok("12:30") and not seven_segment_ok("MENU")
