"""Set16's reader rules, each on a short manual of another appliance written for the test: a
table whose first column draws the lamps of each value (the value is the next cell, and the
lamps, printed spaced, are how the display shows it)."""

from __future__ import annotations

from apbot.read import read_manual

_LAMPS_MANUAL = """\
# Brisa desk fan

## Keys

POWER — fan on / off.
SWING — the sweep angle.

## Sweep angle

Press SWING to step to the next sweep angle. After the widest it returns to the narrowest.
The angle lamps show which one is chosen:

| Lamps   | Sweep       | Use                  |
|---------|-------------|----------------------|
| ● ○ ○   | Narrow      | one person           |
| ○ ● ○   | Medium      | a desk               |
| ○ ○ ●   | Wide        | the whole room       |
"""


def _stepped(model: object, action: str) -> str:
    features = model.features.values()  # type: ignore[attr-defined]
    return next(s.variable for f in features for s in f if action in s.actions and s.variable)


def test_a_column_of_drawn_lamps_leaves_the_values_to_the_next_column() -> None:
    model = read_manual(_LAMPS_MANUAL, ["press_power", "press_swing"]).model
    spec = model.variables[_stepped(model, "press_swing")]
    assert [str(v).lower() for v in spec.values] == ["narrow", "medium", "wide"]


def test_spaced_lamps_beside_a_value_are_how_the_display_shows_it() -> None:
    model = read_manual(_LAMPS_MANUAL, ["press_power", "press_swing"]).model
    spec = model.variables[_stepped(model, "press_swing")]
    assert {str(k).lower(): v for k, v in spec.show.items()} == {
        "narrow": "●○○",
        "medium": "○●○",
        "wide": "○○●",
    }
