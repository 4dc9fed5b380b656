"""Rules for manuals that arrive noisy (see benchmarks/manual_noise.py): tables drawn with
spaces by a converter that does not know Markdown, running text broken again."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.text_sections import boilerplate_heading

TWO_COLUMNS = """\
## The keys

The keys sit under the display. Tap them lightly.

Key                           Use
⏻ ON (left corner)            Wakes the grill or sends it to sleep.
PANINI · STEAK · FISH         Cooking modes.
VEGETABLES · TOAST · BURGER   More cooking modes.
SEAR                          Adds a burst of heat.
GO                            Starts!
"""


def test_a_two_column_table_drawn_with_spaces_gives_one_row_per_line() -> None:
    units = parse_manual(TWO_COLUMNS).units
    rows = [u for u in units if u.header == ("Key", "Use")]
    assert [u.cells[0] for u in rows] == [
        "⏻ ON (left corner)",
        "PANINI · STEAK · FISH",
        "VEGETABLES · TOAST · BURGER",
        "SEAR",
        "GO",
    ]
    assert rows[1].cells[1] == "Cooking modes."


def test_a_wrapped_two_column_legend_stays_running_text() -> None:
    legend = """\
Key                 Meaning
DRIP                Drop icon. Starts the flow; touch a second time to
(drop)              stop it before the cup is full.
HEAT                Flame icon. Heats the water again.
"""
    units = parse_manual(legend).units
    assert not any(u.header for u in units)
    assert any("stop it before the cup is full" in u.text for u in units)


def test_capitalised_words_in_a_table_are_no_two_columns_of_prose() -> None:
    # three lines split at one gap, whose right parts are short capitalised phrases: a table
    # a converter drew, not prose set side by side (read down one column, then the other)
    text = """\
Part                        Job
⏻ POWER (right corner)      Turns it on and off.
LIGHT · DARK · EXTRA DARK   Browning levels.
BAGEL · PASTRY · CRUMPET    Bread kinds.
"""
    units = parse_manual(text).units
    light = next(u for u in units if "LIGHT" in u.text)
    assert "Browning levels." in light.text


PAN = ["press_power", "press_mode", "press_temp", "press_up", "press_down", "press_start"]

BOILERPLATE_FIRST = """\
# Hearth HB-9 steam oven

## IMPORTANT SAFEGUARDS

- Never press and hold POWER while you move the oven.
- A shop may leave it in demonstration mode: press MODE to switch demonstration mode on or
  off.

## Using the oven

Press MODE to choose STEAM, BAKE or GRILL; each press moves to the next.
Press TEMP, then set 100 to 230 °C with UP and DOWN, 5 °C a step.
Press START.

## 9. Warranty and service

Hold MODE for 5 seconds to switch the service display on or off.
"""


def test_safety_and_warranty_sections_lend_no_values() -> None:
    texts = [u.text for u in parse_manual(BOILERPLATE_FIRST).units]
    assert not any("POWER" in t or "demonstration" in t or "service" in t for t in texts)
    assert any(t.startswith("Press MODE to choose") for t in texts)
    model = read_manual(BOILERPLATE_FIRST, PAN).model
    assert all_values(model.variables["mode"]) == ["steam", "bake", "grill"]


def test_a_section_heading_of_boilerplate_words_alone_is_dropped() -> None:
    for heading in (
        "IMPORTANT SAFEGUARDS",
        "2. Safety instructions",
        "Warranty and service",
        "11 Disposal & guarantee",
        "Explanation of the warning symbols",
    ):
        assert boilerplate_heading(heading), heading
    for heading in (
        "Child safety lock",
        "Specifications and guarantee",
        "Using the oven",
        "Before you call for service",
        "Care programme",
    ):
        assert not boilerplate_heading(heading), heading


ROOM_FIRST = """\
# Hearth HB-9 steam oven

## Where to put it

Use the oven at an ambient temperature between 5 °C and 35 °C. Store the appliance
frost-free (0 °C to 40 °C) when it is not used.

## Cooking

Press TEMP and set the temperature with UP and DOWN: 100 to 230 °C, 5 °C a step.
Press MODE for STEAM, BAKE or GRILL. Press START.
"""


def test_the_room_s_temperature_is_no_setting_s_range() -> None:
    temp = read_manual(ROOM_FIRST, PAN).model.variables["temp"]
    assert isinstance(temp, NumericVariable)
    assert temp.ranges is not None
    assert (temp.ranges[0][0], temp.ranges[-1][1]) == (100, 230)


def test_a_legend_with_lines_set_in_or_a_first_row_of_values_is_no_two_column_table() -> None:
    set_in = """\
Part          Job
POWER         Wakes the fan. A second press sends it to sleep and keeps
              every setting.
SPEED         Steps through LOW, MID and HIGH.
"""
    shown = """\
AUTO 24°C        Target temperature in AUTO
LOCK             Keys locked
OFF              Fan asleep
"""
    for text in (set_in, shown):
        assert not any(u.header for u in parse_manual(text).units), text


SISTER = """\
# Brisa WM-6 washer

## Delay

Press DELAY to finish the wash later: 2 to 24 hours, one hour a press.
Model WM-6 Plus only: a TURBO key sits beside DELAY. TURBO selects AUTO, 1, 2 or 3, and each
press adds 5 minutes, from 10 to 60.

## Starting

Press START.
"""


def test_a_sister_model_s_paragraph_lends_no_values_to_a_key_near_it() -> None:
    model = read_manual(SISTER, ["press_power", "press_delay", "press_start"]).model
    delay = model.variables["delay"]
    assert isinstance(delay, NumericVariable) and delay.ranges is not None
    assert (delay.ranges[0][0], delay.ranges[-1][1]) == (2, 24)


PAGED = """\
HEARTH HB-9 STEAM OVEN
Thank you for choosing the HB-9. It steams, bakes and grills.

- 1 -

HEARTH HB-9   Operating guide
KEYS ON THE PANEL
The panel is on the door, above the handle.
[ window ]

- 2 -

HEARTH HB-9   Operating guide

[ display ]
MODE        ( TEMP dial )        START
CLOCK                            STOP
MODE       Steps through STEAM, BAKE and GRILL.
CLOCK      Sets the time of day.

- 3 -

HEARTH HB-9   Operating guide
CARE
Wipe the door with a damp cloth.

- 4 -
"""


def test_a_short_line_after_a_page_break_is_no_caption_over_a_table() -> None:
    # a page break passed over leaves a blank line: "[ display ]" goes on from the page
    # before, so the panel drawing and the legend under it are no table
    units = parse_manual(PAGED).units
    assert not any(u.header for u in units)
    assert any(u.text.startswith("MODE") and "Steps through" in u.text for u in units)


def test_a_two_column_table_whose_cells_start_in_lower_case_is_still_a_table() -> None:
    text = """\
The hold time is shown in minutes.

Shown    Hold time
--       no hold (the factory setting)
30       half an hour
60       one hour
"""
    rows = [u for u in parse_manual(text).units if u.header == ("Shown", "Hold time")]
    assert [u.cells[0] for u in rows] == ["--", "30", "60"]
