"""Tables that count presses, pointers to a table further on, and keypad worked examples."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

STEAMER = """
IMPORTANT SAFETY INSTRUCTIONS
Read all instructions before use. Never operate the steamer with a damaged cord or plug. Keep
the appliance out of the reach of children. Do not immerse the base in water or other liquid.

CONTROL PANEL
- **HEAT** — selects the steam strength.
- **PRESET** — chooses a cooking preset.
- **Number pads 0 to 9** — enter the time.
- **START** — starts.

COOKING BY TIME
No key is needed first: enter the cooking time with the number pads, then touch START.

| Pads touched | Display | Cooking time |
|---|---|---|
| 3 0 | 00:30 | 30 seconds |
| 1 5 0 0 | 15:00 | 15 minutes |

Touch **HEAT** to change the strength; each touch moves to the next line of the table below.

| Times pressed | Strength | Suitable for |
|---|---|---|
| 1 | FULL | root vegetables |
| 2 | MEDIUM | fish fillets |
| 3 | GENTLE (delicate food) | eggs, custard |

PRESETS
1. Touch PRESET until the dish you want is shown (see table).
2. Touch START.
3. When the beeper sounds, stir the food.

| Presses | Dish | Weight |
|---|---|---|
| 1 | Broccoli | 200-500 g |
| 2 | Dumplings | 6-12 pieces |
| 3 | Sweetcorn (on the cob, 1 or 2 ears) | 1-2 ears |
"""

ACTIONS = ["press_heat", "press_preset", "press_start"] + [f"press_{d}" for d in range(10)]


def test_a_column_counting_presses_is_no_value_list_the_next_column_is() -> None:
    model = read_manual(STEAMER, ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.variables["heat"].values == ["full", "medium", "gentle"]


def test_a_pointer_to_a_table_reaches_past_the_steps_between() -> None:
    model = read_manual(STEAMER, ACTIONS).model
    assert model.variables["preset"].values == ["broccoli", "dumplings", "sweetcorn"]


def test_a_keys_pressed_table_is_worked_examples_and_the_pads_enter_the_time() -> None:
    model = read_manual(STEAMER, ACTIONS).model
    times = [v for v, spec in model.variables.items() if spec.type == "time"]
    assert times, model.variables
    feature = next(f for f in model.features.values() if f[0].variable in times)
    assert set(feature[0].actions) == {f"press_{d}" for d in range(10)}


SCALE_OVEN = """
GENERAL SAFETY
Do not operate the oven empty. Never heat liquids in sealed jars; they may burst. Children
should only use the oven under supervision. Do not use metal dishes on the turntable.

PANEL
THAW — chooses what you are thawing.   0-9 — number keys.   START — starts.

THAWING BY WEIGHT
1. Press THAW to choose the food. Each press moves on:

| Presses | Food | Weight |
|---|---|---|
| 1 | Mince | 100 g – 1.5 kg |
| 2 | Chicken pieces | 200 g – 2 kg |
| 3 | Rolls | 50 – 400 g |

2. Enter the weight of the food in grams with the number keys (e.g. 7 5 0).
3. Press START.
"""


def test_an_amount_typed_after_a_choice_key_is_the_second_step_of_its_feature() -> None:
    actions = ["press_thaw", "press_start"] + [f"press_{d}" for d in range(10)]
    reading = read_manual(SCALE_OVEN, actions)
    model = reading.model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.variables["thaw"].values == ["mince", "chicken pieces", "rolls"]
    steps = next(f for f in model.features.values() if f[0].variable == "thaw")
    assert len(steps) == 2 and steps[1].variable == "weight"
    assert set(steps[1].actions) == {f"press_{d}" for d in range(10)}
    weight = model.variables["weight"].model_dump(mode="json")
    # the chart's first column counts presses: each food's row gives its own weights
    assert weight["unit"] == "g" and weight["depends_on"] == "thaw"
    assert weight["cases"]["rolls"]["ranges"][0][:2] == [50, 400]
    assert weight["cases"]["chicken pieces"]["ranges"][0][:2] == [200, 2000]


def test_a_range_from_grams_to_kilograms_is_read_in_grams() -> None:
    from apbot.read.values import find_ranges

    (r,) = find_ranges("100 g – 1.5 kg")
    assert (r.low, r.high, r.unit) == (100, 1500, "g")


POWER_GUIDE = """
## Cooking
1. Type the time on the number pads.
2. Tap **LEVEL** and type the power level with the number pads.
3. Tap **START**.

A guide to the outputs:

| Output | Suits |
|---|---|
| 100 % | Soup, water |
| 80 % | Leftovers |
| 40 % | Stews |
| 20 % | Thawing |
"""


def test_a_guide_table_of_amounts_gives_the_range_in_the_step_that_meets_them() -> None:
    actions = ["press_level", "press_start"] + [f"press_{d}" for d in range(10)]
    model = read_manual(POWER_GUIDE, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    output = next(v for v in model.variables.values() if v.label == "LEVEL")
    assert output.unit == "%" and output.ranges == [(20, 100, 20)]


OVEN_PANEL = """
## Using the oven
The display shows the programme as PROG 1, PROG 2 … PROG 9. Touch PROG to go to the next
one; after PROG 9 it returns to PROG 1.

1. Type the time on the number pads. Longer dishes: cook in two stages.
2. Touch **LEVEL** and type the power level with the number pads.

Level guide

 Level    Name        Use
 90 %     High        Drinks
 60 %     Medium      Stews
 30 %     Low         Thawing

## Specifications

                    OV-1             OV-2
Level settings      230 V ~ 50 Hz    230 V ~ 50 Hz
Input level         1100 W           1200 W
Cavity              20 L             25 L
"""


def test_numbered_programmes_written_with_their_label_are_a_list_of_codes() -> None:
    actions = ["press_prog", "press_level"] + [f"press_{d}" for d in range(10)]
    model = read_manual(OVEN_PANEL, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.variables["prog"].values == [str(n) for n in range(1, 10)]


def test_a_captioned_guide_table_gives_the_range_and_a_data_row_is_no_header() -> None:
    actions = ["press_prog", "press_level"] + [f"press_{d}" for d in range(10)]
    model = read_manual(OVEN_PANEL, actions).model
    level = next(v for v in model.variables.values() if v.label == "LEVEL")
    assert level.type == "numeric" and level.unit == "%"
    assert level.ranges == [(30, 90, 30)]  # not the specifications' row names, no "two" step


# a pencil sharpener whose guide lists pencils, each with the point the POINT dial is set to
PENCIL = """# Pencil sharpener PS-2

## Keys
| Key | Function |
|---|---|
| POWER | Switches the sharpener on and off. |
| POINT | Dial with three positions: blunt · medium · fine. |
| SPEED | Next motor speed. |

## POINT guide
| Pencil | Point | Turns |
|---|---|---|
| Carpenter pencil | blunt | 10 |
| Coloured pencils, soft | medium | 5 to 8 |
| Drawing pencils, hard | fine | 12 |
"""


def test_a_guide_led_by_other_things_gives_the_key_no_values_in_its_first_column() -> None:
    model = read_manual(PENCIL, ["press_power", "turn_point", "press_speed"]).model
    point = model.variables["point"]
    assert point.values == ["blunt", "medium", "fine"], point.values


# a hob whose POWER section lists its levels, each with the watts it gives and what it suits
HOB_LEVELS = """# Induction hob IH-1

## Keys
| Key | Function |
|---|---|
| ON/OFF | Switches the hob on and off. |
| POWER | Chooses the power level. |
| TIMER | Sets the timer. |

## POWER
Press POWER repeatedly to choose the level:
| Level | Power | Suitable for |
|---|---|---|
| P1 | 300 W | Keeping warm |
| P2 | 800 W | Simmering |
| P3 | 1200 W | Frying |
| P4 | 2000 W | Boiling |
"""


def test_a_table_led_by_level_lists_the_keys_own_steps_not_a_guide() -> None:
    model = read_manual(HOB_LEVELS, ["press_on_off", "press_power", "press_timer"]).model
    assert any(v.values == ["p1", "p2", "p3", "p4"] for v in model.variables.values())
