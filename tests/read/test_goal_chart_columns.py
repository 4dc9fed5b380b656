"""A chart whose heading row gives one setting per column ("Use | Fan | Level | Lamp | Timer")
holds each setting's values under its own heading: a cell there names no code of another
column's setting. Checked on a small footbath-like model and charts written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_manual import coded_names

BATH = """
appliance: {id: bath_1, category: foot_bath, name: "Soak FB-3 foot bath", brand: S}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: pulse_button, kind: button, label: "PULSE"}
  - {id: fan_button, kind: button, label: "FAN"}
  - {id: timer_button, kind: button, label: "TIMER"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  pulse:
    type: discrete
    values: ["off", "1", "2", "3"]
  fan:
    type: discrete
    values: ["off", "on"]
  timer:
    type: time
    ranges: [["00:10:00", "01:00:00", 600]]
    format: "h:mm"
actions:
  press_power: {control: power_button}
  press_pulse: {control: pulse_button}
  press_fan: {control: fan_button}
  press_timer: {control: timer_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  pulse:
    - {actions: [press_pulse], variable: pulse, effect: next}
  fan:
    - {actions: [press_fan], variable: fan, effect: toggle}
  timer:
    - {actions: [press_timer], variable: timer, effect: next}
"""

SPACED = """
IDEAS FOR A SOAK

  Use                Fan       Pulse     Timer
  -----------------  --------  --------  ------
  Evening wind-down  on        off       20 min
  After a long walk  off       3         40 min
  Quick refresh      off       off       10 min
  Before bed         on        2         30 min
"""

PIPED = """
| Use | Fan | Pulse | Timer |
|---|---|---|---|
| Evening wind-down | on | 1 | 20 min |
| Quick refresh | off | off | 10 min |
| After a long walk | off | 3 | 40 min |
"""


def test_a_cell_under_another_heading_names_no_code() -> None:
    """ "off | 10 min" side by side: the pulse's OFF and the timer's ten minutes, not a pulse
    level called "10 min" (nor "on" a name of pulse 2)."""
    model = loads_model(BATH)
    for manual in (SPACED, PIPED):
        assert [c for c in coded_names(model, manual) if c[0] == "pulse"] == []


def test_ten_minutes_stays_a_time_on_such_a_chart() -> None:
    model = loads_model(BATH)
    goal = parse_instruction(model, "Just a quick ten-minute soak with the fan on.", SPACED)
    assert goal.get("timer") == "00:10:00"
    assert "pulse" not in goal


def test_a_numbered_chart_still_names_its_codes() -> None:
    """ "No. | Pulse" over "2 | Wave": the code column is the setting's own, so it still names."""
    model = loads_model(BATH)
    manual = "| No. | Pulse | Feel |\n|---|---|---|\n| 1 | Ripple | soft |\n| 2 | Wave | firm |"
    manual += "\n| 3 | Storm | hard |"
    names = [c for c in coded_names(model, manual) if c[0] == "pulse"]
    assert ("pulse", "2", "Wave") in names


HOB = """
appliance: {id: hob_1, category: hotplate, name: "Ember HP-1 hotplate", brand: E}
controls:
  - {id: on_button, kind: button, label: "ON/OFF"}
  - {id: step_button, kind: button, label: "STEP"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  step:
    type: discrete
    values: ["S1", "S2", "S3"]
actions:
  press_on: {control: on_button}
  press_step: {control: step_button}
features:
  power:
    - {actions: [press_on], variable: power, effect: toggle}
  step:
    - {actions: [press_step], variable: step, effect: next}
"""


def test_a_heading_naming_an_uncoded_setting_keeps_the_codes() -> None:
    """ "Power" over "S1": the chart calls the coded step "power", while the model's POWER is
    only on/off and shows no S1 — the codes are still named (dropped since 2f6953f)."""
    model = loads_model(HOB)
    for manual in (
        "| Power | Good for |\n|---|---|\n| S1 | Melting |\n| S2 | Frying |\n| S3 | Boiling |",
        "    Power   Good for\n    S1      Melting\n    S2      Frying\n    S3      Boiling",
    ):
        names = [c for c in coded_names(model, manual) if c[0] == "step"]
        assert ("step", "S2", "Frying") in names
