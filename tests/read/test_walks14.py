"""Walks opened by a short press of one key through several fields (`pressed_walks.py`), the
fields named by a printed field order and valued by display codes (`walk_order.py`)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.walk_order import (
    code_run_field,
    first_case_field,
    glossed_field,
    order_names,
    with_step,
)

# a bike computer (our own words): MENU walks the rider slot, the wheel size, the rider's sex
BIKE = """VELOTA BC-9 bike computer

KEYS
  MENU      Opens the rider settings; moves on to the next item.
  +         Higher value.
  -         Lower value.
  LIGHT     Backlight on / off.

RIDER SETTINGS
  The items always come in this order:

     RIDER (R) -> WHEEL -> GENDER -> stored

  1. Press MENU. The display shows the rider slot, e.g. R1 blinking.
  2. Pick the slot with + or -. R1 -> R2 -> ... -> R4 -> R1.
  3. Press MENU. The display shows the wheel size, e.g. W 26.
  4. Set the wheel with + (+1 cm) or - (-1 cm). Range 30 to 75 cm.
  5. Press MENU. The display shows GEN M.
  6. Choose with + or - (M = man, W = woman).
  7. Press MENU to store.

LIGHT
  Press LIGHT to switch the backlight on or off.
"""
BIKE_ACTIONS = ["press_menu", "press_plus", "press_minus", "press_light"]


def _walk_of(model, opener: str):  # type: ignore[no-untyped-def]
    return [
        steps
        for steps in model.features.values()
        if len(steps) > 2 and [s.actions for s in steps][:1] == [[opener]]
    ]


def test_a_short_press_walks_the_fields_named_by_the_printed_order() -> None:
    model = read_manual(BIKE, BIKE_ACTIONS).model
    walks = _walk_of(model, "press_menu")
    assert len(walks) == 1
    names = [s.variable for s in walks[0] if s.variable]
    assert names == ["rider", "wheel", "gender"]
    assert next(tuple(r) for r in model.variables["rider"].ranges or [])[:2] == (1, 4)
    assert model.variables["wheel"].unit == "cm"
    assert model.variables["gender"].values == ["man", "woman"]
    assert model.variables["gender"].label == "GEN"


def test_field_orders_as_arrows_or_as_what_the_key_moves_through() -> None:
    lines = [
        "  Field order:  hours → minutes → dose → stored",
        "SET moves through: year, month, day and hour.",
        "Press A -> the lamp lights.",
    ]
    assert order_names(lines) == [["hours", "minutes", "dose"], ["year", "month", "day", "hour"]]


def test_a_run_of_display_codes_is_a_number_from_first_to_last() -> None:
    field = code_run_field("", "Use ▲ to go through C1, C2 … C6 (it wraps).", 0)
    assert field is not None and field["label"] == "C"
    low, high = field["evidence"].ranges[0].low, field["evidence"].ranges[0].high
    assert (low, high) == (1, 6)
    assert code_run_field("", "Press A1 or B2 to choose.", 0) is None  # two prefixes, no run


def test_codes_glossed_by_words_are_the_words_shown_as_codes() -> None:
    field = glossed_field("Pick the fan with UP or DOWN (L = low, H = high, A = auto).")
    assert field is not None
    assert field["values"] == ["low", "high", "auto"]
    assert field["show"] == {"low": "L", "high": "H", "auto": "A"}


def test_a_range_told_per_unit_takes_the_first_case() -> None:
    field = first_case_field("Range 30-90 cm with metric units, 12-35 in with imperial.", 0)
    assert field is not None
    assert (field["evidence"].ranges[0].low, field["evidence"].ranges[0].high) == (30, 90)
    assert first_case_field("Range 30-90 cm.", 0) is None


def test_a_presss_step_read_beside_a_hold_of_the_pair() -> None:
    field = code_run_field("", "R1 -> R2 -> ... -> R9", 0)
    assert field is not None
    stepped = with_step(field, "Set it with + (+1 cm) or - (-1 cm); hold for 10 at a time.", 0)
    assert stepped["evidence"].step == (1.0, "")
