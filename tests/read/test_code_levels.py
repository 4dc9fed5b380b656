"""A code span is a setting's scale only where it is no range of models, parts or types."""

from apbot.read import read_manual

_PARTS = """# Fan heater

## Controls
- Press SPEED to change the fan speed.

## Parts
Fan speed motor: BM1 - BM3 series.
"""

_LEVELS = """# Fan heater

## Controls
- Press SPEED to change the fan speed (S1 ... S5).
"""


def _speed(manual: str) -> dict:
    return read_manual(manual, ["press_speed"]).model.model_dump()["variables"]["speed"]


def test_a_series_of_parts_is_no_scale() -> None:
    assert _speed(_PARTS).get("show") is None


def test_a_code_span_beside_the_setting_is_its_scale() -> None:
    speed = _speed(_LEVELS)
    assert speed["show"] == "S{value}" and speed["ranges"] == [(1, 5, 1)]
