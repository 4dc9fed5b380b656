"""Rules drawn from last session's blind set J5 (development data now), each on a small manual
in our own words: value rows drawn with arrow heads, a placeholder glossed in brackets, a key
named AUTO OFF that is a setting, keys printed as a name and a sign, a slashed pair of values
that is no key name, legend rows joined by dot leaders, a display word with dashes for off."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.value_lists import find_list


def test_arrow_heads_drawn_with_a_dashed_shaft_separate_a_list() -> None:
    items = find_list("0 --► 10 --► 20 --► 40 min --► 0 …")
    assert items is not None and items[0] == ["0", "10", "20", "40 min"]


def test_an_ellipsis_in_an_arrow_row_stands_for_the_steps_it_skips() -> None:
    items = find_list("0 h (none) → 2 h → 3 h → 4 h … → 7 h → 0 h")
    assert items is not None
    assert items[0] == ["0 h", "2 h", "3 h", "4 h", "5 h", "6 h", "7 h"]


def test_a_dashed_screen_glossed_in_brackets_is_the_word_it_glosses() -> None:
    items = find_list("15 min → 45 min → -- (off) → 15 min …")
    assert items is not None and items[0] == ["15 min", "45 min", "off"]


def test_a_row_both_ways_with_the_unit_after_the_last_number() -> None:
    items = find_list("40 ◄► 60 ◄► 90 ◄► 120 mic")
    assert items is not None and items[0] == ["40", "60", "90", "120 mic"]


def test_a_value_per_name_in_brackets_is_no_list() -> None:
    assert find_list("The fan goes back to the mode's first level (DAY: 2, NIGHT: 1).") is None


# a sealer with a timed switch-off key, keys printed as a name and a sign, a slashed pair of
# values in a data table, and a display legend joined by dot leaders
SEALER = """FOLIO BS-2 bag sealer

TECHNICAL DATA
   Film thickness WARM/COOL     up to 120 mic

KEYS
   A  ⏻          switch on / off
   B  COOL       warm / cool sealing
   C  FILM −     thinner film
   D  FILM +     thicker film
   E  AUTO OFF   automatic switch-off time
   F  START      start / stop sealing

   What the display shows
     WARM 60 mic ........ warm sealing with the film thickness
     SEAL ............... sealing; other keys blocked

Warm or cool
   Press COOL to change between WARM and COOL. Cool sealing is for self-adhesive film.
   It needs no warm-up.

Film thickness
   FILM − and FILM + step through the same list, one value per press:

        40 ◄► 60 ◄► 90 ◄► 120 mic

Automatic switch-off
   The sealer switches itself off when no key has been pressed for the set time.
   Press AUTO OFF to change it:

        15 min → 45 min → -- (off) → 15 min …

Sealing
   Press START. SEAL appears. Press START again to stop.
"""
SEALER_ACTIONS = ["press_power", "press_cool", "press_film_down", "press_film_up",
                  "press_auto_off", "press_start"]  # fmt: skip


def test_a_key_named_auto_off_sets_the_switch_off_time_it_is_no_stop_key() -> None:
    model = read_manual(SEALER, SEALER_ACTIONS).model
    (steps,) = [s for s in model.features.values() if s[0].actions == ["press_auto_off"]]
    assert steps[0].variable != "running"
    assert model.variables[steps[0].variable].values == ["15 min", "45 min", "off"]


def test_a_slashed_pair_of_values_printed_once_does_not_name_the_key() -> None:
    model = read_manual(SEALER, SEALER_ACTIONS).model
    (steps,) = [s for s in model.features.values() if s[0].actions == ["press_cool"]]
    assert model.variables[steps[0].variable].values == ["warm", "cool"]


def test_keys_printed_as_a_name_and_a_sign_step_the_list_they_share() -> None:
    model = read_manual(SEALER, SEALER_ACTIONS).model
    (steps,) = [s for s in model.features.values() if "press_film_up" in s[-1].actions]
    var = model.variables[steps[-1].variable]
    assert [list(r) for r in var.ranges or []] == [[40, 60, 20], [60, 120, 30]]


def test_dot_leader_rows_are_legend_rows_of_their_own() -> None:
    manual = parse_manual(SEALER)
    texts = [u.text for u in manual.units]
    assert "SEAL    sealing; other keys blocked" in texts
    model = read_manual(SEALER, SEALER_ACTIONS).model
    assert model.variables["running"].show == {"off": "", "on": "SEAL"}


# a held key whose display word, with dashes for its blank value, shows while it is off; the
# sentence after a reset says which settings are kept
IRON = """PRESSA SI-4 steam iron

   I/O          Power switch. Switches the iron on and off.
   TURBO        Press: turbo steam on / off.
   AUTO OFF     Hold 3 seconds to switch the auto switch-off off or on.

   AUTO OFF --   The auto switch-off is disabled.

SWITCHING OFF
   When you switch the iron off, the programme and the turbo steam return to their standard
   values. The auto switch-off setting is kept.
"""
IRON_ACTIONS = ["switch_power", "press_turbo", "hold_auto_off"]


def test_a_display_word_with_dashes_for_its_blank_value_shows_the_setting_off() -> None:
    model = read_manual(IRON, IRON_ACTIONS).model
    (steps,) = [s for s in model.features.values() if s[0].actions == ["hold_auto_off"]]
    var = model.variables[steps[0].variable]
    assert var.show == {"on": "", "off": "AUTO OFF --"}
    assert var.initial == "on"


# a recipe names the settings in passing, beside the key: no list of the key's values
PROOFER = """LEVAIN P-2 dough proofer

   ⏻        switch on / off
   MODE     proof / slow rise
   MIST     Humidity (water tray) on / off.

Humidity
   Touch MIST to switch the humidity on or off.

RECIPES
   Farmhouse loaf
     1. First rise: PROOF, 30 °C / 86 °F, MIST on, about 1:00.
"""
PROOFER_ACTIONS = ["press_power", "press_mode", "press_mist"]


def test_a_recipe_naming_settings_in_passing_gives_no_key_a_list() -> None:
    model = read_manual(PROOFER, PROOFER_ACTIONS).model
    (steps,) = [s for s in model.features.values() if s[0].actions == ["press_mist"]]
    assert model.variables[steps[0].variable].values == ["off", "on"]


# "Power levels available:" near MODE names MODE's levels, though a POWER key leads the words
HEATER = """# Heater H-3

| Key | Function |
|---|---|
| POWER | Switches the heater on or off. |
| MODE | Changes the heat output. |

## Heat output

Press MODE to change the heat output.

Power levels available:

LOW · MEDIUM · HIGH · TURBO
"""


def test_levels_led_by_another_keys_noun_are_still_this_keys_list() -> None:
    model = read_manual(HEATER, ["press_power", "press_mode"]).model
    assert model.variables["mode"].values == ["low", "medium", "high", "turbo"]


# a heading naming the setting it shows examples of keeps its list ("Power level examples")
OVEN = """# Microwave MW-20

| Key | Function |
|---|---|
| POWER LEVEL | Sets the power of the next cooking. |
| START | Starts cooking. |

## Power level examples

Each press of POWER LEVEL changes the level: HIGH → MED-HIGH → MED → LOW → DEFROST.
"""


def test_a_settings_own_examples_heading_is_no_aside() -> None:
    model = read_manual(OVEN, ["press_power_level", "press_start"]).model
    assert model.variables["power_level"].values[:2] == ["high", "med-high"]


# the sentence after a reset giving the value a setting is reset to ("stays at 0") keeps nothing
FRYER = """# Fryer AF-3

| Key | Function |
|---|---|
| MODE | Chooses the programme: FRIES → CHICKEN → FISH → CAKE. |
| TEMP + | Raises the temperature. |
| TEMP − | Lowers the temperature. |
| TIMER | Adds 5 minutes to the timer. |

Set the temperature from 80 to 200 °C in steps of 10 °C. The timer runs from 0 to 60 minutes in
steps of 5 minutes.

Changing the programme returns all settings to their standard values. The timer stays at 0
until you press TIMER.
"""


def test_a_setting_said_to_stay_at_a_value_after_a_reset_is_reset() -> None:
    actions = ["press_mode", "press_temp_up", "press_temp_down", "press_timer"]
    model = read_manual(FRYER, actions).model
    assert "timer" in model.features["set_mode"][0].reset


# the appliance's own stored recipes, chosen with a key, are no recipe section to skip
AUTO = """# Microwave MW-30

| Key | Function |
|---|---|
| AUTO MENU | Chooses an automatic recipe. |
| START | Starts cooking. |

## Automatic recipes

Press AUTO MENU repeatedly to choose: POPCORN → POTATO → PIZZA → BEVERAGE.
"""


def test_automatic_recipes_chosen_with_a_key_keep_their_list() -> None:
    model = read_manual(AUTO, ["press_auto_menu", "press_start"]).model
    assert model.variables["auto_menu"].values[:2] == ["popcorn", "potato"]
