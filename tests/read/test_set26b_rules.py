"""Rules of the set26b session (the twenty-sixth set's centrifuge, stirrer and karaoke speaker
read as development data), each on a small manual in our own words: a sentence with a bare
arrow names only the pair whose name it says (``labels_sign_pairs``), a speed takes an rpm
range named elsewhere (``quantity_units``), a range told as spans of amounts with a step each
(``values_span_steps``), also as list items under another key's sentence
(``evidence_whose._item_run``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.values import Range
from apbot.read.values_span_steps import find_span_steps

# a dryer cabinet with a pair of arrows per setting, printed with the setting's name
CABINET = """
Borell DC-2 drying cabinet

  Keys: ⏻   [FAN ▲] [FAN ▼]   [TIME ▲] [TIME ▼]

  Specifications

  | Item      | DC-2           |
  |-----------|----------------|
  | Fan       | 20 - 80 %      |

DRYING TIME

Use TIME ▲ and TIME ▼ to set the drying time from 10 to 240 minutes in steps of 10 minutes.

FAN

FAN ▲ / ▼ change the air flow.
"""
CABINET_ACTIONS = [
    "press_power",
    "press_fan_up",
    "press_fan_down",
    "press_time_up",
    "press_time_down",
]


def test_a_bare_arrow_sentence_is_the_pair_it_names() -> None:
    """ "Use TIME ▲ and TIME ▼" is the time's pair: the fan does not take the time's range."""
    model = read_manual(CABINET, CABINET_ACTIONS).model
    fan = next(v for n, v in model.variables.items() if n.startswith("fan"))
    assert fan.type != "time"
    assert all(r[1] <= 100 for r in fan.ranges)


# a lab shaker whose speed pair has no range in its own sentences: the data table gives it
SHAKER = """
Orbis OS-4 orbital shaker

  Keys: ⏻   [SPEED ▲] [SPEED ▼]   [TIME ▲] [TIME ▼]

TECHNICAL DATA

  | Item        | OS-4            |
  |-------------|-----------------|
  | Speed       | 50 - 800 rpm    |
  | Run time    | 1 - 99 min      |

SETTING THE SPEED

SPEED ▲ / ▼ change the speed by 10 rpm a press.
"""


def test_a_speed_takes_an_rpm_range_named_elsewhere() -> None:
    model = read_manual(
        SHAKER,
        ["press_power", "press_speed_up", "press_speed_down", "press_time_up", "press_time_down"],
    ).model
    speed = model.variables["speed"]
    assert speed.type == "numeric"
    assert speed.ranges[0][0] == 50 and speed.ranges[-1][1] == 800


def test_spans_of_amounts_each_with_its_step() -> None:
    told = (
        "Between 15 seconds and 5 minutes each press moves the delay by 15 seconds. "
        "Between 5 and 45 minutes each press moves it by 5 minutes."
    )
    assert find_span_steps(told) == [Range(15, 300, "s", 15), Range(300, 2700, "s", 300)]
    listed = "2 to 20 litres in 2-litre steps, then 20 to 60 litres in steps of 5 litres"
    assert find_span_steps(listed) == [Range(2, 20, "l", 2), Range(20, 60, "l", 5)]
    grams = "100 to 500 g in 50-g steps, then 500 to 2000 g in steps of 100 g."
    assert find_span_steps(grams) == [Range(100, 500, "g", 50), Range(500, 2000, "g", 100)]
    assert find_span_steps("Between 1 and 10 minutes each press adds 1 minute.") == []


# a fan heater's off-timer told as spans in list items, under a sentence about another key
HEATER = """
Calor FH-3 fan heater

  Controls: ⏻   OFF-TIMER   HEAT knob

OFF-TIMER

  1. Press OFF-TIMER.
  2. Within 5 seconds, turn the HEAT knob:
     - 1 to 3 hours in 10-minute clicks,
     - then 3 to 12 hours in 30-minute clicks.
"""


def test_spans_told_as_list_items() -> None:
    model = read_manual(
        HEATER, ["press_power", "press_off_timer", "turn_heat_cw", "turn_heat_ccw"]
    ).model
    timer = next(v for n, v in model.variables.items() if "timer" in n)
    assert timer.type == "time"
    assert [r[2] for r in timer.ranges] == [600, 1800]


# a sous-vide stick whose knobs are turned for a value and pushed to switch something
STICK = """
Therma SV-2 sous-vide stick

  Panel: ⏻   TEMP knob   PUMP knob

  Display lamps:  WARM: heating is on    FLOW: the pump is on

  ⏻        standby / on
  TEMP     turn: water temperature; push: heating on / off
  PUMP     turn: pump speed; push: pump on / off

Turn the TEMP knob to set the water temperature from 40 to 90 °C in steps of 0.5 °C.
Turn the PUMP knob to set the pump speed from 1 to 5.
"""
STICK_ACTIONS = [
    "press_power",
    "turn_temp_cw",
    "turn_temp_ccw",
    "push_temp",
    "turn_pump_cw",
    "turn_pump_ccw",
    "push_pump",
]


def test_a_knob_pushed_switches_what_its_push_part_names() -> None:
    model = read_manual(STICK, STICK_ACTIONS).model
    heating = model.variables["heating"]
    assert heating.values == ["off", "on"]
    assert heating.show == {"off": "", "on": "WARM"}
    toggles = {
        f.variable: f.actions for steps in model.features.values() for f in steps if f.variable
    }
    assert toggles["heating"] == ["push_temp"]
    temp = next(n for n, v in model.variables.items() if v.type == "numeric" and v.unit == "°C")
    assert "turn_temp_cw" in toggles[temp]


# a hot-air station whose FINE key flips between two nozzles, each with its own heat range
STATION = """
Vapora HG-2 hot air station

  Panel: ⏻   FINE   AIR   HEAT knob

  ⏻        standby / on
  FINE     heat control by WIDE or by FINE nozzle
  AIR      air pump on / off
  HEAT     turn: heat

NOZZLES

  WIDE    the heat is the air temperature at the wide nozzle. Range 100-450 °C.
          One click of the HEAT knob changes it by 10 °C. Starting value 300 °C.
  FINE    the heat is the temperature at the fine tip. Range 150-400 °C.
          One click changes it by 5 °C. Starting value 250 °C.

Press FINE to change from one nozzle mode to the other; the lamp shows WIDE or FINE.

A change of mode resets the heat to the mode's starting value and switches the air off.
"""
STATION_ACTIONS = ["press_power", "press_fine", "press_air", "turn_heat_cw", "turn_heat_ccw"]


def test_a_key_named_as_one_of_two_modes_chooses_them_and_each_has_its_range() -> None:
    model = read_manual(STATION, STATION_ACTIONS).model
    mode = model.variables["fine"]
    assert mode.values == ["wide", "fine"]
    assert mode.show == {"wide": "WIDE", "fine": "FINE"}
    heat = next(v for v in model.variables.values() if v.depends_on == "fine")
    assert heat.cases["wide"].ranges == [(100, 450, 10)]
    assert heat.cases["fine"].ranges == [(150, 400, 5)]
    assert (heat.cases["wide"].initial, heat.cases["fine"].initial) == (300, 250)
    step = next(f for steps in model.features.values() for f in steps if f.variable == "fine")
    assert step.set == {"air": "off"}  # "switches the air off": that, and no other reset
    assert step.reset == []


# a desk lamp whose keys print a sign glued to the name, and whose chart marks its start
LAMP = """
Lumo DL-4 desk lamp

  Keys: ⏻   [GLOW+] [GLOW−]   EFFECT

SAFETY

Do not look into the light. Keep the lamp away from water. Unplug it before cleaning.

BRIGHTNESS

The lamp remembers its brightness. GLOW + and GLOW − set the brightness from 0 to 20.

EFFECT

Each press of EFFECT selects the next effect:

    FADE  >  WAVE  >  SPARK  >  FADE ...

    FADE   - the light fades in and out slowly (factory setting)
    WAVE   - a wave runs round the shade
"""


def test_a_key_printed_with_a_glued_sign_is_found_spaced_and_a_bracket_marks_its_clause() -> None:
    model = read_manual(
        LAMP, ["press_power", "press_glow_up", "press_glow_down", "press_effect"]
    ).model
    glow = next(v for n, v in model.variables.items() if n.startswith("glow"))
    assert tuple(glow.ranges[0][:2]) == (0, 20)
    effect = next(v for n, v in model.variables.items() if n.startswith("effect"))
    assert effect.initial == "fade"
