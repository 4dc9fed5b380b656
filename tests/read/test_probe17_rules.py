"""Rules from probing the reader with short manuals of our own (probe17): each rule on a small
manual written in different words from the probe that found it."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual
from apbot.read.drawn_pieces import drawn_piece_marks
from apbot.read.table_transposed import key_row_marks


def _values(text: str, actions: list[str], variable: str) -> list[str] | None:
    """The values read for one variable (None for a number or a time)."""
    model: dict[str, Any] = read_manual(text, actions).model.model_dump(mode="json")
    return model["variables"][variable].get("values")


# a juicer whose panel drawing sits in a code fence: one line, pieces split by bars, each key's
# lamps printed after its name in capitals
JUICER = """# Pressa J-2 Slow Juicer

## Panel

```
  SWITCH   |   PULP   NONE  FINE  THICK   |   REVERSE   |   SPIN   GENTLE  BRISK
```

A lamp lights beside the chosen word.

## Use

Press SWITCH to turn the juicer on. Press PULP until the lamp you want lights. Press SPIN
to change how hard the screw turns. Hold REVERSE to free a blocked screw.
"""
JUICER_KEYS = ["press_switch", "press_pulp", "hold_reverse", "press_spin"]


def test_a_key_piece_of_a_drawn_panel_line_lists_its_lamps() -> None:
    assert _values(JUICER, JUICER_KEYS, "pulp") == ["none", "fine", "thick"]
    assert _values(JUICER, JUICER_KEYS, "spin") == ["gentle", "brisk"]


def test_drawn_pieces_need_the_key_first_and_capitals_after() -> None:
    line = "  SWITCH   |   PULP   NONE  FINE  THICK   |   REVERSE   |   SPIN   GENTLE  BRISK"
    others = {"switch", "reverse", "spin"}
    assert drawn_piece_marks(line, set(), {"pulp"}, others) == ["NONE", "FINE", "THICK"]
    # the keys drawn side by side, no lamps: nothing
    assert drawn_piece_marks("MENU  TIMER | START | STOP", set(), {"menu"}, {"timer"}) is None
    # a piece that goes on in lower case is a caption, not lamps
    assert drawn_piece_marks("PULP sets pulp | A | B", set(), {"pulp"}, set()) is None
    # no bars: no drawing
    assert drawn_piece_marks("PULP  NONE  FINE", set(), {"pulp"}, set()) is None


def test_a_three_letter_key_name_alone_in_the_first_cell_leads_its_row() -> None:
    row = ("ION", "WEAK", "NORMAL", "STRONG")
    assert key_row_marks(row, set(), (), False, {"ion"}) == ["WEAK", "NORMAL", "STRONG"]
    # a short word inside a longer cell is too common to tie it to the key
    assert key_row_marks(("ION lamp", "WEAK", "STRONG"), set(), (), False, {"ion"}) is None


def test_a_numbered_row_under_a_spanning_heading_is_the_key_row() -> None:
    header = ("#", "Control", "Steps", "", "", "")
    row = ("2", "BLADE", "SLOW", "PULSE", "FAST", "ICE")
    marks = key_row_marks(row, {"blade"}, header, False)
    assert marks == ["SLOW", "PULSE", "FAST", "ICE"]
    # a header naming each column is a record per key, no marks
    named = ("#", "Control", "Lamp", "Sound", "Display", "Colour")
    assert key_row_marks(row, {"blade"}, named, False) is None


ROASTER = """# Kaffeko R-1 Home Bean Roaster

## Keys

Four keys: MAINS, HOT, DRUM and ROAST.

| HOT | MILD | MEDIUM | STRONG | CHAR |
|-----|------|--------|--------|------|

| Nr. | Key  | Choices |        |       |
|-----|------|---------|--------|-------|
| 1   | DRUM | SLOW    | NORMAL | QUICK |

Press ROAST to begin.
"""


def test_a_roaster_reads_a_short_key_row_and_a_numbered_row() -> None:
    keys = ["press_mains", "press_hot", "press_drum", "press_roast"]
    assert _values(ROASTER, keys, "hot") == ["mild", "medium", "strong", "char"]
    assert _values(ROASTER, keys, "drum") == ["slow", "normal", "quick"]


# a plain-text manual whose sections are numbered, the number set apart by a wide gap
HONEY = """HIVEMATE  HX-2  HONEY EXTRACTOR

1  Spinning
The drum has three swirls: Gentle, Even and Brisk. Press SWIRL to step through them.

2  Heating
Press WARMTH to switch the jacket heater on or off.
"""


def test_a_wide_gapped_section_number_and_short_title_is_a_heading() -> None:
    from apbot.read.text import parse_manual

    units = parse_manual(HONEY).units
    assert any(u.text == "1  Spinning" and u.heading == "1  Spinning" for u in units)
    assert all(not u.text.startswith("2  Heating Press") for u in units)
    # a numbered step with one space stays a step
    steps = parse_manual("How to clean\n\n1 Rinse the jar.\n2 Dry it.\n").units
    assert not any(u.heading.startswith(("1 ", "2 ")) for u in steps)


def test_a_noun_said_once_after_a_title_pair_belongs_to_both() -> None:
    from apbot.read.value_lists import find_list

    found = find_list("Use the BRUSH key to pick Soft or Firm bristles.")
    assert found is not None and found[0] == ["Soft", "Firm"]
    # two words in capitals, or three names, are left to the other rules
    assert find_list("Pick Soft or Firm Extra bristles.") != (["Soft", "Firm"], "list")
