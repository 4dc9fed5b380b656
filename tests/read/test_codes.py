"""Programme codes named by the manual's chart, each on a small manual written in our own words."""

from __future__ import annotations

from apbot.read import read_manual

# a chart whose names carry a remark in brackets, one of them wrapped onto the next line
REMARKS = """NORDA SM-2 STEAM OVEN
Operating instructions

KEYS
  PROG      next programme: C1 → C2 → C3 → C1
  START     starts the programme

PROGRAMMES

  | Code | Programme          | Temperature |
  |------|--------------------|-------------|
  | C1   | Gentle steam       | 70 °C       |
  |      | (fish, vegetables) |             |
  | C2   | Full steam (meat)  | 100 °C      |
  | C3   | Reheat             | 90 °C       |

Press PROG until the code of the programme you want is shown, then press START.
"""
REMARKS_ACTIONS = ["press_prog", "press_start"]


def test_a_chart_name_s_remark_in_brackets_is_not_part_of_the_name() -> None:
    model = read_manual(REMARKS, REMARKS_ACTIONS).model
    (spec,) = [v for v in model.variables.values() if "C1" in (v.show or {}).values()]
    assert list(spec.values or []) == ["gentle steam", "full steam", "reheat"]
