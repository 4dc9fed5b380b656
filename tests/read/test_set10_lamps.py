"""Rules found on a daylight lamp's manual (set10), tested on short manuals in our own words:
figures grouped by thousands, a mode chart whose Display column follows the names, a list of
names drawn as a table without a header, figures a chart names, a legend led by callouts, and
a run of arrows that belongs to the key named right before it."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.value_lists import find_list

LAMP = """GLOWA DL-3 desk lamp

CONTROLS

  ① ⏻ - lamp on / off
  ② MODE - chooses the mode
  ③ SHADE - light colour
  ④ LEVEL - brightness

MODES

Each touch of MODE moves to the next mode:

 | Mode     | Display | What it does                     |
 |----------|---------|----------------------------------|
 | Study    | StdY    | steady cool light                |
 | Relax    | rELA    | soft light for the evening       |
 | Night    | nGt     | very dim light                   |

Order: StdY → rELA → nGt → StdY ...

SHADE

Touch SHADE to change the colour of the light:

    AMBER     2700K   like candle light
    IVORY     4000K   neutral white
    GLACIER   6000K   cool blue-white

Order: 2700K → 4000K → 6000K → 2700K ...

LEVEL

Touch LEVEL to change the brightness: 1,500 → 3,000 → 6,000 lux and back to 1,500 lux.

QUICK CARD

  Step 1: SHADE x1 · LEVEL x2 (1500 → 3000 → 6000)
"""

ACTIONS = ["press_power", "press_mode", "press_shade", "press_level"]


def _model():  # type: ignore[no-untyped-def]
    return read_manual(LAMP, ACTIONS).model


def test_thousands_are_grouped_not_decimals() -> None:
    level = _model().variables["level"]
    assert level.ranges is not None
    ends = sorted({x for r in level.ranges for x in (r[0], r[1])})
    assert ends == [1500, 3000, 6000]


def test_a_comma_before_one_or_two_digits_stays_a_decimal() -> None:
    units = parse_manual(
        "A scale\n\nThe bowl holds 1,5 kg and 2,25 l; the panel takes 2,500 W.\n"
    ).units
    assert "1,5 kg" in units[-1].text and "2,25 l" in units[-1].text and "2500 W" in units[-1].text


def test_codes_named_by_a_display_column_after_the_names() -> None:
    mode = _model().variables["mode"]
    assert mode.values == ["study", "relax", "night"]
    assert {k: v.upper() for k, v in (mode.show or {}).items()} == {
        "study": "STDY",
        "relax": "RELA",
        "night": "NGT",
    }


def test_figures_a_headerless_chart_names_become_names() -> None:
    shade = _model().variables["shade"]
    assert shade.values == ["amber", "ivory", "glacier"]
    assert shade.show == {"amber": "2700K", "ivory": "4000K", "glacier": "6000K"}


def test_callouts_start_items_and_not_a_whole_drawing_line() -> None:
    units = parse_manual(LAMP).units
    assert any(u.text.startswith("⏻ - lamp on / off") for u in units)
    drawing = parse_manual("Parts\n\n① Lid · ② Bowl · ③ Base\n④ Cord · ⑤ Feet\n").units
    assert len([u for u in drawing if "Lid" in u.text]) == 1
    assert not any(u.text.startswith("Cord") for u in drawing)


def test_a_figure_with_its_unit_leads_the_list_not_the_key_name() -> None:
    assert find_list("- SHADE 2700K → 4000K → 6000K") == (["2700K", "4000K", "6000K"], "arrows")
    # a bare figure after one key's name keeps the old reading (worked examples say "1 → 2")
    assert find_list("Each press of MODE goes on in the order 1 → 2 → 3 → 4")[0][0] != "1"


def test_arrows_after_another_keys_name_are_not_this_keys() -> None:
    shade = _model().variables["shade"]
    assert shade.values == ["amber", "ivory", "glacier"]  # not 1500 … 6000, LEVEL's


FAN = """BRIZA F-2 desk fan

USE

Touch MODE to go to the next mode: StdY → rELA → nGt → StdY ...

WHAT THE MODES DO

 | Mode     | Display | Air flow                         |
 |----------|---------|----------------------------------|
 | Steady   | StdY    | the same speed all the time      |
 | Relax    | rELA    | a soft, changing breeze          |
 | Night    | nGt     | low and quiet                    |
"""


def test_codes_read_first_take_the_names_before_a_display_column() -> None:
    mode = read_manual(FAN, ["press_power", "press_mode"]).model.variables["mode"]
    assert mode.values == ["steady", "relax", "night"]
    assert {k: v.upper() for k, v in (mode.show or {}).items()} == {
        "steady": "STDY",
        "relax": "RELA",
        "night": "NGT",
    }


GRILL = """ZESTA G-4 panini grill

KEYS

  ⏻      on / off
  BEEF   steak programme (lamp bF)
  FISH   fish programme (lamp FS)
  V      vegetable programme (lamp V)

CHOOSING A PROGRAMME

The three keys BEEF, FISH and V share one job: they choose the programme.
Touch V (lamp V) for vegetables.

Example B - V at 180 °C: touch V and wait.
"""


def test_keys_one_sentence_names_as_choosing_the_programme_are_one_choice() -> None:
    model = read_manual(GRILL, ["press_power", "press_beef", "press_fish", "press_v"]).model
    assert model.variables["programme"].values == ["beef", "fish", "v"]


def test_a_letter_key_is_its_letter_not_a_phrase_holding_it() -> None:
    from apbot.read.labels import find_labels

    manual = parse_manual(GRILL)
    labels = find_labels(manual, ["power", "beef", "fish", "v"])
    assert labels["v"].text == "V"


HEATER = """WARMO H-2 panel heater

KEYS

  ⏻   on / off
  ✺   heat output

2.1 Warmth

Touch ✺ to change the output: LOW → MEDIUM → HIGH → LOW ...
"""


def test_a_key_printed_as_an_icon_is_named_by_the_heading_its_word_begins() -> None:
    model = read_manual(HEATER, ["press_power", "press_warm"]).model
    assert "warmth" in model.variables  # not "warm", the action's clipped word


ROLLER = """ROLLA R-1 foam roller

PARTS

  (A) Display
  (B) Dial: turn to choose a pattern; push (click) to start or stop
  (C) ⏻ (hold 2 seconds)

Turn the dial: WAVE → PULSE → WAVE ...
"""


def test_a_key_whose_push_starts_and_stops_is_the_start() -> None:
    model = read_manual(ROLLER, ["hold_power", "turn_dial_cw", "turn_dial_ccw", "press_dial"]).model
    assert "running" in model.variables
    assert any(
        step.actions == ["press_dial"] and step.variable == "running"
        for steps in model.features.values()
        for step in steps
    )


PURIFIER = """AIRO P-3 air purifier

KEYS

  ⏻      on / off
  MODE   chooses the mode: AUTO → SLEEP → TURBO → AUTO ...
  LIGHT  night light: OFF → DIM → BRIGHT → OFF ...

SWITCHING OFF

When you switch off:
  • the night light is kept (it comes back as it was);
  • the mode always returns to AUTO, so the next start is quiet.
"""


def test_an_item_before_the_reset_in_its_list_says_what_is_kept() -> None:
    model = read_manual(PURIFIER, ["press_power", "press_mode", "press_light"]).model
    resets = {v for steps in model.features.values() for s in steps for v in s.reset or []}
    assert "light" not in resets


def test_dot_lamps_beside_uneven_levels_are_what_the_display_shows() -> None:
    text = LAMP + "\nLEVEL LAMPS\n\n    ●○○  1,500 lux\n    ●●○  3,000 lux\n    ●●●  6,000 lux\n"
    level = read_manual(text, ACTIONS).model.variables["level"]
    assert level.show == {"1500": "●○○", "3000": "●●○", "6000": "●●●"}
