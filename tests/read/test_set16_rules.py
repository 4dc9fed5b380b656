"""Set16's reader rules, each on a short manual of another appliance written for the test: a
table whose first column draws the lamps of each value (the value is the next cell, and the
lamps, printed spaced, are how the display shows it)."""

from __future__ import annotations

from apbot.read import read_manual

_LAMPS_MANUAL = """\
# Brisa desk fan

## Keys

POWER — fan on / off.
SWING — the sweep angle.

## Sweep angle

Press SWING to step to the next sweep angle. After the widest it returns to the narrowest.
The angle lamps show which one is chosen:

| Lamps   | Sweep       | Use                  |
|---------|-------------|----------------------|
| ● ○ ○   | Narrow      | one person           |
| ○ ● ○   | Medium      | a desk               |
| ○ ○ ●   | Wide        | the whole room       |
"""


def _stepped(model: object, action: str) -> str:
    features = model.features.values()  # type: ignore[attr-defined]
    return next(s.variable for f in features for s in f if action in s.actions and s.variable)


def test_a_column_of_drawn_lamps_leaves_the_values_to_the_next_column() -> None:
    model = read_manual(_LAMPS_MANUAL, ["press_power", "press_swing"]).model
    spec = model.variables[_stepped(model, "press_swing")]
    assert [str(v).lower() for v in spec.values] == ["narrow", "medium", "wide"]


def test_spaced_lamps_beside_a_value_are_how_the_display_shows_it() -> None:
    model = read_manual(_LAMPS_MANUAL, ["press_power", "press_swing"]).model
    spec = model.variables[_stepped(model, "press_swing")]
    assert {str(k).lower(): v for k, v in spec.show.items()} == {
        "narrow": "●○○",
        "medium": "○●○",
        "wide": "○○●",
    }


def test_a_wrap_between_a_display_label_and_figures_gives_the_figures() -> None:
    from apbot.read.code_cycles import code_run

    assert code_run("After ST 12 comes ST 01 again.") == [f"ST {n:02d}" for n in range(1, 13)]
    assert code_run("After L3 comes L1.") == ["L1", "L2", "L3"]
    assert code_run("After ST 12 comes S1.") is None  # two ways of writing: no one run


_STATIONS_MANUAL = """\
# Kestrel kitchen radio

## Keys

POWER — radio on / off.
▲ / ▼ — next / previous station; in a setting view, next / previous value.
ALARM — alarm tone.

## Stations

Press ▲ or ▼ while the display shows the station: each press moves one station.
After ST 12 comes ST 01, and below ST 01 comes ST 12.

## Alarm tone

1. Press ALARM. The display shows AL 3.
2. Press ▲ or ▼ to change it, 1 to 5.
"""


def test_the_pair_in_the_display_view_steps_the_run_its_sentences_name() -> None:
    actions = ["press_power", "press_up", "press_down", "press_alarm"]
    model = read_manual(_STATIONS_MANUAL, actions).model
    station = model.variables.get("station")
    assert station is not None
    assert [str(v) for v in station.values] == [f"{n:02d}" for n in range(1, 13)]
    assert station.show == "ST {value}"


def test_a_range_whose_ends_carry_a_gloss_after_their_unit() -> None:
    from apbot.read.values import find_ranges

    (found,) = find_ranges("The arm reaches between 20 cm (shortest) and 80 cm (longest).")
    assert (found.low, found.high, found.unit) == (20, 80, "cm")


def test_a_tap_that_moves_the_thing_by_an_amount_is_the_step() -> None:
    from apbot.read.value_steps import find_step

    assert find_step("Tap + or -: the arm moves 2 cm in or out and stops.") == (2.0, "cm")
    assert find_step("Hold + for 2 s: the arm moves 10 cm out.") is None


def test_the_one_icon_no_key_word_names_is_the_key_never_named() -> None:
    from apbot.read.text_chars import _KEEP
    from apbot.read.text_sign_keys import name_signed_keys

    text = "③  ☀ — brightness.\n④  ⌛ — auto-off.\n\nTouch ⌛ to choose the auto-off time."
    out = name_signed_keys(text, ["brightness", "clock"], _KEEP)
    assert "CLOCK — auto-off" in out and "Touch CLOCK" in out


def test_a_warning_sign_apart_from_the_keys_legend_is_no_key() -> None:
    from apbot.read.text_chars import _KEEP
    from apbot.read.text_sign_keys import name_signed_keys

    text = "❋ — blower level.\n\n⚠ — hot grille. Let it cool.\n\nPress ❋ to change the level."
    out = name_signed_keys(text, ["blower", "surge"], _KEEP)
    assert "SURGE" not in out and "Press BLOWER" in out


def test_the_noun_the_display_shows_anew_names_the_pair() -> None:
    manual = """\
# Riva camera slider

## Moving the carriage

Tap ◀ or ▶: the carriage moves 1 cm and the display shows the new position, for example 12 cm.
The carriage travels between 0 cm (left end) and 90 cm (right end).
"""
    model = read_manual(manual, ["press_left", "press_right"]).model
    assert "position" in model.variables


def test_a_heading_listing_topics_gives_no_values() -> None:
    manual = """\
# Pico walkie-talkie

## RING TONES, SQUELCH, BACKLIGHT

Press RING to send the ring tone.
"""
    model = read_manual(manual, ["press_ring", "press_scan"]).model
    values = [
        str(v).lower() for spec in model.variables.values() for v in getattr(spec, "values", [])
    ]
    assert "squelch" not in values and "backlight" not in values


def test_a_knob_whose_positions_are_off_and_levels_is_the_power_too() -> None:
    manual = """\
# Lumo bedside speaker

## Controls

VOLUME / OFF knob — switches the speaker on and off and sets the loudness.
SOURCE — next input.

## Switching on

The knob has seven click positions: OFF and levels 1 to 6. Turn it clockwise from OFF to
switch on. While the speaker is off every key is ignored.
"""
    model = read_manual(manual, ["turn_cw", "turn_ccw", "press_source"]).model
    (turned,) = [s.variable for f in model.features.values() for s in f if "turn_cw" in s.actions]
    assert turned is not None
    assert [str(v) for v in model.variables[turned].values] == ["off", "1", "2", "3", "4", "5", "6"]
    (guard,) = [g for g in model.guards if g.when == {turned: "off"}]
    assert guard.only == ["turn_cw"]


def test_a_menu_key_takes_the_name_its_short_press_opens() -> None:
    manual = """\
# Vela baby camera

## Keys

(A) MENU — short press: night vision. Hold 3 s: screen lock on / off.
(B) ▲ / ▼ — change the value shown.

## Night vision

1. Press MENU. The display shows NV 1.
2. Press ▲ or ▼ to change it, 1 to 3.
"""
    model = read_manual(manual, ["press_menu", "hold_menu", "press_up", "press_down"]).model
    assert "night_vision" in model.variables
    assert "menu" not in model.variables


def test_a_knobs_off_and_levels_in_other_wordings() -> None:
    from apbot.read.off_positions import _OFF_LEVELS_RE

    for said in (
        "Dial positions: OFF, 1 to 5.",
        "dial positions off and 1–5",
        "positions Off and 1-5",
    ):
        found = _OFF_LEVELS_RE.search(said)
        assert found is not None and found.groups() == ("1", "5"), said


def test_the_display_view_opening_the_sentence_names_the_pair() -> None:
    moved = _STATIONS_MANUAL.replace(
        "Press ▲ or ▼ while the display shows the station: each press moves one station.",
        "While the display shows the station, press ▲ or ▼: each press moves one station.",
    )
    actions = ["press_power", "press_up", "press_down", "press_alarm"]
    station = read_manual(moved, actions).model.variables.get("station")
    assert station is not None
    assert [str(v) for v in station.values] == [f"{n:02d}" for n in range(1, 13)]
