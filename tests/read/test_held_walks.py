"""A held key opening two settings walked with the stepping pair (`held_walks.py`)."""

from __future__ import annotations

from apbot.read import read_manual

# a pond pump (our own words): QUIET held opens its start time, then its length
POND = """BRIOLA PP-3 pond pump controller

KEYS
  QUIET     Press: quiet period on / off.   Hold 3 s: set the quiet period.
  UP        Raise the value shown.
  DOWN      Lower the value shown.
  FLOW      Next flow level: LOW, MID, HIGH.

QUIET PERIOD
  During the quiet period the pump runs at its lowest flow.

  Press QUIET to switch the quiet period on; press it again to switch it off.

  1. Hold QUIET for 3 seconds. The display shows the start time, e.g. Q 21:00.
  2. Press UP or DOWN to change the start time in steps of 15 minutes. After 23:45
     comes 00:00.
  3. Press QUIET briefly. The display shows the length, e.g. Q 6 h.
  4. Press UP or DOWN to change the length, from 1 to 10 hours in steps of 1 hour.
  5. Do not touch any key for 5 seconds: the setting is stored.

FLOW
  Press FLOW to choose LOW, MID or HIGH. Press UP or DOWN to raise or lower the flow.
"""
POND_ACTIONS = ["press_quiet", "hold_quiet", "press_up", "press_down", "press_flow", "wait_5s"]


def test_held_key_walks_a_start_time_and_a_length() -> None:
    model = read_manual(POND, POND_ACTIONS).model
    walks = [
        steps
        for steps in model.features.values()
        if [s.actions for s in steps][:1] == [["hold_quiet"]]
    ]
    assert len(walks) == 1
    steps = walks[0]
    assert [s.actions[0] for s in steps] == ["hold_quiet", "press_up", "press_quiet", "press_up"]
    start, length = steps[1].variable, steps[3].variable
    assert start is not None and length is not None
    assert model.variables[start].type == "time"
    assert next(tuple(r) for r in model.variables[start].ranges or [])[1:] == ("23:45:00", 900)
    assert model.variables[length].unit == "h"
    assert all(s.timeout == 5 for s in steps)


# a spa panel (our own words): the lock's word is LOCK, though a sleep mode's code SL stands
# nearer the keys' rows
SPA = """AQUA S-2 spa panel

KEYS
  UP / DOWN   Raise / lower the set temperature.
  MODE        Next heating mode ST, EC, SL.
  UP + DOWN   Hold both 5 s: panel lock on / off.

  Heating modes: ST standard, EC economy, SL sleep. The keys UP and DOWN set 26 to 40 °C.

PANEL LOCK
  Hold UP and DOWN together for 5 seconds. LOCK appears and the keys are locked.
"""
SPA_ACTIONS = ["press_up", "press_down", "press_mode", "hold_up_down"]


def test_the_lock_word_is_lock_before_a_two_letter_code() -> None:
    model = read_manual(SPA, SPA_ACTIONS).model
    locks = [v for v in model.variables.values() if (v.show or {}).get("on") in ("LOCK", "SL")]
    assert locks and all(v.show["on"] == "LOCK" for v in locks)


def test_two_keys_held_together_take_the_hold_time_the_manual_gives() -> None:
    from apbot.read.hold_seconds import pair_hold_seconds

    lines = ["  2+3  WARM ▲ and COOL ▼ together      5 s: panel lock on / off",
             "Hold WARM ▲ and COOL ▼ together for 5 seconds. LOCK appears."]  # fmt: skip
    assert pair_hold_seconds(lines, "COOL ▼", "WARM ▲") == 5
    assert pair_hold_seconds(lines, "WARM", "COOL") == 5  # names printed without their arrows
    assert pair_hold_seconds(["ZONE + TIMER  Held together for 3 seconds"], "ZONE", "TIMER") == 3
    assert pair_hold_seconds(["Hold ZONE for 5 seconds."], "ZONE", "TIMER") is None


# the lock's section names a CHILD LOCK symbol, but the display is said to show C-L
CANCEL_LOCK = """CONTROL PANEL

CANCEL   Stops a programme.
TEMP     Sets the temperature from 40 to 90 °C in steps of 5 °C.

CHILD LOCK

Hold CANCEL for 3 seconds to lock the keys. The display shows C-L.

While the keys are locked, the CHILD LOCK symbol is lit. Hold CANCEL again for 3 s to unlock.
"""


def test_the_lock_word_is_the_one_the_display_is_said_to_show() -> None:
    model = read_manual(CANCEL_LOCK, ["press_cancel", "hold_cancel", "press_temp"]).model
    assert model.variables["child_lock"].show == {"off": "", "on": "C-L"}


def test_the_lock_word_that_lights_before_the_one_a_touched_key_shows() -> None:
    text = CANCEL_LOCK.replace(
        "The display shows C-L.", "LOCK lights; touching a key then shows LOC."
    )
    model = read_manual(text, ["press_cancel", "hold_cancel", "press_temp"]).model
    assert model.variables["child_lock"].show == {"off": "", "on": "LOCK"}


# a greenhouse vent controller (our own words): TIME held opens the clock's hours, then its
# minutes
VENT = """VENTRA GV-1 greenhouse vent controller

KEYS
  TIME      Press: show the opening time.   Hold 3 s: set the clock.
  +         Raise the value shown.
  -         Lower the value shown.
  VENT      Open or close the vent now.

OPENING TIME
  Press TIME. Press + or - to move the opening time by 30 minutes per press.

SETTING THE CLOCK
  1. Hold TIME for 3 seconds. The hours flash.
  2. Press + or - to set the hours, one hour per press.
  3. Press TIME briefly. The minutes flash.
  4. Press + or - to set the minutes. Hold + or - for 2 seconds to move 10 minutes at a time.
  5. Press TIME to confirm.
"""
VENT_ACTIONS = ["press_time", "hold_time", "press_plus", "press_minus", "hold_plus",
                "hold_minus", "press_vent"]  # fmt: skip


def test_held_key_walks_the_hours_then_the_minutes_of_a_clock() -> None:
    model = read_manual(VENT, VENT_ACTIONS).model
    walks = [
        steps
        for steps in model.features.values()
        if [s.actions for s in steps][:1] == [["hold_time"]]
    ]
    assert len(walks) == 1
    steps = walks[0]
    assert [s.actions[0] for s in steps] == [
        "hold_time", "press_plus", "press_time", "press_plus", "press_time"
    ]  # fmt: skip
    clock = steps[1].variable
    assert clock is not None and steps[3].variable == clock
    assert model.variables[clock].type == "time" and model.variables[clock].wrap
    assert steps[1].effect["press_plus"].add == 3600
    assert steps[3].effect["press_minus"].add == -60
    assert steps[3].effect["hold_plus"].add == 600


# the same controller's held key setting a delay of hours and minutes (a duration, not a clock)
VENT_DELAY = (
    VENT.replace("Hold 3 s: set the clock.", "Hold 3 s: set the vent delay.")
    .replace("SETTING THE CLOCK", "VENT DELAY")
    .replace("to set the hours, one hour per press.", "to set the hours, from 0 to 12 hours.")
)


def test_held_key_walking_hours_of_a_delay_makes_no_clock() -> None:
    model = read_manual(VENT_DELAY, VENT_ACTIONS).model
    assert not any(
        v.type == "time" and v.wrap and v.ranges[0][1] == "23:59:00"
        for v in model.variables.values()
    )


# a bird-feeder timer (our own words): FEED held opens the feed time, named beside its display
# word, then the pause after it, listed value by value; waiting stores it
FEEDER = """PIKKU BF-2 bird feeder timer

KEYS
  FEED      Press: feeding on / off.   Hold 3 s: set the feeding.
  ▲         Later / more.
  ▼         Earlier / less.

FEEDING
  1. Hold FEED for 3 seconds. FT and the feed time flash, e.g. FT 07:00.
  2. Set the feed time with ▲ and ▼. Each press moves it by 30 minutes. After 23:30
     comes 00:00.
  3. Press FEED. PA and the pause flash, e.g. PA 2 h.
  4. Set the pause with ▲ / ▼: 1, 2, 3 or 4 hours.
  5. Wait 5 seconds. The values are stored.
"""
FEEDER_ACTIONS = ["press_feed", "hold_feed", "press_up", "press_down", "wait_5s"]


def test_a_walk_s_fields_are_named_beside_their_display_words_and_a_listed_one_is_read() -> None:
    model = read_manual(FEEDER, FEEDER_ACTIONS).model
    (steps,) = [s for s in model.features.values() if s[0].actions == ["hold_feed"]]
    start, pause = steps[1].variable, steps[3].variable
    assert start == "feed_time" and pause == "pause"
    assert model.variables[start].label == "FT" and model.variables[pause].label == "PA"
    assert tuple(next(iter(model.variables[pause].ranges or [])))[:2] == (1, 4)
    assert all(s.timeout == 5 for s in steps)


# a kitchen radio (our own words): WAKE held walks the hours, then the minutes in steps of 5,
# of a time named beside its display word; NAP held opens one setting only
RADIO = """TOKI KR-1 kitchen radio

KEYS
  WAKE      Press: wake-up on / off.   Hold 3 s: set the wake-up time.
  ▲ / ▼     Up / down.
  NAP       Hold 3 s: set the nap length.

WAKE-UP TIME
  1. Hold WAKE for 3 seconds. WK and the wake time appear, the hour flashes.
  2. Press ▲ or ▼ to set the hour.
  3. Press WAKE. The minutes flash.
  4. Press ▲ or ▼ to set the minutes. Each press moves the time by 5 minutes.
  5. Press WAKE to confirm.

NAP LENGTH
  1. Hold NAP for 3 seconds. NP and the length appear.
  2. Press ▲ or ▼: 10, 20, 30 or 40 minutes.
  3. Wait 5 seconds; the setting is stored.
"""
RADIO_ACTIONS = ["press_wake", "hold_wake", "press_up", "press_down", "hold_nap", "wait_5s"]


def test_a_clock_walk_is_named_beside_its_display_word_and_steps_the_minutes_it_says() -> None:
    model = read_manual(RADIO, RADIO_ACTIONS).model
    (steps,) = [s for s in model.features.values() if s[0].actions == ["hold_wake"]]
    assert steps[1].variable == "wake_time" == steps[3].variable
    assert steps[3].effect["press_up"].add == 300
    assert tuple(next(iter(model.variables["wake_time"].ranges or [])))[1:] == ("23:55:00", 300)


def test_a_hold_opening_one_setting_the_pair_steps_is_that_setting() -> None:
    model = read_manual(RADIO, RADIO_ACTIONS).model
    (steps,) = [s for s in model.features.values() if s[0].actions == ["hold_nap"]]
    assert [s.actions[0] for s in steps] == ["hold_nap", "press_up"]
    nap = steps[1].variable
    assert nap == "nap_length" and model.variables[nap].label == "NP"
    assert model.variables[nap].type == "time" and steps[1].timeout == 5


# an aquarium light (our own words): MOON held opens the moonlight's start hour, then its end
# hour, which the steps say is set "in the same way"
AQUARIUM = """LUMA AQ-5 aquarium light

KEYS
  ▲        Brighter; while setting the moonlight: one hour later.
  ▼        Dimmer; while setting the moonlight: one hour earlier.
  MOON     Press: moonlight on / off.   Hold 3 s: set the moonlight hours.

MOONLIGHT HOURS
  1. Hold MOON for 3 seconds. The display shows the start hour, e.g. M-ON 20:00.
  2. Press ▲ (one hour later) or ▼ (one hour earlier). After 23:00 comes 00:00.
  3. Press MOON briefly. The display shows the end hour, e.g. M-OFF 06:00.
  4. Set the end hour with ▲ / ▼ in the same way.
  5. Wait 5 seconds without touching a key: both hours are stored.
"""
AQUARIUM_ACTIONS = ["press_up", "press_down", "press_moon", "hold_moon", "wait_5s"]


def test_a_second_field_set_in_the_same_way_takes_the_first_fields_kind() -> None:
    model = read_manual(AQUARIUM, AQUARIUM_ACTIONS).model
    walks = [s for s in model.features.values() if [x.actions for x in s][:1] == [["hold_moon"]]]
    assert len(walks) == 1
    steps = walks[0]
    assert [s.actions[0] for s in steps] == ["hold_moon", "press_up", "press_moon", "press_up"]
    start, end = steps[1].variable, steps[3].variable
    assert start and end and start != end
    for var in (start, end):
        assert model.variables[var].type == "time"
        assert next(tuple(r) for r in model.variables[var].ranges or [])[1:] == ("23:00:00", 3600)


# a fan heater's service menu (our own words): three settings walked by MODE, each read in
# another shape — uneven stops with the unit after the last, codes the manual glosses with
# words, a switch the pair turns on and off — the first one skippable, the pause in a note
HEATER = """THERMA FH-7 fan heater

KEYS
  MODE      Next heating mode: ECO, COMFORT, BOOST.
  UP        Menu: next value.
  DOWN      Menu: previous value.

  Overheat guard    g1 low (40 °C) – g2 normal (50 °C) – g3 high (60 °C)

SERVICE MENU

  1. Press and hold MODE for 3 seconds. The display shows the fan run-on, e.g. Ro 30 s.
  2. Press UP or DOWN to change the run-on: 10, 20, 30, 60 or 120 seconds. To keep it,
     go straight to step 3.
  3. Press MODE briefly. The display shows the overheat guard, e.g. g2.
  4. Press UP for a higher guard, DOWN for a lower one (g1, g2, g3; stops at both ends).
  5. Press MODE briefly. The display shows TONE on or TONE off.
  6. Press UP to switch the key tone on, DOWN to switch it off.

  Notes
  If you touch no key for 6 seconds, the menu closes and the settings are stored.
"""
HEATER_ACTIONS = ["press_mode", "hold_mode", "press_up", "press_down", "wait_6s"]


def test_held_key_walks_three_settings_of_several_kinds() -> None:
    model = read_manual(HEATER, HEATER_ACTIONS).model
    walk = next(s for s in model.features.values() if s[0].actions == ["hold_mode"])
    assert [s.actions[0] for s in walk] == [
        "hold_mode",
        "press_up",
        "press_mode",
        "press_up",
        "press_mode",
        "press_up",
    ]
    run_on, guard, tone = (walk[k].variable for k in (1, 3, 5))
    assert run_on and guard and tone
    assert walk[1].optional and not walk[3].optional
    assert all(s.timeout == 6 for s in walk)
    stops = [(r[0], r[1]) for r in model.variables[run_on].ranges or []]
    assert stops[0][0] == "00:00:10" and stops[-1][1] == "00:02:00" and len(stops) == 3
    assert model.variables[guard].values == ["low", "normal", "high"]
    assert model.variables[guard].show == {"low": "g1", "normal": "g2", "high": "g3"}
    assert model.variables[guard].wrap is False
    assert model.variables[tone].values == ["off", "on"]
    assert model.variables[tone].label == "TONE"


# a milk frother (our own words): the menu's items set with the knob, one a range of bare levels
FROTHER = """LATTA MF-2 milk frother

  ⏻        switches the frother on and off
  Knob     turn: the milk temperature; in the menu, the value shown
  MENU     hold 3 s: settings menu; press inside the menu: next item

  The milk temperature is set from 40 to 70 °C in steps of 5 °C.

SETTINGS MENU
  1. Press and hold MENU for 3 seconds. The display shows the foam level, e.g. FL 3.
  2. Turn the knob to choose the foam level (1 to 5).
  3. Press MENU briefly. The display shows the whisk speed, e.g. SP 2.
  4. Turn the knob to choose the speed: 1, 2 or 3 (it stops at 1 and at 3).
  5. Wait 8 seconds. The menu closes.
"""
FROTHER_ACTIONS = ["press_power", "turn_knob_cw", "turn_knob_ccw", "hold_menu", "press_menu"]


def test_a_menu_walk_may_be_set_with_the_knob() -> None:
    model = read_manual(FROTHER, FROTHER_ACTIONS).model
    walk = next(s for s in model.features.values() if s[0].actions == ["hold_menu"])
    assert [s.actions for s in walk][1] == ["turn_knob_cw", "turn_knob_ccw"]
    foam = walk[1].variable
    assert foam == "foam_level"
    assert [tuple(r) for r in model.variables[foam].ranges or []] == [(1, 5, 1)]
    assert walk[3].variable == "whisk_speed"
    # each labelled by the letters of the display's example ("e.g. FL 3", "e.g. SP 2")
    assert model.variables[foam].label == "FL"
    assert model.variables["whisk_speed"].label == "SP"


# a room thermostat (our own words): ▲ / ▼ set the temperature (no range given) and also the
# items of the menu SET opens; the temperature is theirs, not a guess the menu replaces
THERMOSTAT = """CALORA RT-1 room thermostat

  ▲ / ▼    raise or lower the room temperature
  SET      hold 3 s: installer menu

INSTALLER MENU
  1. Hold SET for 3 seconds. The display shows the switching gap, e.g. SG 0.5.
  2. Press ▲ or ▼ to choose the gap: 0.2, 0.5 or 1.0 °C.
  3. Press SET briefly. The display shows the frost guard, e.g. FG 5.
  4. Press ▲ or ▼ to choose 5, 7 or 10 °C.
  5. Wait 5 seconds. The menu closes.
"""
THERMOSTAT_ACTIONS = ["press_up", "press_down", "hold_set", "press_set", "wait_5s"]


def test_the_pair_s_own_setting_named_outside_the_walk_stays() -> None:
    model = read_manual(THERMOSTAT, THERMOSTAT_ACTIONS).model
    walk = next(s for s in model.features.values() if s[0].actions == ["hold_set"])
    assert [walk[k].variable for k in (1, 3)] == ["switching_gap", "frost_guard"]
    own = [
        s[0].variable for s in model.features.values() if s[0].actions == ["press_up", "press_down"]
    ]
    assert own and "temperature" in str(own[0])


def test_a_key_held_to_save_is_no_pause_ending_the_walk() -> None:
    # the walk ends by holding its key ("hold MODE for 2 seconds to save"), and a note says how
    # to leave by a hold: neither is a pause of 2 seconds after which the menu closes by itself
    end = "  7. Press and hold MODE for 2 seconds to save the settings and leave the menu.\n"
    note = "To go back, hold MODE for 2 seconds; the display returns to the room temperature."
    text = HEATER.replace(
        "If you touch no key for 6 seconds, the menu closes and the settings are stored.", note
    ).replace("switch it off.\n", f"switch it off.\n{end}")
    model = read_manual(text, HEATER_ACTIONS).model
    walk = next(s for s in model.features.values() if s[0].actions == ["hold_mode"])
    assert len(walk) == 6
    assert all(s.timeout is None for s in walk)


def test_the_pair_s_own_setting_stays_though_a_field_shares_its_word() -> None:
    # the frost guard's field says "temperature" too: the room temperature the legend gives
    # ▲ / ▼ is still theirs, not a guess the walk's words made
    text = THERMOSTAT.replace("shows the frost guard,", "shows the frost guard temperature,")
    model = read_manual(text, THERMOSTAT_ACTIONS).model
    own = [
        s[0].variable for s in model.features.values() if s[0].actions == ["press_up", "press_down"]
    ]
    assert own and "temperature" in str(own[0])


def test_a_page_or_model_span_in_a_step_is_no_range_of_levels() -> None:
    # "see pages 12-14" and "models 200-300" beside the pair are references, not the field's
    # bare levels 12 to 14 or 200 to 300: the walk does not read a field from them
    for aside in ("(see pages 12-14)", "(models 200-300 only)"):
        text = HEATER.replace("(g1, g2, g3; stops at both ends)", aside)
        model = read_manual(text, HEATER_ACTIONS).model
        walks = [s for s in model.features.values() if s[0].actions == ["hold_mode"]]
        fields = {s.variable for w in walks for s in w if s.variable}
        lows = {r[0] for v in fields for r in getattr(model.variables[v], "ranges", None) or []}
        assert not lows & {12, 200}, aside
