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
