"""Rules about how far a setting goes when a manual tells it in a small table or an example,
each on a short manual written in our own words the way a converted commercial manual reads."""

from __future__ import annotations

from apbot.read import read_manual

# a fan heater whose off-timer table (range, step) was flattened into one line
HEATER = """# Fan heater FH-9

## Keys
| Key | Function |
|---|---|
| ON/OFF | Switches the heater on and off. |
| TIMER | Sets the switch-off timer. |

## Switch-off timer
Press TIMER repeatedly to choose after how long the heater switches itself off.
Timer settings:   Range         Step   0.5 – 4 h   30 min   4 – 16 h   2 h
"""


def test_a_flattened_range_and_step_table_in_hours_gives_each_piece_its_step() -> None:
    model = read_manual(HEATER, ["press_on_off", "press_timer"]).model
    timer = model.variables["timer"]
    tops = [str(r[1]) for r in timer.ranges]
    steps = [str(r[2]) for r in timer.ranges]
    assert tops in (["4", "16"], ["04:00:00", "16:00:00"]), timer.ranges
    assert steps in (["0.5", "2"], ["1800", "7200"]), timer.ranges


# a rice cooker whose preset is told in hours, and shown as hours:minutes in an example
COOKER = """# Rice cooker RC-3

## Keys
| Key | Function |
|---|---|
| MENU | Chooses the cooking menu: WHITE, BROWN or PORRIDGE. |
| PRESET | Sets after how long the rice is ready. |
| START | Starts cooking or the preset countdown. |

## Preset
The preset can be set up to 15 hours ahead. Press PRESET several times; for example,
for rice ready at breakfast press PRESET until the display shows 7:40, then press START.
"""


def test_a_setting_in_hours_the_display_shows_as_hours_and_minutes_is_a_time() -> None:
    model = read_manual(COOKER, ["press_menu", "press_preset", "press_start"]).model
    preset = model.variables["preset"]
    assert preset.type == "time", preset
    assert str(preset.ranges[-1][1]) == "15:00:00"
    assert int(preset.ranges[0][2]) <= 600  # set in minutes: 7:40 can be reached


# a water boiler: the descaling steps wait an hour or two after a key press
BOILER = """# Water boiler WB-5

## Keys
| Key | Function |
|---|---|
| BOIL | Brings the water back to the boil. |
| WARM | Chooses the keep-warm temperature: 60, 80 or 95 °C. |
| POUR | Pours hot water. |

## Descaling
1. Fill with water and add two spoons of citric acid.
2. Press BOIL.
3. Leave for one to three hours, then empty the boiler and rinse it.
"""


def test_a_wait_after_pressing_a_key_is_no_range_of_that_key() -> None:
    model = read_manual(BOILER, ["press_boil", "press_warm", "press_pour"]).model
    boil = model.variables.get("boil")
    assert boil is None or boil.type == "discrete", boil


# an oven whose MORE / LESS keys fine-tune an automatic programme
OVEN = """# Compact oven CO-1

## Keys
| Key | Function |
|---|---|
| AUTO | Chooses an automatic programme: PIZZA, CHIPS or CAKE. |
| + / − | Change the cooking time. |
| MORE / LESS | Adjust the result of an automatic programme. |
| START | Starts the oven. |

## Automatic programmes
Press AUTO until your dish shows. If the dish usually comes out underdone, press MORE; if it
comes out overdone, press LESS. Pressing the other key goes back to the normal result.
"""


def test_more_and_less_keys_that_fine_tune_a_result_choose_less_standard_or_more() -> None:
    actions = ["press_auto", "press_plus", "press_minus", "press_more", "press_less", "press_start"]
    model = read_manual(OVEN, actions).model
    adjust = model.variables["adjust"]
    assert adjust.type == "discrete" and adjust.values == ["less", "standard", "more"]


# a food steamer whose programme table gives each programme its own steaming times
STEAMER = """# Food steamer FS-2

## Keys
| Key | Function |
|---|---|
| PROG | Chooses the programme: VEG, FISH, EGGS or KEEP. |
| STEAM TIME | Changes the steaming time. |
| START | Starts steaming. |

## Programmes
Each press of PROG selects the next programme.

| Display | Programme | Steam time |
|---|---|---|
| VEG | Vegetables | 10 to 40 minutes |
| FISH | Fish fillets | 5, 10 or 15 minutes |
| EGGS | Eggs | 6, 9 or 12 minutes |
| KEEP | Keep warm | — |

Press STEAM TIME to move to the next available time.
"""


def test_a_programme_table_gives_each_programme_its_listed_or_ranged_times() -> None:
    model = read_manual(STEAMER, ["press_prog", "press_steam_time", "press_start"]).model
    steam = model.variables["steam_time"]
    assert steam.depends_on == "prog", steam
    assert steam.cases is not None
    assert [str(x) for x in steam.cases["fish"].ranges[0]][:2] == ["00:05:00", "00:15:00"]
    assert [str(x) for x in steam.cases["eggs"].ranges[0]][:2] == ["00:06:00", "00:12:00"]


# a hair clipper whose guard guide advises a few lengths per hair type, row by row
CLIPPER = """# Hair clipper HC-4

## Keys
| Key | Function |
|---|---|
| POWER | Switches the clipper on and off. |
| STYLE | Chooses the cutting style: EVEN, FADE or TRIM. |
| LENGTH | Next cutting length. After the longest it goes back to the shortest. |

## Length guide
| Hair | Style | Length |
|---|---|---|
| Thin hair, first cut | EVEN | 3 – 4, go shorter later |
| Children | EVEN | 2 |
| Thick curls | FADE | 9 – 12 |
| Beard outline | TRIM | 5 – 6 |
"""


def test_a_guide_column_of_advised_amounts_spans_every_row_not_the_first() -> None:
    model = read_manual(CLIPPER, ["press_power", "press_style", "press_length"]).model
    length = model.variables["length"]
    assert [float(x) for x in length.ranges[0][:2]] == [2, 12], length.ranges


# a kettle whose technical data give each model of the range its own temperature span
KETTLE_MODELS = """# Kettle K-3

## Keys
| Key | Function |
|---|---|
| POWER | Switches the kettle on and off. |
| TEMP | Next water temperature. |

## Technical data
| Model | Capacity | Temp |
|---|---|---|
| K-3 | 1.0 l | 60 – 90 °C |
| K-5 | 1.7 l | 40 – 100 °C |
| K-7 | 1.7 l | 100 °C |
"""


def test_a_table_of_models_gives_no_span_beyond_the_models_own_row() -> None:
    model = read_manual(KETTLE_MODELS, ["press_power", "press_temp"]).model
    assert [float(x) for x in model.variables["temp"].ranges[0][:2]] == [60, 90]


def test_a_guide_column_spans_every_row_whichever_order_its_rows_come_in() -> None:
    # rows in rising order are still advice (single amounts, gaps): no pieces of one range
    rising = CLIPPER.replace(
        "| Thin hair, first cut | EVEN | 3 – 4, go shorter later |\n| Children | EVEN | 2 |\n"
        "| Thick curls | FADE | 9 – 12 |\n| Beard outline | TRIM | 5 – 6 |",
        "| Children | EVEN | 2 |\n| Thin hair, first cut | EVEN | 3 – 4, go shorter later |\n"
        "| Beard outline | TRIM | 5 – 6 |\n| Thick curls | FADE | 9 – 12 |",
    )
    assert rising != CLIPPER
    model = read_manual(rising, ["press_power", "press_style", "press_length"]).model
    assert [float(x) for x in model.variables["length"].ranges[0][:2]] == [2, 12]


def test_a_table_whose_rows_are_type_numbers_is_a_table_of_models_whatever_its_head() -> None:
    for head in ("|  |", "| Item no. |"):
        text = KETTLE_MODELS.replace("| Model |", head)
        model = read_manual(text, ["press_power", "press_temp"]).model
        assert [float(x) for x in model.variables["temp"].ranges[0][:2]] == [60, 90], head
