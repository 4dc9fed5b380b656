"""A display legend row "ON 18:00   the switch-on time is being set", on a small manual written
in our own words: the setting shows the word and its value while it is set, and a key's name
with ON in it ("ON TIME or OFF TIME first" in a troubleshooting row) makes no on/off switch."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

TIMER = """LUMO T-1 SOCKET TIMER
Instructions

KEYS
  CLOCK      hold 3 s: set the clock
  ON TIME    set the switch-on time
  OFF TIME   set the switch-off time
  HOUR       one hour later
  MIN        one minute later

DISPLAY
    CLOCK 07:45  the clock is being set
    ON 18:00     the switch-on time is being set
    OFF 23:00    the switch-off time is being set

Press ON TIME, then HOUR and MIN to set the time the socket switches on.

TROUBLESHOOTING
    HOUR / MIN do nothing      select CLOCK (hold 3 s), ON TIME or OFF TIME first
    socket stays dark          mode is ON or OFF: press MODE until AUTO
"""
ACTIONS = ["hold_clock", "press_on_time", "press_off_time", "press_hour", "press_min"]


def test_a_legend_row_gives_the_setting_its_display_text() -> None:
    model = read_manual(TIMER, ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    shows = {n: v.show for n, v in model.variables.items() if v.type == "time"}
    assert "ON {value}" in shows.values() and "OFF {value}" in shows.values()


def test_a_troubleshooting_row_makes_no_switch_of_a_time_key() -> None:
    model = read_manual(TIMER, ACTIONS).model
    assert not [n for n, v in model.variables.items() if v.type == "discrete" and "on_" in n]
