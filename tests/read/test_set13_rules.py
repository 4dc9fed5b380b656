"""Rules of the set13 session, each on a small manual of our own in words unlike the manuals
that showed the need: a choice's name cell carrying its lamp's sign, a step or factory cell
carrying its unit, a bare "hold" among a key legend's uses, and a cleaner's "Cleaning modes"
heading that is no care section."""

from __future__ import annotations

from apbot.read import read_manual

# a milk frother: a choice cell printed with its lamp's sign ("LATTE ◐"), per-choice ranges,
# and step / factory cells that carry the unit
FROTHER = """# Milk frother

## Keys

| Key | Use |
|---|---|
| DRINK | Picks the drink. |
| + / - | Warmer or cooler. |

Each press of DRINK: LATTE → CAPPU → COCOA → LATTE.

## Temperature per drink

| Drink | Range | Step | Factory setting |
|---|---|---|---|
| LATTE ~ | 50 – 65 °C | 5 °C | 60 °C |
| CAPPU ≈ | 55 – 70 °C | 5 °C | 65 °C |
| COCOA ≋ | 60 – 80 °C | 5 °C | 70 °C |
"""
FROTHER_ACTIONS = ["press_drink", "press_plus", "press_minus"]


def test_a_choice_cell_with_its_lamp_sign_still_names_the_choice() -> None:
    model = read_manual(FROTHER, FROTHER_ACTIONS).model
    temps = [v for v in model.variables.values() if v.depends_on == "drink"]
    assert temps, "no temperature read per drink"
    cases = temps[0].cases
    assert tuple(cases["cocoa"].ranges[0][:2]) == (60, 80)


def test_step_and_factory_cells_may_carry_their_unit() -> None:
    model = read_manual(FROTHER, FROTHER_ACTIONS).model
    temps = [v for v in model.variables.values() if v.depends_on == "drink"]
    latte = temps[0].cases["latte"]
    assert latte.ranges[0][2] == 5
    assert latte.initial == 60


# a fan heater: the key's legend gives one use per gesture, the hold's use a noun after "hold"
HEATER = """# Fan heater

## The panel

1. POWER – switches the heater on and off.
2. FAN (tap: fan speed; hold 2 seconds: eco timer)

## Fan speed

Each tap of FAN moves on: LOW → MID → HIGH → LOW.
"""
HEATER_ACTIONS = ["press_power", "press_fan", "hold_fan"]


def test_a_bare_hold_among_the_legend_uses_names_the_held_setting() -> None:
    model = read_manual(HEATER, HEATER_ACTIONS).model
    held = [s.variable for s in model.features.get("set_eco_timer", [])]
    assert "eco_timer" in held, list(model.features)


# a window-cleaning robot: its settings under a heading "Cleaning modes", which is operation
WINDOW_ROBOT = """# Window robot

## Cleaning modes

Press PATH to change the path. The paths follow each other in a ring:

ZIGZAG → SPIRAL → FRAME → ZIGZAG …

## Cleaning and care

Wipe the pads with a damp cloth.
"""
WINDOW_ACTIONS = ["press_path"]


def test_a_cleaning_modes_heading_is_not_a_care_section() -> None:
    model = read_manual(WINDOW_ROBOT, WINDOW_ACTIONS).model
    path = model.variables["path"]
    assert path.values == ["zigzag", "spiral", "frame"]


# a desk fan: TIMER is touched for the oscillation and held for the sleep timer, each job in a
# section of its own, the held job's list told before the key is named
DESK_FAN = """# Desk fan

## Swing

Touch TIMER to change the swing: OFF → NARROW → WIDE → OFF.

## Sleep timer

The fan can stop by itself after a while:

2 h → 4 h → 8 h → 2 h …

Hold TIMER for 2 seconds; each further hold moves to the next time.

## Settings

As delivered, the swing is NARROW.
"""
DESK_FAN_ACTIONS = ["press_timer", "hold_timer"]


def test_a_list_in_a_section_where_the_key_is_only_held_is_the_holds() -> None:
    model = read_manual(DESK_FAN, DESK_FAN_ACTIONS).model
    held = [s.variable for f in model.features.values() for s in f if "hold_timer" in s.actions]
    assert held and held[0] is not None
    spec = model.variables[held[0]]
    lows = [r[0] for r in spec.ranges or []]
    assert lows and lows[0] in (2, "02:00:00"), spec


# a heated blanket: its start values told in a sentence about how it comes
BLANKET = """# Heated blanket

## Zones

Each press of ZONE moves on: FEET → BODY → FULL → FEET.

On delivery the zone is BODY.
"""


def test_a_sentence_about_how_it_comes_gives_the_start_value() -> None:
    model = read_manual(BLANKET, ["press_zone"]).model
    assert model.variables["zone"].initial == "body"


# a power recliner: a guide's row gives a span in passing before the table of each part's range
RECLINER = """# Power recliner

## Comfort guide

| Activity | Back | How |
|---|---|---|
| Reading | 110–120° | press BACK + a few times |
| Napping | 140–150° | hold BACK + |

## Moving the back and the legs

| Adjustment | Range | Each press |
|---|---|---|
| Back (BACK) | 100° – 160° | 10° |
| Legs (LEGS) | 0° – 80° | 10° |

Press BACK + or BACK - to move the back by 10 degrees.
"""
RECLINER_ACTIONS = ["press_back_plus", "press_back_minus", "press_legs_plus", "press_legs_minus"]


def test_a_settings_own_row_of_a_range_table_gives_its_range() -> None:
    model = read_manual(RECLINER, RECLINER_ACTIONS).model
    back = [v for n, v in model.variables.items() if n.startswith("back")]
    assert back and back[0].ranges, list(model.variables)
    assert (back[0].ranges[0][0], back[0].ranges[-1][1]) == (100, 160)
