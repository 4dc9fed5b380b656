"""Rules of how people phrase requests (goal13), checked on models written for these tests (loaded
unchecked: only the parts a rule reads are written):
a two-channel audio amplifier, a pizza oven, a darkroom timer, a greenhouse vent, a tyre
gauge, a medication reminder, a garden irrigation valve box and a digital photo frame — none
of them in a suite. Each test would fail without its rule."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

AMPLIFIER = """
appliance: {id: amp_1, category: amplifier, name: "Tonwerk A2 two-channel amplifier", brand: T}
controls:
  - {id: a_up, kind: button, label: "A+"}
  - {id: b_up, kind: button, label: "B+"}
  - {id: bal_key, kind: button, label: "BAL"}
  - {id: mode_key, kind: button, label: "MODE"}
  - {id: timer_key, kind: button, label: "TIMER"}
  - {id: range_key, kind: button, label: "RANGE"}
variables:
  mode: {type: discrete, values: [M1, M2, M3]}
  gain_a: {type: numeric, ranges: [[0, 30, 1]], initial: 0, label: "A", show: "A{value}"}
  gain_b: {type: numeric, ranges: [[0, 30, 1]], initial: 0, label: "B", show: "B{value}"}
  balance: {type: numeric, ranges: [[-10, 10, 1]], initial: 0, label: BALANCE}
  timer: {type: discrete, values: ["30", "60", continuous], initial: "30"}
  crossover: {type: discrete, values: ["80", "160"], label: "CROSSOVER RANGE"}
actions:
  press_a: {control: a_up}
  press_b: {control: b_up}
  press_bal: {control: bal_key}
  press_mode: {control: mode_key}
  press_timer: {control: timer_key}
  press_range: {control: range_key}
features:
  gain_a:
    - {actions: [press_a], variable: gain_a, effect: next}
  gain_b:
    - {actions: [press_b], variable: gain_b, effect: next}
  balance:
    - {actions: [press_bal], variable: balance, effect: next}
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  timer:
    - {actions: [press_timer], variable: timer, effect: next}
  crossover:
    - {actions: [press_range], variable: crossover, effect: next}
"""

AMPLIFIER_MANUAL = """
MODES

  Code  Mode                  Balance     Timer    Use
  ----  --------------------  ----------  -------  ----------------
  M1    Flat                  centre      30 min   studio monitors
  M2    Loudness              left 2 60 min        quiet listening
  M3    Night                 centre      60 min   late evenings
"""


def _amp(instruction: str) -> dict:
    return parse_instruction(loads_model(AMPLIFIER, check=False), instruction, AMPLIFIER_MANUAL)


def test_lettered_channels_and_both_channels() -> None:
    assert _amp("Channel A at level twelve.") == {"gain_a": 12}
    assert _amp("Mode M2 with channel A on five.") == {"mode": "M2", "gain_a": 5}
    assert _amp("Both channels at eight.") == {"gain_a": 8, "gain_b": 8}
    assert _amp("Put the B channel at 20.") == {"gain_b": 20}


def test_a_change_said_with_its_direction() -> None:
    assert _amp("Balance down 3.") == {"balance": -3}
    assert _amp("Move the balance down by two.") == {"balance": -2}
    assert _amp("Balance down to 3.") == {"balance": 3}
    assert _amp("Balance up 4.") == {"balance": 4}


def test_wide_and_narrow_span() -> None:
    assert _amp("The wide crossover range, balance down 2.") == {"crossover": "160", "balance": -2}
    assert _amp("The narrow crossover range.") == {"crossover": "80"}
    assert _amp("The narrowest crossover range.") == {"crossover": "80"}


def test_no_time_limit_is_the_endless_timer() -> None:
    assert _amp("Loudness mode with no time limit.") == {"mode": "M2", "timer": "continuous"}
    assert _amp("No timer, please.") == {"timer": "continuous"}


def test_row_with_cells_run_together_still_names_its_code() -> None:
    # the M2 row's filter and slope run together ("35 Hz boost 6 dB"): four cells, five heads
    assert _amp("The loudness mode.") == {"mode": "M2"}


OVEN = """
appliance: {id: oven_1, category: pizza_oven, name: "Forno P1 pizza oven", brand: F}
controls:
  - {id: temp_key, kind: button, label: "TEMP"}
  - {id: menu_key, kind: button, label: "MENU"}
  - {id: start_key, kind: button, label: "START"}
variables:
  menu: {type: discrete, values: [pizzas, breads, roasts]}
  temperature: {type: numeric, unit: "°C", ranges: [[100, 400, 5]], initial: 250}
  state:
    type: discrete
    values: [idle, confirm, baking]
    show: {idle: "", confirm: "GO?", baking: "BAKE"}
actions:
  press_temp: {control: temp_key}
  press_menu: {control: menu_key}
  press_start: {control: start_key}
features:
  temperature:
    - {actions: [press_temp], variable: temperature, effect: next}
  menu:
    - {actions: [press_menu], variable: menu, effect: next}
  start:
    - {actions: [press_start], variable: state, effect: next}
"""


def _oven(instruction: str) -> dict:
    return parse_instruction(loads_model(OVEN, check=False), instruction)


def test_start_goes_past_a_confirmation() -> None:
    assert _oven("Roasts at 200 degrees and start it.") == {
        "menu": "roasts",
        "temperature": 200,
        "state": "baking",
    }


def test_hundreds_said_short() -> None:
    assert _oven("Breads at three twenty-five.")["temperature"] == 325
    assert _oven("Roasts at two fifty, start.")["temperature"] == 250


def test_a_plural_opening_is_no_order_to_start() -> None:
    assert _oven("Roasts at 200 degrees.") == {"menu": "roasts", "temperature": 200}


def test_start_baking_names_the_doing_not_a_value() -> None:
    assert _oven("Breads at 180, start baking.") == {
        "menu": "breads",
        "temperature": 180,
        "state": "baking",
    }


LATHE = """
appliance: {id: lathe_1, category: wood_lathe, name: "Drechsel W3 wood lathe", brand: D}
controls:
  - {id: speed_key, kind: button, label: "SPEED"}
variables:
  speed: {type: discrete, values: ["500", "1000", "2000"]}
actions:
  press_speed: {control: speed_key}
features:
  speed:
    - {actions: [press_speed], variable: speed, effect: next}
"""


def test_rpm_for_a_speed_of_bare_rates() -> None:
    assert parse_instruction(loads_model(LATHE, check=False), "Turn the bowl at 1000 rpm.") == {
        "speed": "1000"
    }


VENT = """
appliance: {id: vent_1, category: greenhouse_vent, name: "Klima GV greenhouse vent", brand: K}
controls:
  - {id: mode_key, kind: button, label: "MODE"}
  - {id: vent_key, kind: button, label: "VENT"}
  - {id: up_key, kind: button, label: "▲"}
variables:
  mode: {type: discrete, values: [sensor, timer]}
  delay:
    type: discrete
    depends_on: mode
    cases:
      sensor: {values: ["0", "15", "30"], initial: "15"}
  open_time:
    type: discrete
    depends_on: mode
    cases:
      timer: {values: ["6:00 AM", "6:30 AM", "7:00 AM"], initial: "6:30 AM"}
  close_time:
    type: discrete
    depends_on: mode
    cases:
      timer: {values: ["6:00 PM", "7:00 PM", "8:00 PM"], initial: "7:00 PM"}
  vent: {type: discrete, values: [closed, open], initial: open}
actions:
  press_mode: {control: mode_key}
  press_vent: {control: vent_key}
  press_up: {control: up_key}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  vent:
    - {actions: [press_vent], variable: vent, effect: toggle}
  delay:
    - {actions: [press_up], variable: delay, effect: next}
  open_time:
    - {actions: [press_up], variable: open_time, effect: next}
  close_time:
    - {actions: [press_up], variable: close_time, effect: next}
"""


def _vent(instruction: str) -> dict:
    return parse_instruction(loads_model(VENT, check=False), instruction)


def test_times_of_day_kept_as_text() -> None:
    assert _vent("Timer mode: open at 7 a.m., close at 8 p.m.") == {
        "mode": "timer",
        "open_time": "7:00 AM",
        "close_time": "8:00 PM",
    }


def test_a_state_with_its_schedule_is_no_state_now() -> None:
    got = _vent("Timer mode with the vent opening at half past six, and close it right now.")
    assert got == {"mode": "timer", "open_time": "6:30 AM", "vent": "closed"}


def test_a_state_counted_from_an_event_says_when() -> None:
    assert _vent("Sensor mode, close 30 minutes after sunset.") == {"mode": "sensor", "delay": "30"}
    assert _vent("A fifteen minute delay.") == {"delay": "15"}


def test_no_delay_is_the_lists_zero_and_shut_is_closed() -> None:
    assert _vent("Sensor mode with no delay.") == {"mode": "sensor", "delay": "0"}
    assert _vent("Shut the vent.") == {"vent": "closed"}


GAUGE = """
appliance: {id: gauge_1, category: tyre_gauge, name: "Luft TG tyre gauge", brand: L}
controls:
  - {id: unit_key, kind: button, label: "UNIT"}
  - {id: user_key, kind: button, label: "USER"}
variables:
  unit: {type: discrete, values: [psi, kPa]}
  car: {type: discrete, values: [car 1, car 2, car 3]}
actions:
  press_unit: {control: unit_key}
  press_user: {control: user_key}
features:
  unit:
    - {actions: [press_unit], variable: unit, effect: next}
  car:
    - {actions: [press_user], variable: car, effect: next}
"""


def test_pressure_units_and_ordinals_of_word_numbered_values() -> None:
    model = loads_model(GAUGE, check=False)
    assert parse_instruction(model, "Show it in kilopascals.") == {"unit": "kPa"}
    assert parse_instruction(model, "The second car, in psi.") == {"car": "car 2", "unit": "psi"}


REMINDER = """
appliance: {id: rem_1, category: pill_reminder, name: "Dosa R4 medication reminder", brand: D}
controls:
  - {id: count_key, kind: button, label: "COUNT"}
  - {id: set_key, kind: button, label: "SET"}
variables:
  count: {type: discrete, values: ["1", "2", "3"], show: "{value}x"}
  reminder_1: {type: time, ranges: [["00:00:00", "23:45:00", 900]], initial: "08:00:00"}
  reminder_2:
    type: time
    depends_on: count
    cases:
      "2": {ranges: [["00:00:00", "23:45:00", 900]], initial: "20:00:00"}
      "3": {ranges: [["00:00:00", "23:45:00", 900]], initial: "14:00:00"}
  reminder_3:
    type: time
    depends_on: count
    cases:
      "3": {ranges: [["00:00:00", "23:45:00", 900]], initial: "20:00:00"}
actions:
  press_count: {control: count_key}
  press_set: {control: set_key}
features:
  count:
    - {actions: [press_count], variable: count, effect: next}
  reminders:
    - {actions: [press_set], variable: reminder_1, effect: next}
"""


def _reminder(instruction: str) -> dict:
    return parse_instruction(loads_model(REMINDER, check=False), instruction)


def test_times_in_a_row_fill_numbered_settings_in_order() -> None:
    assert _reminder("Twice a day, at 8 am and 8 pm.") == {
        "count": "2",
        "reminder_1": "08:00:00",
        "reminder_2": "20:00:00",
    }
    assert _reminder("Three times a day, the first at 7 am and the last at 10 pm.") == {
        "count": "3",
        "reminder_1": "07:00:00",
        "reminder_3": "22:00:00",
    }


VALVES = """
appliance: {id: valve_1, category: valve_box, name: "Regen V3 irrigation valve box", brand: R}
controls:
  - {id: zone_key, kind: button, label: "ZONE"}
  - {id: onoff_key, kind: button, label: "ON/OFF"}
variables:
  zone: {type: discrete, values: [Z1, Z2, Z3]}
  zone_on:
    type: discrete
    depends_on: zone
    cases:
      Z1: {values: ["off", "on"], initial: "on"}
      Z2: {values: ["off", "on"], initial: "on"}
      Z3: {values: ["off", "on"], initial: "on"}
actions:
  press_zone: {control: zone_key}
  press_onoff: {control: onoff_key}
features:
  zone:
    - {actions: [press_zone], variable: zone, effect: next}
  zone_on:
    - {actions: [press_onoff], variable: zone_on, effect: toggle}
"""

VALVES_MANUAL = """
Each zone valve waters one bed. Press ZONE to pick a zone valve (Z1 - Z3); a zone valve
switched off keeps its times. The box has three zone valves.
"""


def test_a_setting_named_by_the_manuals_noun_and_its_own_switch() -> None:
    model = loads_model(VALVES, check=False)
    assert parse_instruction(model, "The second valve.", VALVES_MANUAL) == {"zone": "Z2"}
    assert parse_instruction(model, "Turn off zone 3.", VALVES_MANUAL) == {
        "zone": "Z3",
        "zone_on": "off",
    }


FRAME = """
appliance: {id: frame_1, category: photo_frame, name: "Bild F8 digital photo frame", brand: B}
controls:
  - {id: rot_key, kind: button, label: "ROTATE"}
  - {id: scent_key, kind: button, label: "SCENT"}
  - {id: uv_key, kind: button, label: "UV"}
variables:
  rotation: {type: numeric, unit: "°", ranges: [[0, 270, 90]], wrap: true}
  scent: {type: discrete, values: ["off", "on"]}
  uv: {type: discrete, values: [full, dim], show: {full: "UV100", dim: "UV40"}}
actions:
  press_rot: {control: rot_key}
  press_scent: {control: scent_key}
  press_uv: {control: uv_key}
features:
  rotation:
    - {actions: [press_rot], variable: rotation, effect: next}
  scent:
    - {actions: [press_scent], variable: scent, effect: toggle}
  uv:
    - {actions: [press_uv], variable: uv, effect: next}
"""

FRAME_MANUAL = """
KEYS

  SCENT    Switches the fragrance heater on or off.
  ROTATE   Turns the picture by a right angle.
"""


def _frame(instruction: str) -> dict:
    return parse_instruction(loads_model(FRAME, check=False), instruction, FRAME_MANUAL)


def test_turns_said_in_words() -> None:
    assert _frame("Show it upside down.") == {"rotation": 180}
    assert _frame("A quarter turn clockwise.") == {"rotation": 90}
    assert _frame("A quarter turn anticlockwise.") == {"rotation": 270}


def test_a_legends_qualifier_and_a_percentage_code() -> None:
    assert _frame("The fragrance on.") == {"scent": "on"}
    assert _frame("The 40 percent UV setting.") == {"uv": "dim"}


BOX_MANUAL = """
  ┌──────┬──────┬──────────────────┐
  │ Band │ Code │ Sound            │
  ├──────┼──────┼──────────────────┤
  │ SEA  │ W1   │ Surf on sand     │
  │      │ W2   │ Foghorn          │
  │ SKY  │ W3   │ Wind in pines    │
  └──────┴──────┴──────────────────┘
"""

BOX = """
appliance: {id: box_1, category: sound_box, name: "Ruhe S1 sound box", brand: R}
controls:
  - {id: sound_key, kind: button, label: "SOUND"}
variables:
  sound: {type: discrete, values: [W1, W2, W3]}
actions:
  press_sound: {control: sound_key}
features:
  sound:
    - {actions: [press_sound], variable: sound, effect: next}
"""


def test_box_drawn_tables_name_codes() -> None:
    model = loads_model(BOX, check=False)
    assert parse_instruction(model, "The foghorn, please.", BOX_MANUAL) == {"sound": "W2"}


GRIDDLE = """
appliance: {id: griddle_1, category: griddle, name: "Plancha P2 griddle", brand: G}
controls:
  - {id: mem_key, kind: button, label: "MEM"}
  - {id: size_key, kind: button, label: "SIZE"}
variables:
  memory: {type: discrete, values: [P, A, B], label: MEM}
  size: {type: discrete, values: [S, M, L], initial: S, label: SIZE}
  clock_set: {type: discrete, values: ["7:00 AM", "8:00 AM"], initial: "8:00 AM"}
actions:
  press_mem: {control: mem_key}
  press_size: {control: size_key}
features:
  memory:
    - {actions: [press_mem], variable: memory, effect: next}
  size:
    - {actions: [press_size], variable: size, effect: next}
"""


def test_a_lone_letter_is_a_value_unless_it_follows_a_number() -> None:
    """ "7 am" / "7 a.m." is half of a time said; "the stored P setting" names the value P."""
    griddle = loads_model(GRIDDLE, check=False)
    assert parse_instruction(griddle, "Use the stored P setting.") == {"memory": "P"}
    assert parse_instruction(griddle, "Set it for 7 a.m.") == {"clock_set": "7:00 AM"}
    assert parse_instruction(griddle, "Set it for seven am.") == {"clock_set": "7:00 AM"}
