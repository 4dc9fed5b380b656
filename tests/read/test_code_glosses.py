"""Display words the manual glosses with a longer name (code_glosses), on short manuals in our
own words: the values become the glosses, the display words what the display shows."""

from __future__ import annotations

from apbot.read import read_manual

ROCKER = """ROKKA BR-3 baby rocker

THE KEYS

  Key      Function
  ⏻        Switches the unit on or off.
  MOTION   Chooses the motion; one of the lamps lights:
             ↔ SWAY = gentle sway
             ↕ BOUNCE = up and down bounce (soft)
  SOUND    Chooses the sound: CHIME → RAIN → HUM → CHIME …
             HUM (deep hum), RAIN (rain on leaves), CHIME (music box, bells)

MOTION

  Press MOTION: SWAY → BOUNCE → SWAY …
"""


def test_display_words_take_the_glosses_holding_them() -> None:
    model = read_manual(ROCKER, ["press_power", "press_motion", "press_sound"]).model
    motion = next(v for n, v in model.variables.items() if "motion" in n)
    assert motion.values == ["gentle sway", "up and down bounce"]
    assert motion.show == {"gentle sway": "SWAY", "up and down bounce": "BOUNCE"}


def test_a_gloss_not_naming_the_display_word_is_left() -> None:
    model = read_manual(ROCKER, ["press_power", "press_motion", "press_sound"]).model
    sound = next(v for n, v in model.variables.items() if "sound" in n)
    assert sound.values == ["chime", "rain", "deep hum"]  # "rain on leaves" describes it


CLEANER = """POLO R-2 pool robot

AREA   What the robot cleans:
         FLOOR  – the floor only
         WALL   – floor and walls
         LINE   – the waterline only

Press AREA: FLOOR → WALL → LINE → FLOOR …
"""


def test_a_plural_or_a_compound_holds_the_display_word() -> None:
    model = read_manual(CLEANER, ["press_area"]).model
    area = next(v for n, v in model.variables.items() if "area" in n)
    assert area.values == ["floor", "floor and walls", "waterline"]
    assert area.show == {"floor": "FLOOR", "floor and walls": "WALL", "waterline": "LINE"}


GRILL = """TOSTA CG-2 contact grill

HEAT   Chooses the heat: OFF → LOW → HIGH → OFF …
         OFF = appliance off, LOW = low heat, HIGH = high heat
"""


def test_a_switch_word_or_the_settings_own_name_adds_nothing() -> None:
    model = read_manual(GRILL, ["press_heat"]).model
    heat = next(v for n, v in model.variables.items() if "heat" in n)
    assert heat.values == ["off", "low", "high"]


FAN = """AIRO F3 tower fan

SPEED  Chooses the speed: LOW → MID → HIGH → LOW …
MODE   Chooses the mode: NORMAL → SLEEP → NATURE → NORMAL …

Display messages
  HIGH  – room temperature too high
  SLEEP – display goes dark for a quiet sleep
"""


def test_a_display_message_away_from_the_settings_legend_names_no_value() -> None:
    model = read_manual(FAN, ["press_speed", "press_mode"]).model
    speed = next(v for n, v in model.variables.items() if "speed" in n)
    assert speed.values == ["low", "mid", "high"]  # not "room temperature too high"


HEATER = """WARMA H-2 panel heater

LEVEL  Chooses the heat: LOW → HIGH → LOW …

Messages the display gives:
  HIGH – temperature too high
  LOW  – temperature too low
"""


def test_glosses_sharing_one_frame_around_the_words_name_nothing() -> None:
    model = read_manual(HEATER, ["press_level"]).model
    level = next(v for n, v in model.variables.items() if "level" in n)
    assert level.values == ["low", "high"]


KETTLE = """VARMA TK-2 tea kettle

THE KEYS
  ⏻       Switches the kettle on or off.
  TEMP    Chooses the water: WARM → HOT → BOIL → WARM …

INDICATOR LAMPS
  BOIL = rolling boil
  HOT (surface hot) – do not touch
"""


def test_a_gloss_followed_by_a_warning_tells_of_a_state() -> None:
    """ "HOT (surface hot) – do not touch" warns of the lamp's state: no name for HOT."""
    for text in (KETTLE, KETTLE.replace("HOT (surface hot) – do", "HOT – surface hot, do")):
        temp = read_manual(text, ["press_power", "press_temp"]).model.variables["temp"]
        assert temp.values == ["warm", "hot", "rolling boil"]


STEAMER = """PARO S-1 garment steamer

MODE   Chooses the mode; one of the lamps lights:
         STEAM – with steam
         MIST  – with a fine mist
Press MODE: STEAM → MIST → STEAM …
"""


def test_a_leading_with_is_no_part_of_the_name() -> None:
    mode = read_manual(STEAMER, ["press_power", "press_mode"]).model.variables["mode"]
    assert mode.values == ["steam", "fine mist"]
