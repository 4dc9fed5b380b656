"""A pair of keys whose legend says what they raise and lower keeps that quantity as its own
setting (roles_raised), each rule on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual

# a foot spa: the arrow pair raises the bubble strength; TIMER cycles its own list of times
SPA = """# Foot spa

## The keys

| Key | What it does |
|---|---|
| ON/OFF | Switches the spa on or off. |
| ▲ / ▼ | Raise / lower the bubble strength, from 1 to 6. |
| TIMER | Shows and changes the switch-off time. |

## Switch-off time

Each press of TIMER moves to the next time in this order:
10 min > 20 min > 30 min > 45 min > 60 min > 10 min ...
"""
SPA_ACTIONS = ["press_on_off", "press_up", "press_down", "press_timer"]

# a rowing machine console: GOAL picks what counts down, the arrows raise the target number
ROWER = """# Rowing console

## Console keys

| Key | Function |
|---|---|
| PROG | Moves to the next training programme: EASY, STEADY, SPRINT. |
| GOAL | Picks what the workout counts down: time, strokes or metres. |
| UP / DOWN | Increase / decrease the target number on the display. |

Press UP to raise the number or DOWN to lower it.
"""
ROWER_ACTIONS = ["press_prog", "press_goal", "press_up", "press_down"]


def _setter(model: object, action: str) -> set[str]:
    feats = model.features  # type: ignore[attr-defined]
    return {s.variable for steps in feats.values() for s in steps if action in s.actions}


def test_the_pair_keeps_the_quantity_its_legend_raises() -> None:
    model = read_manual(SPA, SPA_ACTIONS).model
    (var,) = _setter(model, "press_up") - {None}
    assert "strength" in var
    assert list(model.variables[var].ranges[0][:2]) == [1, 6]
    # TIMER steps through its own list by itself (no longer the arrows' entry key)
    (timer,) = _setter(model, "press_timer") - {None}
    assert timer != var and "press_up" not in {
        a
        for steps in model.features.values()
        for s in steps
        for a in s.actions
        if s.variable == timer
    }


def test_the_pair_is_named_after_what_it_raises_not_a_nearby_noun() -> None:
    model = read_manual(ROWER, ROWER_ACTIONS).model
    (var,) = _setter(model, "press_up") - {None}
    assert var == "target_number"
    assert model.variables[var].type == "numeric"


# a heated mattress pad: one pair of arrows for the warmth of whichever side SIDE has chosen
PAD = """# Heated mattress pad

## Controller keys

| Key | What it does |
|---|---|
| POWER | Switches the pad on or off. |
| SIDE | Changes between the LEFT side and the RIGHT side. |
| ▲ / ▼ | Raise / lower the warmth of the selected side, from 1 to 5. |
"""
PAD_ACTIONS = ["press_power", "press_side", "press_up", "press_down"]

# a rowing console whose arrows set a target whose range depends on what GOAL picked
ROWER_TABLE = """# Rowing console

## Console keys

| Key | Function |
|---|---|
| GOAL | Picks what the workout counts down: time, strokes or metres. |
| UP / DOWN | Increase / decrease the target number on the display. |

## Choosing the target number

| Lamp | Goal | Range | Step | Value when selected |
|---|---|---|---|---|
| T | time | 2 - 60 minutes | 1 minute | 10 |
| S | strokes | 50 - 2000 strokes | 50 strokes | 500 |
| M | metres | 100 - 10000 m | 100 m | 2000 |
"""
ROWER_TABLE_ACTIONS = ["press_goal", "press_up", "press_down"]


def test_an_amount_of_the_selected_side_is_kept_per_side() -> None:
    model = read_manual(PAD, PAD_ACTIONS).model
    (var,) = _setter(model, "press_up") - {None}
    spec = model.variables[var]
    (side,) = _setter(model, "press_side") - {None}
    assert spec.depends_on == side and spec.remember
    assert set(spec.cases) == {"left", "right"}
    assert all(list(c.ranges[0][:2]) == [1, 5] for c in spec.cases.values())


def test_a_bare_range_column_gives_the_pair_its_range_per_choice() -> None:
    model = read_manual(ROWER_TABLE, ROWER_TABLE_ACTIONS).model
    (var,) = _setter(model, "press_up") - {None}
    spec = model.variables[var]
    assert spec.depends_on is not None
    assert [list(r) for r in spec.cases["strokes"].ranges] == [[50, 2000, 50]]
    assert spec.cases["metres"].initial == 2000


def test_an_arrow_cycle_in_brackets_starts_at_its_first_code() -> None:
    from apbot.read.value_lists import find_list

    found = find_list("MENU | Each touch lights the next menu code (M1 → M2 → … → M5 → M1).")
    assert found is not None and found[0] == ["M1", "M2", "M3", "M4", "M5"]


# a hand mixer: + / − raise the speed alone; after TIMER (whose cell says so) they set the timer
MIXER = """# Hand mixer

## The keys

| Key | What it does |
|---|---|
| POWER | Switches the mixer on or off. |
| − | Lowers the speed (or the timer, see below). |
| + | Raises the speed (or the timer, see below). |
| TIMER | Set the timer with − / +. |

## The timer

1. Touch TIMER. The timer flashes.
2. Touch + or − to change the time from 0:00 to 10:00 in 30-second steps.
"""
MIXER_ACTIONS = ["press_power", "press_minus", "press_plus", "press_timer"]


def test_a_key_set_with_the_pair_shares_it_with_the_pairs_own_quantity() -> None:
    model = read_manual(MIXER, MIXER_ACTIONS).model
    alone = [s for s in model.features.values() if s[0].actions[0] == "press_plus"]
    (speed,) = {steps[0].variable for steps in alone}
    assert speed == "speed"
    after = [s for s in model.features.values() if s[0].actions == ["press_timer"]]
    (steps,) = after
    assert len(steps) == 2 and "press_plus" in steps[1].actions
    assert model.variables[steps[1].variable].type == "time"


# a heated rail: the arrows set the temperature alone; after a held TIMER they set the times
RAIL = """# Heated towel rail

## Keys

| Key | What it does |
|---|---|
| ON/OFF | Switches the rail on or off. |
| ▲ | warmer (or later, while the drying time is being set) |
| ▼ | cooler (or earlier, while the drying time is being set) |
| TIMER | hold 3 s: set the drying time |

## Temperature

The temperature of the rail is set with ▲ and ▼ – no other key is needed. It goes from
30 to 65 °C.

## Drying time

1. Hold TIMER for 3 seconds. The start time flashes.
2. Set the start time with ▲ (later) and ▼ (earlier). Each touch moves the time by 30 minutes.
3. Wait 5 seconds: the time is stored.
"""
RAIL_ACTIONS = ["press_on_off", "press_up", "press_down", "hold_timer"]


def test_the_pair_sets_alone_what_its_no_other_key_sentence_names() -> None:
    model = read_manual(RAIL, RAIL_ACTIONS).model
    alone = {s[0].variable for s in model.features.values() if s[0].actions[0] == "press_up"}
    assert "temperature" in alone


# a twin-zone cellar whose table writes each range with its unit at both ends
CELLAR = """# Wine cellar

## Keys

| Key | Use |
|---|---|
| ZONE | Changes between the TOP zone and the BOTTOM zone. |
| ▲ / ▼ | Raise / lower the temperature of the selected zone. |

## Setting the temperature

| Zone | Range | Step |
|---|---|---|
| TOP | 6 °C to 11 °C | 1 °C |
| BOTTOM | 11 °C to 17 °C | 1 °C |

Install the cellar where the room stays between 10 and 32 °C.
"""
CELLAR_ACTIONS = ["press_zone", "press_up", "press_down"]


def test_a_range_cell_with_the_unit_at_both_ends_is_the_zones_range() -> None:
    model = read_manual(CELLAR, CELLAR_ACTIONS).model
    (var,) = _setter(model, "press_up") - {None}
    spec = model.variables[var]
    assert spec.depends_on is not None and spec.remember
    assert [list(r) for r in spec.cases["top"].ranges] == [[6, 11, 1]]
    assert [list(r) for r in spec.cases["bottom"].ranges] == [[11, 17, 1]]
