"""Reading rules on small manuals written for the test: each says one thing one way."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.model.validate import check_model
from apbot.read import read_manual

WASHER = """
# Panel

| Key | What it does |
|---|---|
| POWER | Switches the washer on and off. |
| MODE | Chooses the wash mode. |
| TEMP | Sets the temperature, adjusted with + and −. |
| START | Starts the wash. |

Each press of MODE moves to the next mode: ECO → FAST → NIGHT → back to ECO.

| Mode | Temperature |
|---|---|
| ECO | 30 – 60 °C |
| FAST | 40 – 90 °C |
| NIGHT | 20 – 40 °C |

Press TEMP, then + or − to change the temperature in 10 °C steps.
To lock the keys, press and hold + and − together for 3 seconds; LOCK appears.
"""
WASHER_ACTIONS = [
    "press_power", "press_mode", "press_temp", "press_plus", "press_minus", "press_start",
    "hold_plus_minus",
]  # fmt: skip


def test_a_mode_cycle_a_dependent_range_a_stepping_pair_and_a_lock():
    model = read_manual(WASHER, WASHER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.variables["mode"].values == ["eco", "fast", "night"]
    temp = model.variables["temp"]
    assert temp.depends_on == "mode"
    assert temp.cases["fast"].ranges == [(40, 90, 10)]
    steps = model.features["set_temp"]
    assert steps[0].actions == ["press_temp"] and set(steps[1].actions) == {
        "press_plus",
        "press_minus",
    }
    assert model.features["child_lock"][0].actions == ["hold_plus_minus"]
    assert model.variables["child_lock"].show == {"off": "", "on": "LOCK"}
    guards = {g.name: g for g in model.guards}
    assert guards["power off"].only == ["press_power"]


COOKER = """
## Program pads

| Program | Cooking time |
|---|---|
| RICE | automatic |
| SOUP | 0:30 – 3:00 |
| STEW | 0:30 – 8:00 |

Touch a program pad, then START. The RUN lamp lights and the display shows RUN.
"""


def test_pads_listed_in_a_programme_table_select_one_programme():
    model = read_manual(COOKER, ["press_rice", "press_soup", "press_stew", "press_start"]).model
    program = model.variables["program"]
    assert program.values == ["rice", "soup", "stew"]
    (step,) = model.features["soup"]
    assert step.actions == ["press_soup"] and step.variable == "program"
    assert step.effect is not None and getattr(step.effect, "to", None) == "soup"


def test_silence_is_a_recorded_guess_and_still_a_checked_model():
    reading = read_manual("Nothing about the keys here.", ["press_a", "press_b", "turn_c_cw"])
    assert not [p for p in check_model(reading.model) if p.severity == "error"]
    assert reading.report.guesses and all(n.line is None for n in reading.report.guesses)


KEYPAD_HOB = """
# The panel

  ON/OFF     LEVEL     TIMER          [ display ]

* **0 – 9** — number keys.
* **LEVEL** — each press raises the power level, 1 to 9, then back to 1.
* **TIMER** — the keypad then takes the cooking time in minutes.

## Programmes

PROGRAMME knob positions, clockwise from OFF: OFF · Simmer · Boil · Fry · Warm Default temp.

To set the delay, press DELAY, then + / −.

| Data | Value |
|---|---|
| Timer | 1 min – 3 h |
"""
KEYPAD_ACTIONS = [
    "press_on_off", "press_level", "press_timer", "turn_programme_cw", "turn_programme_ccw",
    "press_delay", "press_plus", "press_minus",
    *[f"press_{d}" for d in range(10)],
]  # fmt: skip


def test_the_keypad_names_no_range_and_a_panel_drawing_makes_no_toggle() -> None:
    reading = read_manual(KEYPAD_HOB, KEYPAD_ACTIONS)
    model = reading.model
    timer = model.variables["timer"]
    # "0 – 9 — number keys" is the keypad; "1 min – 3 h" the timer's range, in minutes
    assert timer.type == "time" and timer.entry is not None
    assert str(timer.ranges[0][0]) == "00:01:00" and str(timer.ranges[-1][1]) == "03:00:00"
    # ON/OFF in the drawing of the panel is a key's name, not "on and off" wording for TIMER
    assert not any(
        getattr(step.effect, "kind", step.effect) == "toggle" and step.variable == "timer"
        for steps in model.features.values()
        for step in steps
    )


def test_a_dotted_run_in_flattened_text_and_a_list_of_keys() -> None:
    model = read_manual(KEYPAD_HOB, KEYPAD_ACTIONS).model
    programme = next(v for n, v in model.variables.items() if "programme" in n)
    assert programme.values == ["off", "simmer", "boil", "fry", "warm"]
    # "DELAY, then + / −" lists keys, not the delay's values
    delay = model.variables["delay"]
    assert delay.type != "discrete" or "+" not in delay.values


def test_a_timer_key_finds_its_range_under_the_name_its_legend_gives_it() -> None:
    manual = """
TIMER   Push to set the Delay Start timer.
+ / -   Used with TIMER to change the delay.

SPECIFICATIONS   Rated power: 650 W   Delay start: up to 15 hours
"""
    model = read_manual(manual, ["press_timer", "press_plus", "press_minus"]).model
    timer = model.variables["timer"]
    assert max(float(v) for v in all_values(timer)) == 15  # hours, not a guessed 1–60 min


def test_a_range_told_by_the_first_press_and_the_longest_setting() -> None:
    manual = """
## Reserve

1. Tap **RESERVE**. The display shows how long from now the rice will be ready.
   The first tap gives 0.5 h; keep tapping to add more time.
   The longest reservation is 24 h.
"""
    model = read_manual(manual, ["press_reserve", "press_start"]).model
    values = [float(v) for v in all_values(model.variables["reserve"])]
    assert values[0] == 0.5 and values[1] == 1.0 and values[-1] == 24


def test_an_arrow_list_ends_at_the_comma_and_a_shared_pair_keeps_its_own_setting() -> None:
    manual = """
* **SPEED** — fan speed.
* **▲ / ▼** — change the target humidity. While the TIMER is being set they change the hours.
* **TIMER** — switches the unit off after a number of hours.

Press **SPEED** to go to the next fan speed. The order is LOW → MED → HIGH, and from HIGH
the next press brings you back to LOW.
"""
    model = read_manual(manual, ["press_speed", "press_timer", "press_up", "press_down"]).model
    assert model.variables["speed"].values == ["low", "med", "high"]
    assert "humidity" in model.variables  # the pair's own setting, not the timer's


def test_care_is_an_aside_section_only_as_the_sections_own_word() -> None:
    from apbot.read.shapes import ASIDE_HEADING

    for heading in ("Care and cleaning", "7 CARE", "Cleaning and care", "Care & maintenance"):
        assert ASIDE_HEADING.search(heading), heading
    for heading in ("Easy Care", "Baby care programme", "4.2 Easy care", "Care programme"):
        assert not ASIDE_HEADING.search(heading), heading


def test_water_calls_for_millilitres_only_as_the_settings_own_noun() -> None:
    from apbot.read.shapes import _fits

    assert _fits("°dH", ["water_hardness"])  # a hardness is in its own unit
    assert not _fits("°dH", ["water"]) and _fits("ml", ["water"])
    assert _fits("l", ["amount", "water"]) and not _fits("W", ["water_amount"])
