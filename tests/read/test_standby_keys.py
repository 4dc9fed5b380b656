"""A key the manual says works only in standby: it works while the appliance is off, and not
while it runs (a small air purifier manual written in our own words)."""

from __future__ import annotations

from apbot.read import read_manual

PURIFIER = """# Air purifier AP-7

## Keys
| Key | Function |
|---|---|
| POWER | Switches the purifier on and off (standby). |
| SPEED | Changes the fan speed: LOW, MID or HIGH. |
| DELAY | Switches the purifier on after a number of hours. |

## Delayed start
The delay can only be set while the purifier is in standby. Press DELAY repeatedly until the
number of hours you want shows (1 to 8 hours).
"""


def test_a_key_that_works_only_in_standby_works_while_off_and_not_while_on() -> None:
    model = read_manual(PURIFIER, ["press_power", "press_speed", "press_delay"]).model
    off = next(g for g in model.guards if g.when == {"power": "off"})
    assert "press_delay" in off.only
    on = [g for g in model.guards if g.when == {"power": "on"}]
    assert on and all("press_delay" not in g.only for g in on)
