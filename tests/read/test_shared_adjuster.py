"""A function key that chooses which setting a shared adjuster changes (roles_shared), each
rule on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual

# a contact grill: one pair of arrow keys, a SET key that hands them the other setting
GRILL = """# Contact grill

## Keys

| Key | Use |
|---|---|
| ON/OFF | Power. |
| SET | Toggles the arrow keys between the grilling time and the temperature. |
| UP / DOWN | Raise or lower the value on the display. |
| GO | Starts grilling. |

## Grilling

The arrow keys normally change the grilling time (1 to 30 minutes).
To change the heat, press SET: the temperature blinks. Use UP and DOWN to pick 160 to 230 °C.
Press SET once more to return to the time.
"""
GRILL_ACTIONS = ["press_on_off", "press_set", "press_up", "press_down", "press_go"]


def _steps(model: object, var: str) -> list[list[tuple[str, ...]]]:
    feats = model.features  # type: ignore[attr-defined]
    return [
        [tuple(s.actions) for s in steps]
        for steps in feats.values()
        if any(s.variable == var for s in steps)
    ]


def test_a_key_that_switches_the_pair_gives_it_both_settings() -> None:
    model = read_manual(GRILL, GRILL_ACTIONS).model
    temps = [v for v in model.variables if v.startswith("temp")]
    times = [v for v in model.variables if "time" in v]
    assert temps and times, list(model.variables)
    pair = ("press_up", "press_down")
    # after SET the arrows set the temperature, after SET again the time
    assert [("press_set",), pair, ("press_set",), pair] in _steps(model, temps[0])
    # alone they set the time (their own sentence says so)
    assert [pair] in _steps(model, times[0])


# a bread oven: a jog dial picks the bake; DELAY and BAKE TIME hand it their time instead
OVEN = """CONTROLS
KNOB      Jog knob. Turn it to pick the bake: CRUSTY, SOFT, RYE or QUICK.
          Once DELAY or BAKE TIME is pressed, turning the knob changes that time.
DELAY     How many hours until the bread should be ready (1 to 12 hours).
BAKE TIME The baking time, 20 to 90 minutes.
START     Starts baking.
"""
OVEN_ACTIONS = ["turn_knob_cw", "turn_knob_ccw", "press_delay", "press_bake_time", "press_start"]


def test_a_dial_with_its_own_list_also_sets_what_a_key_hands_it() -> None:
    model = read_manual(OVEN, OVEN_ACTIONS).model
    turns = ("turn_knob_cw", "turn_knob_ccw")
    steps = {name: [tuple(s.actions) for s in feature] for name, feature in model.features.items()}
    assert [("press_delay",), turns] in steps.values(), steps
    assert [("press_bake_time",), turns] in steps.values(), steps
    assert [turns] in steps.values(), steps  # turned alone, it picks the bake


# a waffle maker: the MODE key hands the arrows the browning; its next press hands back the time
WAFFLE = """WAFFLE MAKER  -  KEYS
POWER  on and off
MODE   makes the up and down arrows set the browning level; press it once more and they set the
       baking time again.
UP / DOWN  change the value on the display (normally the baking time, 2 to 8 minutes).
"""
WAFFLE_ACTIONS = ["press_power", "press_mode", "press_up", "press_down"]


def test_a_key_that_hands_the_pair_one_setting_and_then_back() -> None:
    model = read_manual(WAFFLE, WAFFLE_ACTIONS).model
    pair = ("press_up", "press_down")
    level = next((v for v in model.variables if v.startswith("level")), None)
    time = next((v for v in model.variables if v.startswith("time")), None)
    assert level and time, list(model.variables)
    assert [("press_mode",), pair, ("press_mode",), pair] in _steps(model, level)
    assert [pair] in _steps(model, time)


# a radio alarm: one SET key and one TUNE wheel; the wheel tunes the radio unless SET handed it
# the clock's hour, then (SET again) its minutes
RADIO = """RADIO ALARM

Turn the TUNE wheel to change the station (87.5 to 108 MHz).

Setting the time
1. Press CLOCK SET. The hour blinks.
2. Turn the TUNE wheel to set the hour.
3. Press CLOCK SET. The minutes blink.
4. Turn the TUNE wheel to set the minutes.
5. Press CLOCK SET to finish.
"""
RADIO_ACTIONS = ["turn_tune_cw", "turn_tune_ccw", "press_clock_set"]


def test_a_clock_set_hour_then_minute_with_one_key_and_one_dial() -> None:
    model = read_manual(RADIO, RADIO_ACTIONS).model
    turns = ("turn_tune_cw", "turn_tune_ccw")
    hour = next((v for v in model.variables if v.endswith("hour")), None)
    minute = next((v for v in model.variables if v.endswith("minute")), None)
    assert hour and minute, list(model.variables)
    assert [("press_clock_set",), turns, ("press_clock_set",), turns] in _steps(model, hour)
    assert _steps(model, minute) == _steps(model, hour)
    assert any(
        steps == [turns]
        for f in model.features.values()
        for steps in [[tuple(s.actions) for s in f]]
    ), "turned alone the wheel keeps its own setting"


def test_a_clock_set_hour_then_minute_with_the_stepping_pair() -> None:
    text = RADIO.replace("Turn the TUNE wheel to set", "Press + or - to set").replace(
        "Turn the TUNE wheel to change the station", "Press + or - to change the volume"
    )
    model = read_manual(text, ["press_plus", "press_minus", "press_clock_set"]).model
    hour = next((v for v in model.variables if v.endswith("hour")), None)
    assert hour, list(model.variables)
    pair = ("press_plus", "press_minus")
    assert [("press_clock_set",), pair, ("press_clock_set",), pair] in _steps(model, hour)


def test_clock_steps_that_run_on_and_name_the_hour_in_passing() -> None:
    text = RADIO.replace(
        "2. Turn the TUNE wheel to set the hour.",
        "2. Turn the TUNE wheel until the right hour shows. One click is an hour. It rolls round.",
    ).replace(
        "4. Turn the TUNE wheel to set the minutes.", "4. Turn the TUNE wheel to the minutes."
    )
    model = read_manual(text, RADIO_ACTIONS).model
    hour = next((v for v in model.variables if v.endswith("hour")), None)
    assert hour, list(model.variables)


# a two-plate griddle: each plate has PROG and TEMP/TIME keys and its own + / −; one table
GRIDDLE = """# Twin griddle

| Key | Use |
|---|---|
| PROG 1 | Next programme of plate 1: PANCAKE → STEAK → TOAST. |
| PROG 2 | Next programme of plate 2: PANCAKE → STEAK → TOAST. |
| TEMP/TIME 1 / TEMP/TIME 2 | Switches + and − of the plate between the time and the temperature. |
| + 1 / − 1, + 2 / − 2 | Raise or lower the value of the plate. |

The + and − keys of a plate change its time unless TEMP/TIME was pressed.

| Programme | Temperature | Time |
|---|---|---|
| PANCAKE | 180–220 °C | 2–6 min |
| STEAK | 200–250 °C | 3–15 min |
| TOAST | 160–200 °C | 1–4 min |
"""
GRIDDLE_ACTIONS = [
    "press_prog1", "press_temptime1", "press_plus1", "press_minus1",
    "press_prog2", "press_temptime2", "press_plus2", "press_minus2",
]  # fmt: skip


def test_the_second_zone_takes_the_programme_table_on_its_own_programme() -> None:
    model = read_manual(GRIDDLE, GRIDDLE_ACTIONS).model
    temps = sorted(v for v in model.variables if v.startswith("temp"))
    assert len(temps) == 2, list(model.variables)
    parents = [getattr(model.variables[t], "depends_on", None) for t in temps]
    assert parents == ["prog1", "prog2"], parents
