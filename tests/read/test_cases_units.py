"""A setting whose range depends on the unit a selector chooses: one case per unit, each with
its own range, step and starting value, from manuals written for these tests."""

from __future__ import annotations

from apbot.model.schema import NumericVariable
from apbot.read import read_manual

BATH = """
FOOTBATH FB-9

KEYS

  No.  Key     Touch                          Touch and hold 3 seconds
  ---  ------  -----------------------------  ------------------------
  1    HEAT    heating on / off               change °C / °F
  2    ▲       temperature one degree up      --
  3    ▼       temperature one degree down    --

THE DISPLAY

  Symbol     Meaning
  ---------  ------------------------------------
  °C or °F   the scale the temperature is shown in

TEMPERATURE

Touch ▲ or ▼ to change the temperature by one degree per touch.
In °C: 30 to 44 degrees. In °F: 86 to 111 degrees. The value stops at the ends.

CELSIUS OR FAHRENHEIT

Touch and hold HEAT for 3 seconds: the scale lamp changes from °C to °F (or back). The
temperature returns to the start value of the new scale: 38 °C, or 100 °F.
"""

SOFTENER = """
# Softener WS-4

## Keys

| Key | Use |
|---|---|
| HARD | Touch: set the hardness with ▲ / ▼. Hold 3 s: the next unit, °dH / ppm / gpg. |
| ▲ / ▼ | Raise or lower the value. |

## Hardness

Touch HARD, then ▲ or ▼. The range depends on the unit:

   °dH:  1 to 30, in steps of 1       (factory value 12 °dH)
   ppm:  20 to 500, in steps of 10    (factory value 210 ppm)
   gpg:  1 to 30, in steps of 1       (factory value 12 gpg)

## Hardness unit

Hold HARD for 3 seconds. The unit lamp moves on to the next unit, in the order
°dH -> ppm -> gpg -> °dH.
"""

ACTIONS_BATH = ["press_heat", "hold_heat", "press_up", "press_down"]
ACTIONS_SOFT = ["press_hard", "hold_hard", "press_up", "press_down"]


def _by_unit(text: str, actions: list[str], name: str) -> tuple[str | None, dict]:
    var = read_manual(text, actions).model.variables[name]
    assert isinstance(var, NumericVariable)
    return var.depends_on, {k: (c.ranges, c.initial) for k, c in (var.cases or {}).items()}


def test_a_temperature_with_one_range_per_scale() -> None:
    model = read_manual(BATH, ACTIONS_BATH).model
    var = model.variables["temperature"]
    assert var.depends_on is not None
    cases = {k: ([list(r) for r in c.ranges], c.initial) for k, c in var.cases.items()}
    assert sorted(cases.values()) == [([[30, 44, 1]], 38), ([[86, 111, 1]], 100)]


def test_a_hardness_with_one_range_and_step_per_unit() -> None:
    model = read_manual(SOFTENER, ACTIONS_SOFT).model
    hard = next(
        v for n, v in model.variables.items() if n.startswith("hard") and v.type == "numeric"
    )
    cases = {k: ([list(r) for r in c.ranges], c.initial) for k, c in hard.cases.items()}
    assert sorted(cases.values()) == [
        ([[1, 30, 1]], 12),
        ([[1, 30, 1]], 12),
        ([[20, 500, 10]], 210),
    ]
