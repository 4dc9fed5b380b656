"""values33: a key's values guessed (on/off) where the manual states them."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual


def _values(text: str, actions: list[str], variable: str) -> list[str] | None:
    """The values read for one variable (None for a number or a time)."""
    model: dict[str, Any] = read_manual(text, actions).model.model_dump(mode="json")
    return model["variables"][variable].get("values")


# a ceiling fan remote whose PATTERN key has a table of presses in its own section (taken from
# values32's branch, a739e5ce): the column of words is the key's list
FAN = """# Zephyr CF-2 ceiling fan remote

## Keys

POWER switches the fan on and off. PATTERN changes how the air moves. HOURS sets the switch-off.

## Air pattern — PATTERN

PATTERN picks how the air moves. Every press goes one row further; after the last row the fan
is back at the first.

| Press | Light | Air           |
|-------|-------|---------------|
| —     | ○     | steady breeze |
| 1st   | ◐     | gentle gusts  |
| 2nd   | ●     | strong gusts  |
| 3rd   | ○     | back to steady|

## Switch-off — HOURS

| Press | Hours |
|-------|-------|
| 1     | 2     |
| 2     | 4     |
"""
FAN_KEYS = ["press_power", "press_pattern", "press_hours"]


def test_a_press_count_table_in_the_keys_section_lists_its_choices() -> None:
    # before: PATTERN was guessed an on/off of its own
    assert _values(FAN, FAN_KEYS, "pattern") == ["steady breeze", "gentle gusts", "strong gusts"]


def test_a_press_count_table_of_figures_gives_no_names() -> None:
    from apbot.read.pressed_names import pressed_names
    from apbot.read.text import parse_manual

    units = parse_manual(FAN).units
    assert pressed_names(units, "hours", "HOURS") is None  # figures: an amount, read elsewhere
    assert pressed_names(units, "lamp", "LAMP") is None  # no section names the key


# a foot spa: the BUBBLES key steps a cycle that is a part of the HEAT key's cycle
SPA = """# Aquella FS-3 foot spa

## Controls

POWER switches the spa on and off. HEAT sets the water heating. BUBBLES starts the bubbles.

## Heating

Press HEAT. Every press goes on to the next level: OFF -> SOFT -> MEDIUM -> STRONG -> OFF.

## Bubbles

1. Press BUBBLES to start the bubbles.
2. To change how strong they are, press BUBBLES again while they run:
   SOFT -> MEDIUM -> STRONG -> SOFT.
"""
SPA_KEYS = ["press_power", "press_heat", "press_bubbles"]


def test_a_cycle_stated_for_the_key_alone_stays_its_list() -> None:
    # before: dropped as a part of HEAT's list, BUBBLES was guessed an on/off of its own
    assert _values(SPA, SPA_KEYS, "bubbles") == ["soft", "medium", "strong"]
    assert _values(SPA, SPA_KEYS, "heat") == ["off", "soft", "medium", "strong"]


def test_a_part_of_another_keys_list_without_a_cycle_is_still_dropped() -> None:
    # names listed near the key, not stepped round: no list of the key's own
    text = SPA.replace(
        "while they run:\n   SOFT -> MEDIUM -> STRONG -> SOFT.",
        "while they run (SOFT, MEDIUM and STRONG heating allow it).",
    )
    assert _values(text, SPA_KEYS, "bubbles") != ["soft", "medium", "strong"]
