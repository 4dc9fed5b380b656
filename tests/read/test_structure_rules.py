"""Rules about a manual's structure (page furniture, plain-text headings, specification tables,
the panel's printed legend, sections that only mention values), each on a small manual written
the way a commercial manual reads once converted to text."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.text import parse_manual

# a washer-dryer manual flattened from a PDF: running headers, page numbers, plain headings
WASHER = """AQUAVALE WD-7
Washer-Dryer  ·  Instructions for use

CONTENTS
1 Safety ................ 2      4 Daily use ............ 5
2 Installation .......... 3      5 Troubleshooting ...... 7

1 SAFETY
WARNING Risk of electric shock. Have the machine connected by a qualified person to an earthed
socket (220–240 V, 10 A). Children from 8 years may use the machine under supervision.
Never use the machine if the door seal, the cable or the hose is damaged. Do not wash items
soiled with petrol, solvents, wax or cooking oil: they can ignite while drying.

AQUAVALE WD-7                                                        - 2 -


AQUAVALE WD-7                                                 Instructions for use
2 INSTALLATION
Remove the three transit bolts at the rear before first use and keep them for moving. The
machine must stand level; adjust the feet with a 17 mm spanner.

AQUAVALE WD-7                                                        - 3 -


AQUAVALE WD-7                                                 Instructions for use
4 DAILY USE
4.1 Choosing the water level
Press WATER LEVEL to select the amount of water. Each press selects the next level; after the
highest level the lowest comes back. Choose a level that lets the laundry move
freely in the drum. For a very small load

AQUAVALE WD-7                                                        - 5 -


AQUAVALE WD-7                                                 Instructions for use
choose the lowest level.
4.2 Starting
Press START/PAUSE. The drum turns and water flows in.

5 TROUBLESHOOTING
Problem Possible cause Remedy Water stays in the drum Drain blocked Clean the pump filter
Drum does not turn Load too small Select LOW, MID or HIGH and restart

AQUAVALE WD-7                                                        - 7 -


TECHNICAL DATA
| Supply | 220–240 V ~ 50 Hz |
| Water levels | 18, 24, 30, 36 and 42 L |
| Dimensions | 595 × 565 × 850 mm |
"""


def test_page_headers_and_numbers_are_dropped_and_a_broken_sentence_goes_on() -> None:
    units = parse_manual(WASHER).units
    texts = [u.text for u in units]
    assert not any("- 5 -" in t or "WD-7 Instructions for use" in t for t in texts)
    assert any(t.startswith("For a very small load choose the lowest level.") for t in texts)


def test_plain_text_headings_start_sections() -> None:
    units = parse_manual(WASHER).units
    headings = [u.text for u in units if u.text == u.heading]
    assert "4.1 Choosing the water level" in headings
    assert "5 TROUBLESHOOTING" in headings and "TECHNICAL DATA" in headings
    # numbered steps and ordinary sentences stay sentences
    assert not any(h.startswith("Press") for h in headings)


def test_a_specification_row_led_by_the_settings_name_gives_its_values() -> None:
    actions = ["press_water_level", "press_start_pause"]
    model = read_manual(WASHER, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    (var,) = [v for v in model.variables if "water" in v]
    assert all_values(model.variables[var]) == [18, 24, 30, 36, 42]
    # a rating in volts is no range of a setting, and a remedy lists no setting's values
    assert not any(
        set(map(str, all_values(spec))) & {"220", "240", "low", "mid", "high"}
        for spec in model.variables.values()
    )


KETTLE = """# Brewline VK-2 variable-temperature kettle

## Important safety instructions

Fill between the MIN and MAX marks. Never immerse the base in water. The kettle switches
off when it boils dry. Keep the cord away from the hot-plate of a cooker or a 2000 W heater.

## Parts

| Part | What it does |
|---|---|
| **ON** | Starts heating. |
| **VOLUME ring** | Turn it to set how much water is poured. |

## Technical data

| Item | Value |
|---|---|
| Rated power | 1850–2200 W |
| Volume per pour | 100–900 ml |
| Cable length | 0.75 m |
"""


def test_a_quantity_takes_a_range_in_its_own_unit_from_the_specifications() -> None:
    actions = ["press_on", "turn_volume_cw", "turn_volume_ccw"]
    model = read_manual(KETTLE, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    values = all_values(model.variables["volume"])
    assert values[0] == 100 and values[-1] == 900  # ml, not the watts of the row above


CABINET = """GLOWMAX SC-4 UV CABINET
Instruction Manual

PANEL
MODE   OFF   QUICK   FULL   KEEP        HOURS  - / +     GO
MODE knob   Large knob on the left; it clicks into the positions printed round it.
HOURS knob   Turn it to set the storage time.

FOR EXAMPLE
Example: a bottle was rinsed at 6 pm. You pick QUICK, FULL and KEEP in turn to compare.

PROBLEMS
Nothing happens Knob at OFF Select QUICK, KEEP or DRY
"""


def test_positions_printed_beside_a_knobs_name_on_the_panel_are_its_values() -> None:
    actions = ["turn_mode_cw", "turn_mode_ccw", "turn_hours_cw", "turn_hours_ccw", "press_go"]
    model = read_manual(CABINET, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.variables["mode"].values == ["off", "quick", "full", "keep"]


def test_a_worked_example_and_a_remedy_give_no_values() -> None:
    text = CABINET.replace("MODE   OFF   QUICK   FULL   KEEP        HOURS", "MODE  HOURS  GO  DRY")
    actions = ["turn_mode_cw", "turn_mode_ccw", "turn_hours_cw", "turn_hours_ccw", "press_go"]
    model = read_manual(text, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    mode = model.variables["mode"]
    assert mode.type != "discrete" or not {"quick", "full", "keep"} <= set(mode.values or [])


# a catering hob's manual: a numbered key legend and an output table flattened with spaces
HOB = """4 CONTROL PANEL
[ON/OFF]  [POWER LEVEL]  [TIMER]   [ 8.8.8.8 ]   [+] [-]      7 8 9
1 ON/OFF   2 WATT   3 TIMER   4 keys 0-9   5 + and -   6 START

5 SETTING THE OUTPUT
Tap WATT, then change the output with + and -. The output can also be typed in.

Table 2  Output levels  Band  Settings (W)  Step
Low  400 · 600 · 800 · 1000 · 1200  200 W
High  1500 · 2000 · 2500 ·
3000  500 W

9 SAFETY
Never leave hot oil unattended above 2000 W; keep 5 · 10 · 15 cm clear of walls (W).
"""
HOB_ACTIONS = ["press_on_off", "press_watt", "press_timer", "press_plus", "press_minus"]
HOB_ACTIONS += ["press_start"] + [f"press_{d}" for d in range(10)]


def test_the_runs_of_a_table_headed_by_a_quantitys_unit_are_its_settings() -> None:
    model = read_manual(HOB, HOB_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    values = all_values(model.variables["watt"])
    assert values == [400, 600, 800, 1000, 1200, 1500, 2000, 2500, 3000]


def test_keys_0_9_in_a_legend_name_the_keypad_not_a_range() -> None:
    model = read_manual(HOB, HOB_ACTIONS).model
    for name, spec in model.variables.items():
        if spec.type == "numeric" and name != "watt":
            assert all_values(spec)[-1] != 9 or all_values(spec)[0] != 0, name


# a washing machine's settings page set in two columns, as a PDF converter leaves it
COLUMNS = """6. SETTINGS
6.1 Spin Press the SPIN button to lower      Rinse Hold: the water of the last rinse
the spin speed. Each press gives a lower     stays in the drum, so that nothing creases.
speed. The lamps show 1200 1000 800 600      Drain it with the Spin/Drain programme
and the symbol Rinse Hold. After the last    once you are back.
one the highest speed comes back.
6.2 Child lock Hold SPIN and RINSE         To release it, hold the same two buttons
together for 3 seconds: CL appears and      again for 3 seconds; CL goes off and the
every button is locked.                     buttons work again.
"""
COLUMN_ACTIONS = ["press_spin", "press_rinse", "hold_spin_and_rinse", "press_start"]


def test_two_columns_side_by_side_are_read_one_after_the_other() -> None:
    texts = [u.text for u in parse_manual(COLUMNS).units]
    assert "6.1 Spin Press the SPIN button to lower the spin speed." in texts
    assert any(t.startswith("Rinse Hold: the water of the last rinse stays in the") for t in texts)


def test_a_keys_lamps_showing_numbers_make_it_an_amount_not_the_two_key_holds_toggle() -> None:
    model = read_manual(COLUMNS, COLUMN_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert all_values(model.variables["spin"]) == [600, 800, 1000, 1200]
    assert model.features["child_lock"][0].actions == ["hold_spin_and_rinse"]


# a domino hob: one sensor per zone, touched for the zone and held for its timer
DOMINO = """# Vellmar HZ-2 Domino Hob

## Safety

Stay with the pan when frying; oil overheats fast. Do not use the hob if the glass is cracked.
The key lock keeps children from changing a setting.

## Sensors

| Sensor | Use |
|---|---|
| ON/OFF | Hob on / off |
| FRONT | Selects the front zone (touch) · front timer (touch and hold) |
| BACK | Selects the back zone (touch) · back timer (touch and hold) |
| − / + | Change the value of whatever is selected |
| LOCK | Key lock (touch and hold) |

Touch a zone's sensor, then use + and − to set its heat from 0 to 9.
"""
DOMINO_ACTIONS = ["press_on_off", "press_front", "press_back", "hold_front", "hold_back"]
DOMINO_ACTIONS += ["press_minus", "press_plus", "hold_lock"]


def test_a_keys_hold_sets_the_timer_its_legend_names_and_the_lock_is_the_lock_key() -> None:
    model = read_manual(DOMINO, DOMINO_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.features["child_lock"][0].actions == ["hold_lock"]
    timer = model.variables["front_timer"]
    assert timer.type == "time"
    (feature,) = [steps for steps in model.features.values() if steps[0].actions == ["hold_front"]]
    assert set(feature[1].actions) == {"press_minus", "press_plus"}
    heat = model.features["set_front"]  # the touch still sets the zone's own amount
    assert heat[0].actions == ["press_front"] and model.variables["front"].type == "numeric"


# a portable hob with one knob that the timer borrows and that otherwise sets the temperature
KNOB = """# Solvik PH-1 Portable Induction Hob

## Safety notes

Never heat an empty pan. Keep the air vents free. Persons with a pacemaker should ask a doctor.

## Controls

- **POWER** — switches the hob on and off.
- **TIMER** — hands the knob over to the timer for the next turns.
- **Knob** — turning clockwise raises the value shown, anticlockwise lowers it.

## Setting the temperature

Turn the knob. Each click changes the temperature by 10 °C, from 60 °C to 240 °C.

## Timer

Press **TIMER**, then turn the knob to set 1–180 minutes; press **TIMER** again to go back.
"""
KNOB_ACTIONS = ["press_power", "press_timer", "turn_knob_cw", "turn_knob_ccw"]


def test_a_shared_knob_turned_alone_sets_the_amount_its_section_names() -> None:
    model = read_manual(KNOB, KNOB_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    temperature = all_values(model.variables["temperature"])
    assert temperature[0] == 60 and temperature[-1] == 240 and 190 in temperature
    (alone,) = model.features["set_temperature"]
    assert set(alone.actions) == {"turn_knob_cw", "turn_knob_ccw"}
    assert model.features["set_timer"][0].actions == ["press_timer"]


# a twin-tub washer: three keys stepping per-course amounts named by a table's columns
TWIN = """# Lindqvist TT-6 Twin Tub Washer

## Keys

| Key | What it does |
|---|---|
| COURSE | Chooses the course. |
| WASH | Wash time. |
| RINSE | Number of rinses. |
| DELAY | Finish later; each press adds one hour (2 to 12 hours). |
| START | Starts the course. |

### Courses

| Course | Use it for | Wash (min) | Rinses |
|---|---|---|---|
| Normal | Everyday laundry | 6 – 18 (12) | 0 – 3 (2) |
| Heavy | Work clothes | 12 – 24 (18) | 1 – 3 (3) |
| Quick | Small loads | 3 – 9 (6) | 1 – 2 (1) |

### Changing the settings

Press **WASH** or **RINSE**: every press gives the next value the course allows, and after the
largest the smallest comes back.

The timer moves in one-minute steps up to one hour, and in coarser steps after that, up to 3
hours.
"""
TWIN_ACTIONS = ["press_course", "press_wash", "press_rinse", "press_delay", "press_start"]


def test_a_key_stepped_by_every_press_is_an_amount_and_takes_the_column_of_its_name() -> None:
    model = read_manual(TWIN, TWIN_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    wash = model.variables["wash"]
    assert wash.depends_on == "course"
    (heavy,) = wash.cases["heavy"].ranges  # 12–24 min, in minutes or as a time
    assert [str(x) for x in heavy[:2]] in (["12", "24"], ["00:12:00", "00:24:00"])
    assert model.variables["delay"].depends_on is None  # "Wash (min)" is not the delay's


def test_a_range_told_twice_in_a_sentence_is_the_wider_and_minutes_step_an_hours_range() -> None:
    text = KNOB.replace(
        "then turn the knob to set 1–180 minutes; press **TIMER** again to go back.",
        "then turn the knob. The time moves one minute per click up to one hour,"
        " and in coarser steps after that, up to 3 hours.",
    )
    model = read_manual(text, KNOB_ACTIONS).model
    timer = model.variables["timer"]
    assert timer.type == "time"
    assert timer.ranges[0][1] == "03:00:00" and timer.ranges[0][2] == 60


def test_a_heading_sharing_only_a_words_start_is_no_section_of_the_key() -> None:
    text = """# Oven

| Key | Use |
|---|---|
| COOK | Cooking time, with the number keys. |
| START | Starts. |

## Cookware

- Glass: yes
- Foil: no
- Paper: short times only
"""
    actions = ["press_cook", "press_start"] + [f"press_{d}" for d in range(10)]
    model = read_manual(text, actions).model
    assert not any(
        {"glass", "foil", "paper"} & set(map(str, spec.values or []))
        for spec in model.variables.values()
        if spec.type == "discrete"
    )


def test_a_keypad_cooking_time_with_no_range_read_takes_minutes_and_seconds() -> None:
    text = """# Compact microwave

The clock runs on a 12-hour cycle, so any time from 1:00 to 12:59 can be entered.

| Key | Use |
|---|---|
| TIME COOK | Enter the cooking time with the number keys. |
| START | Starts. |
"""
    actions = ["press_time_cook", "press_start"] + [f"press_{d}" for d in range(10)]
    model = read_manual(text, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    cook = model.variables["time_cook"]
    assert cook.type == "time" and "00:02:30" in all_values(cook)  # not the clock's 1:00–12:59


def test_a_range_in_a_column_of_advice_is_no_limit() -> None:
    text = """# Countertop oven

| Key | Use |
|---|---|
| TEMP | Enter a new temperature with the number keys. |

| # | Function | Suggested use | Suggested °C |
|---|---|---|---|
| 1 | BAKE | Cakes, bread | 160–180 |
| 2 | ROAST | Meat | 180–220 |

## Technical data

Rated voltage 220–240 V ~ 50 Hz · Temperature 40–230 °C · Capacity 12 L.
"""
    actions = ["press_temp"] + [f"press_{d}" for d in range(10)]
    model = read_manual(text, actions).model
    values = all_values(model.variables["temp"])
    assert values[0] == 40 and values[-1] == 230


def test_a_list_of_times_written_h_mm_is_a_time_setting() -> None:
    text = """# Bottle steriliser

| Key | Use |
|---|---|
| DRYING | Each press moves to the next drying time. |

Drying times you can choose: 0:00 (no drying) · 0:20 · 0:40 · 1:00 · 1:30 · 2:00.
"""
    model = read_manual(text, ["press_drying"]).model
    drying = model.variables["drying"]
    assert drying.type == "time"
    assert all_values(drying) == ["00:00:00", "00:20:00", "00:40:00", "01:00:00", "01:30:00",
                                  "02:00:00"]  # fmt: skip


def _dropped(text: str) -> list[str]:
    from apbot.read.text_pages import _furniture

    lines = text.split("\n")
    return [lines[i].strip() for i in sorted(_furniture(lines))]


# steps, notes and table rows that come back on every page, each by a blank line
REPEATS = """KORVEN K-3

2. Press START

Note

  Level 1         gentle
{page}
Example

2. Press START

  Level 1         gentle
{page}
2. Press START

Note

  Level 1         gentle
{page}
"""


def test_repeated_steps_notes_and_table_rows_are_content_without_page_structure() -> None:
    assert _dropped(REPEATS.format(page="")) == []


def test_repeated_steps_notes_and_table_rows_stay_next_to_page_numbers() -> None:
    text = REPEATS.format(page="\nKORVEN K-3                                  - 1 -\n")
    assert set(_dropped(text)) == {"KORVEN K-3                                  - 1 -"}


def test_form_feeds_show_the_pages_whose_running_header_is_dropped() -> None:
    page = "KORVEN K-3 Instructions\n\nPress START to begin the {n} cycle.\n"
    text = "\f".join(page.format(n=n) for n in ("first", "second", "third"))
    texts = [u.text for u in parse_manual(text).units]
    assert not any("KORVEN" in t for t in texts)
    assert sum(t.startswith("Press START") for t in texts) == 3
    assert any("KORVEN" in u.text for u in parse_manual(text.replace("\f", "\n")).units)


LEGEND = """CONTROL PANEL
DELAY START button     Sets the finish time of the programme, up to 24 hours ahead.
TEMPERATURE button     Chooses the wash temperature of the selected programme.
SPIN button            Lowers the spin speed of the programme or turns spinning off.
"""


def test_a_legend_of_terms_each_with_its_definition_is_read_row_by_row() -> None:
    from apbot.read.text_pages import _reading_order

    lines = LEGEND.split("\n")
    order, numbers = _reading_order(lines)
    assert order == lines and numbers == list(range(1, len(lines) + 1))
    # prose set in two columns is still read down the left column first
    prose = [
        "Press the SPIN button to lower the         speed or to switch spinning off for",
        "the speed of the final spin; each press     delicate items that must not be wrung",
        "goes to the next lower speed in turn        out, such as wool and silk garments.",
    ]
    assert _reading_order(prose)[0][0:2] == [
        "Press the SPIN button to lower the",
        "the speed of the final spin; each press",
    ]


# a steamer's key legend and its display legend: the display's "FRESH ON" is a state, not a key
STEAMER = """Control panel

  POWER         switches the steamer on and off
  HOLD FRESH    switches the hold-fresh function on / off
  START         starts the steaming cycle

The display

  STEAM         steaming in progress
  FRESH ON      HOLD FRESH is switched on

Press HOLD FRESH before starting. FRESH ON appears. Press it again to switch it off.
The contents stay sterile for up to 12 hours as long as the lid stays closed.
"""


def test_a_state_the_display_shows_is_not_the_name_of_the_key_that_sets_it() -> None:
    model = read_manual(STEAMER, ["press_power", "press_fresh", "press_start"]).model
    fresh = [v for n, v in model.variables.items() if "fresh" in n]
    assert len(fresh) == 1 and fresh[0].label == "HOLD FRESH"
    assert list(all_values(fresh[0])) == ["off", "on"]
