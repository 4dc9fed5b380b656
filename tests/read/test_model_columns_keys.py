"""A comparison table's own column found by its row of keys (the panel's keys are known)."""

from apbot.read.model_columns import is_type_number, own_column
from apbot.read.text import parse_manual

_MANUAL = """# Bottle steriliser, models ST-10, ST-20 and ST-30 PRO

| | ST-10 | ST-20 | ST-30 PRO |
|---|---|---|---|
| Buttons | ON/OFF | ON/OFF, DRY, TIMER | same as ST-20 + UV |
| Drying times | none | 30, 45 or 60 min | 30 to 90 min |

Press DRY to choose how long the bottles dry.
"""


def _table(keys: list[str]) -> int | None:
    manual = parse_manual(_MANUAL, keys)
    row = next(u for u in manual.units if u.cells and u.cells[0] == "Drying times")
    return own_column(row.header, manual.lines, manual.units, keys)


def test_the_column_whose_keys_are_the_panels_is_its_own() -> None:
    assert _table(["on", "dry", "timer"]) == 2  # ST-20: every key it names is on this panel


def test_a_sister_naming_a_key_the_panel_lacks_is_not_chosen() -> None:
    # with a UV key on the panel, ST-30 PRO (ST-20's keys + UV) names the most of its keys
    assert _table(["on", "dry", "timer", "uv"]) == 3


def test_no_keys_row_match_chooses_nothing() -> None:
    assert _table(["start", "mode"]) is None


def test_an_all_capitals_word_after_the_type_number_is_still_a_model() -> None:
    assert is_type_number("ST-30 PRO") and is_type_number("CM-3 Plus")
    assert not is_type_number("P1")
