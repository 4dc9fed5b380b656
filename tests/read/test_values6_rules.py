"""Values and ranges the read model lacked (seventh round), each on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.shapes import _fits

# a panel drawn with key caps in square brackets, spaced like a table, and a chart of what
# each touch of one key shows on the display
STEAMER = """CONTROL PANEL

  [ STEAM      ] [ COOK TIME   ]        Display: the time of day, or the setting
  [ LEVEL      ] [ CLOCK       ]        being entered.
  [ 1 ] [ 2 ] [ 3 ]
  [ STOP       ]  [ START ]

STEAM
  1. Touch STEAM. Each touch moves on to the next steam amount, as the chart shows.
  2. Touch START.

Steam chart
   Touch STEAM      Display          Use
   1 time           STM 2 cups       vegetables
   2 times          STM 4 cups       fish
   3 times          STM off          no steam
"""

STEAMER_ACTIONS = [
    "press_steam",
    "press_cook_time",
    "press_level",
    "press_clock",
    "press_1",
    "press_2",
    "press_3",
    "press_stop",
    "press_start",
]


def test_key_caps_drawn_in_brackets_are_no_column_of_values() -> None:
    model = read_manual(STEAMER, STEAMER_ACTIONS).model
    values = [str(v) for v in model.variables["steam"].model_dump(mode="json").get("values", [])]
    assert not any("[" in v or "clock" in v or "level" in v for v in values), values


def test_a_display_column_loses_the_word_every_row_starts_with() -> None:
    model = read_manual(STEAMER, STEAMER_ACTIONS).model
    values = model.variables["steam"].model_dump(mode="json")["values"]
    assert values == ["2 cups", "4 cups", "off"], values


# an embroidery unit whose keypad types the number of a design from a numbered chart, and
# whose OK key only closes that entry
EMBROIDERY = """KEYS

  Key          Use
  0 - 9        Number keys: type the number of the pattern you want.
  OK           Ends the entry of a pattern number.
  SPEED        Each press: SLOW > FAST > SLOW ...

PATTERNS

  No.   Pattern          Hoop
  01    Rose             small
  02    Anchor           small
  03    Monogram frame   large
  04    Star border      large
  05    Leaf             small

Type the pattern number, then press OK. The display shows the number.
"""


def test_a_confirm_key_naming_a_numbered_chart_makes_the_keypad_type_that_number() -> None:
    actions = [f"press_{d}" for d in range(10)] + ["press_ok", "press_speed"]
    model = read_manual(EMBROIDERY, actions).model
    spec = model.variables["pattern"].model_dump(mode="json")
    assert spec["type"] == "numeric", spec
    assert spec["ranges"] == [[1, 5, 1]], spec
    steps = [s for f in model.features.values() for s in f if "press_ok" in s.actions]
    assert steps and steps[0].variable == "pattern", steps
    assert "press_5" in steps[0].actions, steps
    assert not any(
        v.model_dump(mode="json").get("type") == "time" for v in model.variables.values()
    ), "the keypad types the pattern, not a time"


# a wind-up timer knob printed every ten minutes, with a small mark between two numbers
OVEN = """TIMER knob
The knob is printed OFF 10 20 30 40 50 60 (minutes). Between two numbers the knob also
clicks at a small mark. Turn it clockwise to add time.

LAMP
Press to switch the lamp on or off.
"""


def test_a_knob_that_clicks_at_small_marks_stops_halfway_between_its_numbers() -> None:
    actions = ["turn_timer_cw", "turn_timer_ccw", "press_lamp"]
    spec = read_manual(OVEN, actions).model.variables["timer"].model_dump(mode="json")
    steps = {r[2] for r in spec["ranges"]}
    assert steps == {300} or steps == {5}, spec


# a two-drawer cooker whose specification gives the timer in hours and whose programme table
# gives each programme's times in minutes
TWO_DRAWERS = """SPECIFICATIONS
Model                     TD-20                   TD-10
Heating power             1800 W                  1500 W
Timer                     up to 10 h              up to 90 min

KEYS
MENU 1 / MENU 2 button – each press moves that drawer to the next programme:
  FRIES → CHICKEN → CAKE → DRY FRUIT, then back to FRIES.
TEMP/TIME 1 / TEMP/TIME 2 button – lets the drawer's + and − keys set the temperature
  (°C flashes); press again and they set the time again.
+ 1 / − 1, + 2 / − 2 buttons – change the time (or temperature) of that drawer.

PROGRAMMES
Programme       Preset          Adjustable          Preset      Adjustable
                temp.           temp.               time        time
FRIES           200 °C          150 – 200 °C        15 min      1 – 40 min
CHICKEN         190 °C          150 – 200 °C        30 min      1 min – 2 h
CAKE            160 °C          120 – 180 °C        35 min      1 – 90 min
DRY FRUIT       60 °C           40 – 90 °C          5 h         1 – 10 h

The temperature moves in steps of 10 °C.
"""


def test_a_programme_column_in_minutes_makes_an_hours_setting_a_time_in_both_zones() -> None:
    actions = [
        "press_menu1", "press_temptime1", "press_plus1", "press_minus1",
        "press_menu2", "press_temptime2", "press_plus2", "press_minus2",
    ]  # fmt: skip
    model = read_manual(TWO_DRAWERS, actions).model
    times = {
        n: v.model_dump(mode="json") for n, v in model.variables.items() if n.startswith("time")
    }
    assert len(times) == 2, list(model.variables)
    for name, spec in times.items():
        assert spec["type"] == "time", (name, spec)
        assert spec["cases"]["fries"]["ranges"][0][:2] == ["00:01:00", "00:40:00"], (name, spec)


# a thawing key told by how much each tap adds, and its top in a larger unit
THAW = """KEYS
THAW        thaw by weight.
START       starts the oven.

THAW
Tap THAW once for every 50 g of frozen food, then tap START. The heaviest setting is 1.5 kg.
"""


def test_a_key_tapped_once_for_every_amount_steps_that_amount_up_to_the_heaviest() -> None:
    model = read_manual(THAW, ["press_thaw", "press_start"]).model
    spec = model.variables["thaw"].model_dump(mode="json")
    assert spec["type"] == "numeric" and spec["unit"] == "g", spec
    assert spec["ranges"] == [[50, 1500, 50]], spec


# a top loader whose chart lists each course's settings joined by hyphens, the standard value
# in brackets, in the order the key shows them
TOP_LOADER = """KEYS
COURSE     each press selects the next course: Normal → Bulky → Fast.
SOAK       each press shows the next soak time (see the chart).
RINSE      each press shows the next number of rinses (see the chart).
START      starts the wash.

COURSE CHART
Values in the order the key shows them; the standard value is in [ ].

  Course     | SOAK (min)         | RINSE (times)
  -----------|--------------------|--------------
  Normal     | 0-10-[20]-30       | 1-[2]-3
  Bulky      | 0-[30]-60-90       | 2-[3]
  Fast       | [0]-10             | [1]-2
"""


def test_numbers_joined_by_hyphens_in_a_chart_are_the_values_not_a_range() -> None:
    actions = ["press_course", "press_soak", "press_rinse", "press_start"]
    model = read_manual(TOP_LOADER, actions).model
    soak = model.variables["soak"].model_dump(mode="json")
    assert soak["cases"]["bulky"] == {"ranges": [[0, 90, 30]], "initial": 30}, soak
    rinse = model.variables["rinse"].model_dump(mode="json")
    assert rinse["cases"]["normal"] == {"ranges": [[1, 3, 1]], "initial": 2}, rinse
    assert rinse["cases"]["bulky"]["ranges"] == [[2, 3, 1]], rinse


# a dryer chart whose column says which programmes take the on/off option, a note from the
# last column run into one of its cells
DRYER = """KEYS
PROGRAMME   turn to choose: Cotton → Mixed → Wool → Refresh.
CREASE      creaseguard on / off.
START       starts the programme.

PROGRAMMES
Programme     Load kg   Anti-crease   Notes
Cotton        8         yes           towels, bedding
Mixed         4         yes
Wool          1         –             wool only;
                                      no anti-crease possible
Refresh       1         –             no heat
"""


def test_a_yes_or_dash_column_says_which_programmes_offer_an_on_off_option() -> None:
    actions = ["turn_programme_cw", "turn_programme_ccw", "press_crease", "press_start"]
    model = read_manual(DRYER, actions).model
    spec = model.variables["crease"].model_dump(mode="json")
    assert spec["depends_on"] == "programme", spec
    assert set(spec["cases"]) == {"cotton", "mixed"}, spec
    assert all(c["values"] == ["off", "on"] for c in spec["cases"].values()), spec


def test_a_power_setting_takes_no_temperature_or_time_range() -> None:
    # "PROBE replaces the power setting by a temperature, 50–200 °C" after a POWER sentence
    assert not _fits("°C", ["power"]) and not _fits("min", ["power"])
    assert _fits("W", ["power"]) and _fits("%", ["power"]) and _fits("", ["power"])


def test_a_snowflake_printed_after_a_row_of_temperatures_is_the_value_cold() -> None:
    text = (
        "TEMP.\nPress TEMP. to change the wash temperature. The lamps over the key read"
        " 60 40 30 20 ❄. Each press lights the next lamp.\n"
    )
    model = read_manual(text, ["press_temp"]).model
    spec = model.variables["temp"].model_dump(mode="json")
    assert spec["values"] == ["60", "40", "30", "20", "cold"], spec
