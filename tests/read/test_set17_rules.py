"""Set17's reader rules, each on a short manual of another appliance written for the test: a
settings menu whose items are letter codes in a column headed "Code", with a named stop among
numbers and choices drawn as symbols; the stepping pair's own quantity on the home screen; a
legend's "Held 3 seconds: switches X on or off"; a refused key's message is not the running
display."""

from __future__ import annotations

from apbot.read import read_manual

_ACTIONS = ["press_start", "press_set", "hold_back", "press_back", "press_up", "press_down"]

_PURIFIER = """\
# Aeris P4 air purifier

## The keys

  ① START  Starts the fan; pressed again, stops it.
  ② BACK   Back: closes the settings and returns to the home screen.
           Held 3 seconds: switches NightGlow on or off.
  ③ SET    Opens the settings menu and moves from one code to the next.
  ④ ▲      On the home screen: brightness up. In the settings: the next value.
  ⑤ ▼      On the home screen: brightness down. In the settings: the previous value.

## Brightness

On the home screen press ▲ or ▼. The display shows the brightness, for example LUX 2.

Order:  OFF ▸ 1 ▸ 2 ▸ 3 ▸ 4.  ▲ stops at 4 and ▼ stops at OFF. Factory setting: 2.

## The settings menu

Stop the fan before you open the settings.

| Code | Setting        | Values (in ▲ order)           | Factory |
|------|----------------|-------------------------------|---------|
| tI   | Fan timer      | OFF, AUTO, 1, 2, 4, 8         | OFF     |
| SP   | Fan speed      | OFF, 1, 2, 3                  | 1       |
| FL   | Filter type    | ▽ carbon, △ hepa, ∘∘ mesh     | △       |

1. Press SET. The first code appears with its value, for example tI OFF.
2. Press ▲ or ▼ until the value you want is shown.
3. Press SET. The value is kept and the next code appears.

While the fan runs the settings cannot be opened: SET shows STOP FAN.
"""


def _model() -> object:
    return read_manual(_PURIFIER, _ACTIONS).model


def _by_label(model: object, label: str) -> object:
    return next(s for s in model.variables.values() if s.label == label)  # type: ignore[attr-defined]


def test_letter_codes_in_a_column_headed_code_are_a_settings_menu() -> None:
    model = _model()
    menu = model.features["settings_menu"]  # type: ignore[attr-defined]
    assert [s.actions for s in menu][:3] == [
        ["press_set"],
        ["press_up", "press_down"],
        ["press_set"],
    ]
    labels = [s.variable and model.variables[s.variable].label for s in menu if s.variable]  # type: ignore[attr-defined]
    assert labels == ["tI", "SP", "FL"]


def test_a_named_stop_among_numbers_is_a_value_of_the_menu_item() -> None:
    spec = _by_label(_model(), "tI")
    assert [str(v) for v in spec.values] == ["off", "auto", "1", "2", "4", "8"]  # type: ignore[attr-defined]


def test_choices_drawn_as_symbols_are_named_and_shown_by_the_symbol() -> None:
    spec = _by_label(_model(), "FL")
    assert [str(v) for v in spec.values] == ["carbon", "hepa", "mesh"]  # type: ignore[attr-defined]
    assert spec.show["hepa"] == "△"  # type: ignore[attr-defined]
    assert spec.initial == "hepa"  # type: ignore[attr-defined]


def test_the_menu_pair_also_moves_its_home_screen_quantity() -> None:
    model = _model()
    spec = model.variables["brightness"]  # type: ignore[attr-defined]
    assert [str(v) for v in spec.values] == ["off", "1", "2", "3", "4"]
    assert spec.wrap is False
    steps = model.features["set_brightness"]  # type: ignore[attr-defined]
    assert steps[0].actions == ["press_up", "press_down"]


def test_a_held_legend_line_switches_the_named_thing_not_the_short_press() -> None:
    model = _model()
    assert "nightglow" in model.variables  # type: ignore[attr-defined]
    held = [s for f in model.features.values() for s in f if "hold_back" in s.actions]  # type: ignore[attr-defined]
    assert held and held[0].variable == "nightglow"


def test_a_refused_keys_message_is_not_what_the_display_shows_while_running() -> None:
    model = _model()
    shown = model.variables["running"].show or {}  # type: ignore[attr-defined]
    assert "STOP FAN" not in shown.values()


_ACTIONS_2 = [
    "switch_power",
    "press_m1",
    "press_m2",
    "press_m3",
    "press_up",
    "press_down",
    "press_set",
]

_HOTPLATE = """\
# Thermo H2 lab hotplate

## The panel

  ① POWER — mains on / off.
  ② M1, M2, M3 — choose a stored recipe.
  ③ ▲ / ▼ — plate heat up / down (5 °C a press).
     In the SET menu: the next / previous value.
  ④ SET — opens the menu and moves from BZ to DIM and back.

## Stored recipes

   Recipe | Factory heat | Typical use
   -------+--------------+------------------------------
   M1     | 60 °C        | agar, gentle warming
   M2     | 120 °C       | solvents, evaporating
   M3     | 250 °C       | digestion, ashing

## Plate heat

The plate heat runs from 30 °C to 300 °C in 5 °C steps.

Warm-up times: to 100 °C : about 40 s     to 200 °C : about 90 s

## The SET menu

  BZ — buzzer volume. How loud the end signal sounds.
     Values: OFF, 1, 2, 3.   Factory: 2.
  DIM — display dimming. The display dims after this time without a key.
     Values: OFF, 15, 30, 60 seconds.   Factory: 30.

  1. Press SET. The display shows the buzzer volume, for example BZ 2.
  2. Press ▲ or ▼ to choose a value.
  3. Press SET. The display shows the dimming, for example DIM 30.
"""


def _hotplate() -> object:
    return read_manual(_HOTPLATE, _ACTIONS_2).model


def test_numbered_keys_a_legend_names_alone_choose_one_thing() -> None:
    model = _hotplate()
    spec = model.variables["recipe"]  # type: ignore[attr-defined]
    assert [str(v) for v in spec.values] == ["m1", "m2", "m3"]
    assert all(f"ch{k}" not in model.variables for k in (1, 2, 3))  # type: ignore[attr-defined]


def test_letter_coded_lead_lines_are_a_settings_menu_the_entry_key_walks() -> None:
    model = _hotplate()
    menu = model.features["settings_menu"]  # type: ignore[attr-defined]
    labels = [model.variables[s.variable].label for s in menu if s.variable]  # type: ignore[attr-defined]
    assert labels == ["BZ", "DIM"]
    assert menu[2].actions == ["press_set"]
    dim = _by_label(model, "DIM")
    assert [str(v).split()[0] for v in dim.values] == ["off", "15", "30", "60"]  # type: ignore[attr-defined]


def test_the_pairs_own_quantity_said_as_noun_up_down_beside_a_menu() -> None:
    model = _hotplate()
    steps = model.features["set_plate_heat"]  # type: ignore[attr-defined]
    spec = model.variables["plate_heat"]  # type: ignore[attr-defined]
    assert steps[0].actions == ["press_up", "press_down"]
    assert list(spec.ranges[0][:2]) == [30, 300]


def test_two_quantities_side_by_side_are_no_range() -> None:
    from apbot.read.values import find_ranges

    assert find_ranges("to 100 °C : about 40 s     to 200 °C : about 90 s") == []
    assert find_ranges("from 100 g to 2.0 kg")[0].high == 2000
