"""Function keys: a row of keys each choosing how the appliance cooks, each opening its own
procedure ("1. Press BAKE. 2. Enter the temperature. 3. Enter the cooking time. 4. Press
START."). Test manuals of our own, in two categories other than the microwave that showed it."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

OVEN = """
# Countertop oven TO-90 — user guide

## The control panel
- **BAKE** — conventional top and bottom heat.
- **FAN** — fan-assisted baking; touch again to switch between FAN 1 and FAN 2 (see the chart).
- **PIZZA** — bottom heat with the fan.
- **WARM** — keeps food warm.
- **0 to 9** — number pads.
- **START** — starts cooking. **CANCEL** — stops and clears.

Touch the function button before you set anything else. Choosing another function button
clears the values you had entered.

## Baking
1. Touch BAKE.
2. Key in the temperature with the number pads (from 100 to 250 °C).
3. Key in the cooking time.
4. Touch START.

## Fan baking
1. Touch FAN. 2. Touch FAN again to select another fan level. 3. Key in the cooking time.
4. Touch START.

| Display | Fan level |
|---|---|
| F-1 | gentle fan |
| F-2 | strong fan |

## Pizza
1. Touch PIZZA. 2. Key in the cooking time. 3. Touch START.

## Keeping warm
Touch WARM, then START: the oven holds 70 °C.
"""
OVEN_ACTIONS = [
    *("press_bake", "press_fan", "press_pizza", "press_warm", "press_start", "press_cancel"),
    *(f"press_{d}" for d in range(10)),
]

COOKER = """
MULTICOOKER MC-5   INSTRUCTIONS

CONTROLS
STEW      Slow stewing.
STEAM     Steaming with the basket.
SOUP      Soups and stocks.
YOGURT    Fermenting milk.
0-9       Number keys.
START     Starts the programme.

Always press one of the cooking function keys first; pressing a different one starts over.

STEWING
1. Press STEW. 2. Enter the cooking time with the number keys. 3. Press START.
STEAMING
1. Press STEAM. 2. Enter the cooking time. 3. Press START.
SOUP
1. Press SOUP. 2. Enter the cooking time. 3. Press START.
YOGURT
Press YOGURT and START. The programme runs for 8 hours.
"""
COOKER_ACTIONS = [
    *("press_stew", "press_steam", "press_soup", "press_yogurt", "press_start"),
    *(f"press_{d}" for d in range(10)),
]


def test_oven_function_buttons_choose_one_function_then_take_their_values() -> None:
    model = read_manual(OVEN, OVEN_ACTIONS).model
    check_model(model)
    name, choice = next(
        (n, v)
        for n, v in model.variables.items()
        if getattr(v, "values", None) and "bake" in v.values
    )
    assert {"bake", "fan", "pizza"} <= set(choice.values)
    bake = model.features["bake"]
    assert getattr(bake[0].effect, "to", None) == "bake"
    temperature = model.variables[bake[1].variable]
    assert temperature.unit == "°C"
    times = {model.features[f][-1].variable for f in ("bake", "fan", "pizza")}
    assert len(times) == 1 and model.variables[times.pop()].type == "time"
    fan = model.features["fan"][0]  # pressed again it steps the fan level, choosing FAN
    assert fan.effect == "next" and fan.set == {name: "fan"}
    assert model.variables[fan.variable].values == ["f-1", "f-2"]


def test_cooker_function_keys_share_the_cooking_time() -> None:
    model = read_manual(COOKER, COOKER_ACTIONS).model
    check_model(model)
    choice = next(
        v for v in model.variables.values() if getattr(v, "values", None) and "stew" in v.values
    )
    assert {"stew", "steam", "soup"} <= set(choice.values)
    times = {model.features[f][-1].variable for f in ("stew", "steam", "soup")}
    assert len(times) == 1


def test_keys_the_manual_never_names_as_one_kind_keep_their_own_settings() -> None:
    text = COOKER.replace(
        "Always press one of the cooking function keys first; pressing a different one starts"
        " over.",
        "",
    )
    model = read_manual(text, COOKER_ACTIONS).model
    assert not any("stew" in (getattr(v, "values", None) or []) for v in model.variables.values())


# a microwave whose CLOCK, KITCHEN TIMER and TIME COOK each take a time and START, with a
# MODE key named "the MODE button": one key so called names no row of keys (review2)
CLOCKED = """CONTROL PANEL

CLOCK sets the time of day. KITCHEN TIMER counts down without cooking. TIME COOK cooks by time.
POWER LEVEL changes the power. The number pads 0-9 enter times. START begins; STOP/CANCEL clears.
Press the MODE button to show the clock in 12 or 24 hours.

SETTING THE CLOCK

1. Press CLOCK.
2. Enter the time of day with the number pads.
3. Press START to confirm.

KITCHEN TIMER

1. Press KITCHEN TIMER.
2. Enter the time to count down (up to 99:99).
3. Press START. The timer counts down and beeps at the end.

COOKING BY TIME

1. Press TIME COOK.
2. Enter the cooking time, up to 99 minutes 99 seconds.
3. Press POWER LEVEL and a number pad 1 to 10 for the power, if you want less than full power.
4. Press START.
"""
CLOCKED_ACTIONS = [
    "press_clock",
    "press_kitchen_timer",
    "press_time_cook",
    "press_power_level",
    "press_mode",
    "press_start",
    "press_stop_cancel",
] + [f"press_{d}" for d in range(10)]


def test_a_key_named_mode_button_makes_no_row_of_function_keys() -> None:
    model = read_manual(CLOCKED, CLOCKED_ACTIONS).model
    assert model.variables["clock"].type == "time"  # the time of day, not a function's value
    assert "kitchen_timer" in model.variables and "time_cook" in model.variables
