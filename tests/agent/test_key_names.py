"""The agent knows a key it has no belief about by its name, however the panel spells it."""

from __future__ import annotations

import pytest

from apbot.agent.finder_keys import _is_digit, _is_reverse, _planned, opposite_key


@pytest.mark.parametrize(
    ("key", "offered", "opposite"),
    [
        ("press_vol_up", ["press_vol_up", "press_vol_down"], "press_vol_down"),
        (
            "press_vol_up_button",
            ["press_vol_up_button", "press_vol_down_button"],
            "press_vol_down_button",
        ),
        (
            "turn_timer_dial_clockwise",
            ["turn_timer_dial_counterclockwise"],
            "turn_timer_dial_counterclockwise",
        ),
        ("turn_dial_cw", ["turn_dial_ccw", "press_dial"], "turn_dial_ccw"),
        ("press_plus_key", ["press_minus_key"], "press_minus_key"),
        ("press_vol_up_button", ["press_and_hold_vol_down_button"], None),  # a hold walks no step
        ("press_menu_button", ["press_back_button"], None),
    ],
)
def test_the_key_that_walks_the_other_way(
    key: str, offered: list[str], opposite: str | None
) -> None:
    assert opposite_key(key, offered) == opposite


def test_a_key_spelt_with_its_kind_is_known_for_what_it_does() -> None:
    assert _is_digit("press_7_button") and not _is_digit("press_timer_button")
    assert _is_reverse("press_temp_down_button") and _is_reverse("turn_knob_counterclockwise")
    assert not _is_reverse("press_temp_up_button")
    assert _planned("press_and_hold_lock_button").skill == "hold"
    assert _planned("turn_timer_dial_counterclockwise").skill == "turn_ccw"
