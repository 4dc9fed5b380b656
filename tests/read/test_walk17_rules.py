"""walk17 rules: each in our own words, for an appliance none of the data manuals describe."""

from __future__ import annotations

from apbot.read.reader import read_manual

_HEATER = """AQUA T3 towel warmer

KEYS

  | Key | Function |
  |-----|----------|
  | POWER | switches the warmer on or off |
  | SET | opens the user settings |
  | + | raises the value |
  | - | lowers the value |

USER SETTINGS

  The user settings are shown by a code before the value. They come in this order:

  | Code | Setting    | Values              |
  |------|------------|---------------------|
  | F1   | Heat       | LOW, MID, HIGH      |
  | F2   | Timer      | 1, 2, 4, 8          |
  | F3   | Beep       | ON, OFF             |

  1. Press SET. F1 and its value appear.
  2. Press + or - until the value you want is shown.
  3. Press SET. The value is kept and the next code appears.
  4. Repeat steps 2 and 3, or wait 6 seconds to return to normal.
"""


def test_a_chart_of_codes_is_a_walk_of_fields() -> None:
    # SET shows the chart's codes one after another; each row is a field set with + / -,
    # not one setting whose values are the codes' names
    actions = ["press_power", "press_set", "press_plus", "press_minus"]
    model = read_manual(_HEATER, actions).model
    walks = [s for s in model.features.values() if len(s) >= 4 and s[0].actions == ["press_set"]]
    assert len(walks) == 1, model.features
    fields = [s.variable for s in walks[0] if s.variable]
    assert len(fields) == 3
    heat = model.variables[fields[0]]
    assert list(heat.values) == ["low", "mid", "high"]
    # the code the display prints before the value is the model's: as the field's display
    # ("F1 HIGH", code_walks) or as its label (the settings-menu reader, which runs first)
    assert (heat.show or {}).get("high") == "F1 HIGH" or heat.label == "F1"
    timer = model.variables[fields[1]]
    assert timer.label == "F2" or any(str(v).startswith("F2 ") for v in (timer.show or {}).values())
    assert "press_plus" in walks[0][1].actions and walks[0][2].actions == ["press_set"]


_DRYER = """LINO D4 shoe dryer

KEYS

  | Key | Use |
  |-----|-----|
  | MENU | hold 3 s to open the settings menu; press to go to the next item |
  | UP | next value |
  | DOWN | previous value |

SETTINGS MENU

  | Code | Item        | Choices          | Default |
  |------|-------------|------------------|---------|
  | A1   | Heat        | UV, 1, 2         | 1       |
  | A2   | Fan         | ON, OFF          | ON      |

  Hold MENU for 3 seconds: A1 appears. UP and DOWN change the value; MENU goes to the next
  item.
"""


def test_a_menu_row_listing_words_among_numbers_keeps_every_choice() -> None:
    # "UV, 1, 2" is three choices (not a range 1-2) and "ON, OFF" two (not nothing)
    actions = ["hold_menu", "press_menu", "press_up", "press_down"]
    model = read_manual(_DRYER, actions).model
    menu = next(s for s in model.features.values() if s[0].actions == ["hold_menu"])
    fields = [s.variable for s in menu if s.variable]
    assert [list(model.variables[f].values) for f in fields] == [["uv", "1", "2"], ["on", "off"]]


_AQUARIUM = """REEFO A1 aquarium feeder

FEEDING SETTINGS

  Press and hold MODE for 2 seconds until 'FD' and the feeding hour flash. Choose the
  hour (0 to 23) with UP and DOWN, then press MODE: 'PT' and the portion count flash. Choose
  1 to 5 portions with UP and DOWN. Press MODE again to finish.

FEEDING NOW

  Press FEED to drop one portion at once.
"""


def test_a_prose_walk_moves_on_mid_sentence() -> None:
    # "…, then press MODE: 'PT' and the portion count flash": the clause after "then" opens
    # the second field, named beside its quoted display word; the hold's lone guessed setting
    # (the hold then the pair) gives way to the walk
    actions = ["hold_mode", "press_mode", "press_up", "press_down", "press_feed"]
    model = read_manual(_AQUARIUM, actions).model
    held = [s for s in model.features.values() if s[0].actions == ["hold_mode"]]
    assert len(held) == 1
    fields = [s.variable for s in held[0] if s.variable]
    assert fields == ["feeding_hour", "portion_count"], fields
    assert held[0][2].actions == ["press_mode"]
    assert model.variables["portion_count"].label == "PT"


_HUMIDOR = """CEDRA H5 humidor

KEYS

  SET key, + key, − key, LAMP key.

TARGETS

  Hold SET for 3 seconds until "RH" and the target humidity flash. Set the humidity
  (60 to 75) with + and −, then press SET: "CLN" and the fan period flash. Choose the
  period with + and − (2 to 12 hours). Press SET once more to store both values.
"""


def test_a_walk_replaces_the_holds_lone_guess() -> None:
    # before the walk, "hold SET, then + / −" was read as one setting of its own ("period");
    # one key opens one procedure, so that guess gives way to the walk through two fields
    actions = ["hold_set", "press_set", "press_plus", "press_minus", "press_lamp"]
    model = read_manual(_HUMIDOR, actions).model
    held = [s for s in model.features.values() if s[0].actions == ["hold_set"]]
    assert len(held) == 1 and len([s for s in held[0] if s.variable]) == 2, model.features
