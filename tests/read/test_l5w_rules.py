"""Rules drawn from last session's blind set L5 (development data now), each on a small manual
in our own words: a key legend set in as a block with no stops, levels printed as display
codes, keys named by their amount, clock lists of minutes and seconds, a heading naming two
keys, and a specifications table comparing the models of a range."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.model_columns import own_column
from apbot.read.text import parse_manual
from apbot.read.value_lists import find_list

# a tea brewer whose key legend is set in three spaces, each row without a full stop
BREWER = """BREWMATE TB-5 tea brewer

KEYS

   ⏻            switches the brewer on and off
   LEAF         kind of tea: GREEN, BLACK, HERBAL
   CUPS         how many cups: 1, 2, 4 (lamps)
   STRONG       hold 2 s: strong brew on/off

USING THE BREWER

Press ⏻. Press LEAF until the tea you want is shown. Press CUPS to choose the amount.
"""


def test_rows_of_a_legend_set_in_as_a_block_are_units_of_their_own() -> None:
    texts = [u.text for u in parse_manual(BREWER).units]
    assert any(t.startswith("LEAF") and "CUPS" not in t for t in texts)
    assert any(t.startswith("CUPS") and "STRONG" not in t for t in texts)


def test_a_key_in_a_set_in_legend_gets_its_own_row_s_values() -> None:
    model = read_manual(BREWER, ["press_power", "press_leaf", "press_cups", "hold_strong"]).model
    assert model.variables["leaf"].values == ["green", "black", "herbal"]


# a foot warmer printing its glow level as codes G1 … G6, never as a number range
WARMER = """TOASTY FW-1 foot warmer

The display shows the glow level (G1 … G6) while you change it.

Press GLOW + for more warmth and GLOW − for less. Press ⏻ to switch off.
"""


def test_a_level_given_only_as_display_codes_is_that_scale() -> None:
    model = read_manual(WARMER, ["press_power", "press_glow_up", "press_glow_down"]).model
    glow = model.variables["glow"]
    assert glow.ranges is not None and [tuple(r) for r in glow.ranges] == [(1, 6, 1)]
    assert glow.show == "G{value}"


# a lamp whose keys are named by their amounts
LAMP = """GLEAM UV-2 curing lamp

15m   Sets the exposure to 15 minutes and starts at once.
45m   Sets the exposure to 45 minutes and starts at once.
"""


def test_keys_named_by_their_amount_keep_controls_of_their_own() -> None:
    model = read_manual(LAMP, ["press_15m", "press_45m"]).model
    ids = [c.id for c in model.controls]
    assert len(ids) == len(set(ids)) == 2


def test_a_clock_list_keeps_the_colon_of_its_first_time() -> None:
    items = find_list("Order: 0:30 → 1:00 → 1:30 → 2:00 → 0:30 …")
    assert items is not None and items[0] == ["0:30", "1:00", "1:30", "2:00"]


# a spinner whose run time is a list of minutes and seconds, told so by its steps
SPINNER = """WHIRL SP-3 salad spinner

Touch RUN to go to the next run time:

   0:15 → 0:30 → 0:45 → 1:00 → 0:15 …

The steps are 15 seconds.
"""


def test_a_clock_list_told_in_seconds_is_minutes_and_seconds() -> None:
    model = read_manual(SPINNER, ["press_run"]).model
    run = next(v for v in model.variables.values() if v.type == "time")
    assert run.ranges is not None and len(run.ranges) == 1
    low, high, step = run.ranges[0]
    assert (str(low), str(high), step) == ("00:00:15", "00:01:00", 15)


# a twin-plate grill: a section titled "Plate mode" is about MODE, not about PLATE
GRILL = """SIZZLE TG-2 twin grill

3   THE KEYS

   PLATE     picks the plate the keys act on: FRONT or REAR
   MODE      mode of the chosen plate

4   OPERATION

4.1  Plate mode: sear, warm or off

   Press MODE to step the chosen plate through its three modes:

         OFF  ─►  SEAR  ─►  WARM  ─►  OFF …

   The plate keeps its mode when you choose the other plate.
"""


def test_a_heading_naming_another_key_after_this_one_lends_it_no_list() -> None:
    model = read_manual(GRILL, ["press_plate", "press_mode"]).model
    assert model.variables["plate"].values == ["front", "rear"]
    assert model.variables["mode"].values == ["off", "sear", "warm"]


def test_the_own_model_is_the_one_the_text_names_most() -> None:
    header = ("Model", "KP-1", "KP-2", "KP-3")
    lines = ["KETTLEPRO KP-2   page 1", "KETTLEPRO KP-2   page 2", "This guide is for the KP-2."]
    lines += ["Model  KP-1  KP-2  KP-3"]
    assert own_column(header, lines) == 2
    assert own_column(header, ["Model  KP-1  KP-2  KP-3"]) is None
    # a longer sister's name that starts with this one's is counted as hers
    plus = ("", "KP-2", "KP-2 Plus")
    said = ["KP-2 Plus only"] * 4 + ["KP-2"]
    assert own_column(plus, said) == 2


# a range's specifications table: the sister model's cell lists a zone this one lacks
RANGE = """HOBLINE HB-2 hob

Model ............ HB-1         HB-2          HB-3
ZONE key ......... –            LEFT, RIGHT   LEFT, MIDDLE, RIGHT
Power ............ 1500 W       2800 W        3600 W

This manual describes the HB-2. HOBLINE HB-2 page 2. HOBLINE HB-2 page 3.

Press ZONE to choose the zone.
"""


def test_a_range_s_table_gives_only_the_own_model_s_values() -> None:
    model = read_manual(RANGE, ["press_zone"]).model
    assert "middle" not in model.variables["zone"].values


# a fan whose trouble row names the fan speed beside its error codes
FAN = """BREEZE fan

Press SPEED + or SPEED − to change the fan speed.

TROUBLESHOOTING
E1 … E9   The fan speed sensor reports a fault. Unplug the fan and call service.
"""


def test_error_codes_naming_the_setting_are_no_scale_of_it() -> None:
    model = read_manual(FAN, ["press_speed_up", "press_speed_down"]).model
    assert model.variables["speed"].show != "E{value}"


# a heater's indented, justified prose: a wrapped line starting "8  hours" is no legend row
HEATER = """HEATER

USING THE TIMER

    Press TIMER to choose how long the heater runs. Each press adds one
    hour, up to 8 hours; the display counts down the remaining time. Press TIMER again after
    8  hours to cancel the timer and return to continuous heating.
"""


def test_an_indented_paragraph_of_prose_is_not_split_at_a_justified_line() -> None:
    texts = [u.text for u in parse_manual(HEATER).units]
    assert not any(t.startswith("8  hours") for t in texts)


# a rice cooker's delay list in hours and minutes, beside a wait told in seconds
COOKER = """AROMA RC-1 rice cooker

DELAY TIMER

Press DELAY to set when cooking finishes: 0:30 → 1:00 → 1:30 → 2:00 → 3:00 → 4:00.
The display flashes for 5 seconds, then the timer starts.
Press START to begin.
"""


def test_a_wait_in_seconds_beside_a_clock_list_keeps_it_hours_and_minutes() -> None:
    model = read_manual(COOKER, ["press_delay", "press_start"]).model
    delay = next(v for v in model.variables.values() if v.type == "time")
    assert delay.ranges is not None and str(delay.ranges[-1][1]) == "04:00:00"


def test_columns_of_programme_codes_are_no_models() -> None:
    lines = ["Use P1 for rice. P1 is quick. Choose P1 often.", "P2 is slow."]
    assert own_column(["Setting", "P1", "P2", "P3"], lines) is None
