"""A stepping pair that also serves settings other keys open keeps a setting of its own when
the manual says what it moves alone (roles_raised.set_alone / alone_range), each on a small
manual of our own."""

from __future__ import annotations

from apbot.read import read_manual

# a boiler: CLOCK and TIMER open their times for the arrows; alone the arrows set the days away
BOILER = """# Boiler

## Keys

| Key | What it does |
|---|---|
| MODE | Next mode: HOME, AWAY. |
| CLOCK | Hold 3 seconds to set the clock. |
| TIMER | Switches the morning timer on or off. |
| ▲ ▼ | Change the value being set. |

## Setting the clock

1. Hold CLOCK for 3 seconds.
2. Press ▲ or ▼ to set the hours, one hour per press.

## Morning timer

1. Press TIMER. READY is shown.
2. Press ▲ or ▼ to move the ready time by 30 minutes per press.

## Away

1. Press MODE until AWAY is shown.
2. Press ▲ or ▼.
The display shows DAYS and how many days you are away.
Each press changes the count by one day; the range is 2 to 30 days.

▲ / ▼ only set the days while no other setting (clock, timer) is open.
"""
BOILER_ACTIONS = ["press_mode", "hold_clock", "press_timer", "press_up", "press_down"]


# an exercise bike: after TIME the arrows set the time; alone they set the resistance
BIKE = """# Bike console

## Keys

| Key | What it does |
|---|---|
| TIME | Set the workout time with ▲ / ▼ (5 to 60 minutes). |
| ▲ | higher |
| ▼ | lower |

## Resistance

Without pressing any other key first, ▲ and ▼ change the resistance level: 1 to 12.
"""
BIKE_ACTIONS = ["press_time", "press_up", "press_down"]


def _alone(model: object, action: str) -> set[str]:
    """The variables ``action`` sets as the first step of a feature (pressed alone)."""
    feats = model.features  # type: ignore[attr-defined]
    return {steps[0].variable for steps in feats.values() if action in steps[0].actions}


def test_the_pair_alone_sets_the_days_it_sets_while_no_other_setting_is_open() -> None:
    model = read_manual(BOILER, BOILER_ACTIONS).model
    assert "days" in _alone(model, "press_up")
    spec = model.variables["days"]
    assert [list(r) for r in spec.ranges] == [[2, 30, 1]]
    assert spec.unit == "d"


def test_without_any_other_key_the_pair_sets_the_level_its_sentence_names() -> None:
    model = read_manual(BIKE, BIKE_ACTIONS).model
    assert "level" in _alone(model, "press_up")


def test_a_range_in_another_quantity_s_unit_beside_the_days_is_not_their_range() -> None:
    text = BOILER.replace(
        "The display shows DAYS and how many days you are away.",
        "The display shows DAYS and how many days you are away.\n"
        "On away days the water is held at 5 to 10 °C against frost.",
    )
    spec = read_manual(text, BOILER_ACTIONS).model.variables["days"]
    assert [list(r) for r in spec.ranges] == [[2, 30, 1]]
    assert spec.unit == "d"
