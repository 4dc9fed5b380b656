"""A table of fault codes under a key's heading is never that key's values."""

from __future__ import annotations

from apbot.model.schema import NumericVariable
from apbot.read import read_manual
from apbot.read.fault_tables import fault_table

# a heater's timer paragraph, with the codes its display may show printed right under it
HEATER = """HEATER H-2 USER GUIDE

CONTROLS

MODE
Press to choose Low, High or Eco.

TIMER
Press to set the shut-off time, 1 to 8 hours.
The display may show these codes:

Code    Meaning
E1      Sensor fault
E2      Overheat
E3      Tilted

START
Starts heating.
"""


def test_error_codes_under_a_key_are_not_its_values() -> None:
    model = read_manual(HEATER, ["press_mode", "press_timer", "press_start"]).model
    assert isinstance(model.variables["timer"], NumericVariable)


def test_a_chart_of_programme_codes_is_no_fault_table() -> None:
    rows = [("P1", "Cotton"), ("P2", "Wool"), ("P3", "Quick")]
    assert not fault_table(("Code", "Programme"), rows)
    assert fault_table(("Code", "Meaning"), [("E1", "Sensor fault"), ("E2", "Overheat")])
    assert fault_table(("Code", "Cause"), [("F1", "Lid open"), ("F2", "No pot")])
