"""A setting opened by holding a key is named after what the hold does, not after the gesture
("change the grind unit", "opens the delayed start"), so the user's words find it. Manuals
written for these tests: a grain mill, a bean roaster and a bath warmer no suite has."""

from __future__ import annotations

from apbot.read.goal import parse_instruction
from apbot.read.reader import read_manual

MILL = """# Granum GM-2 grain mill

## Keys

| Key     | Short press                     | Press and hold              |
|---------|---------------------------------|-----------------------------|
| (1) ON  | switch on / off                 | --                          |
| (2) GRIND | next grind: fine, medium, coarse | 3 s: change weight unit  |
| (3) +   | more grain                      | 2 s: ten steps at once      |
| (4) -   | less grain                      | 2 s: ten steps at once      |

## Weight unit

Hold GRIND for 3 seconds. The unit lamp moves on: g, oz, g.
"""

ROASTER = """# Torra R5 bean roaster

## The keys

ROAST     Touch briefly: opens the roasting time ("RT").
          Touch and hold for 2 seconds: opens the delayed start ("dS").
          Change either with + and -.
+ / -     Raise / lower the value that is open.
START     Starts the roast.

## Roasting time

Touch ROAST, then + or - to set 5 to 20 minutes.

## Delayed start

Touch and hold ROAST for 2 seconds until "dS 0 h" appears. Touch + or - to set the
waiting time from 0 to 8 hours, one hour per touch.
"""

WARMER = """# Calda BW-1 bath warmer

## Keys

| No. | Key    | Touch                  | Touch and hold 3 seconds |
|-----|--------|------------------------|--------------------------|
| 1   | POWER  | switch on / off        | --                       |
| 2   | WARM   | warming on / off       | change °C / °F           |
| 3   | CLOCK  | show the clock         | set the clock            |
"""


def _names(text: str, actions: list[str]) -> set[str]:
    return set(read_manual(text, actions, "test_appliance").model.variables)


def test_a_hold_column_that_changes_a_thing_names_the_setting() -> None:
    actions = ["press_on", "press_grind", "hold_grind", "press_plus", "press_minus"]
    names = _names(MILL, actions)
    assert "weight_unit" in names and "grind_hold" not in names
    assert "plus_hold" not in names  # stepping faster is no setting


def test_a_legend_line_for_holding_names_the_setting_it_opens() -> None:
    actions = ["press_roast", "hold_roast", "press_plus", "press_minus", "press_start"]
    reading = read_manual(ROASTER, actions, "roaster")
    assert "delay_start" in reading.model.variables
    assert "roast_hold" not in reading.model.variables
    goal = parse_instruction(reading.model, "Roast for 12 minutes, delayed by 3 hours", ROASTER, [])
    assert goal.get("delay_start") == "03:00:00"


def test_a_hold_that_switches_the_unit_or_opens_the_keys_own_setting() -> None:
    actions = ["press_power", "press_warm", "hold_warm", "press_clock", "hold_clock"]
    names = _names(WARMER, actions)
    assert "unit" in names and "warm_hold" not in names
    assert "clock_2" not in names  # "hold CLOCK to set the clock": the key's own name says it


HEATER = """# Tepor TH-4 towel heater

## Keys

POWER    switches the heater on and off.
MODE     next mode: COMFORT, ECO, DRY.

## Night level

Hold MODE for 3 seconds to select the night level. The moon lamp lights while it is chosen.
"""


def test_a_sentence_hold_key_to_verb_a_setting_names_it() -> None:
    names = _names(HEATER, ["press_power", "press_mode", "hold_mode"])
    assert "night_level" in names and "mode_hold" not in names


STEAMER = """# Vapo S2 food steamer

## Keys

POWER     Switches the steamer on or off.
TIME      Press to set the steaming time from 5 to 60 minutes.
          Press and hold TIME for 3 s to change rapidly.
START     Starts steaming.
"""


def test_a_hold_that_only_steps_faster_names_no_setting() -> None:
    names = _names(STEAMER, ["press_power", "press_time", "hold_time", "press_start"])
    assert "rapidly" not in names, names


LOADER = """# Vela W7 washing machine

## Keys

POWER     Switches the washer on or off.
PROGRAM   Press to select the programme: cotton, synthetics, wool.
TEMP      Press to select the temperature: 20, 30, 40, 60 °C.
          Hold TEMP for 3 seconds to open the door.
START     Starts or pauses the programme.
"""


def test_a_hold_that_opens_a_part_of_the_appliance_names_no_setting() -> None:
    actions = ["press_power", "press_program", "press_temp", "hold_temp", "press_start"]
    names = _names(LOADER, actions)
    assert "door" not in names, names
