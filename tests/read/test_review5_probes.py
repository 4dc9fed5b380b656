"""Rules a second review found firing on ordinary text, each pinned on a small manual of our
own: a setting key whose legend ends by confirming is no bare OK key, ..."""

from __future__ import annotations

from apbot.read import read_manual

DIGITS = [f"press_{d}" for d in range(10)]

# a countertop oven whose TIMER key is typed on and pressed again to confirm
OVEN_TIMER = """
CONTROL PANEL

POWER  | Switches the oven on or off.
TIMER  | Sets the cooking time, 1 to 90 minutes: type it on the number keys, \
then press TIMER again to confirm the entry.
0 - 9  | Number keys.
START  | Starts cooking.
"""


def test_a_setting_key_whose_legend_ends_by_confirming_is_not_a_bare_ok_key() -> None:
    model = read_manual(OVEN_TIMER, ["press_power", "press_timer", "press_start", *DIGITS]).model
    typed = [
        step.variable
        for steps in model.features.values()
        for step in steps
        if "press_6" in step.actions and step.variable
    ]
    assert typed and all(model.variables[v].label.upper() == "TIMER" for v in typed)
