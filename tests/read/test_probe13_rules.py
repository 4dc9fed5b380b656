"""Rules found by probing the reader with short manuals written unlike our data (probe13)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.actions import action_info

BOTTLE_WARMER = """# Tepida Bottle Warmer

## Keys
- POWER: on and off.
- TIME + / TIME −: the warming time.

Warming time: adjustable from 2 to 20 minutes in steps of 1 minute.
The default is 6 minutes.
"""


def test_number_keys_spelled_with_their_kind_are_digits() -> None:
    for name in ("key_4", "press_key_4", "digit_4", "press_number_4_button", "4_key"):
        info = action_info(name)
        assert info.digit == 4 and info.controls == ("key_4",), name
    assert action_info("press_menu1").digit is None
    assert action_info("wait_10s").digit is None
