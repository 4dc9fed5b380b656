"""Reading what the panel shows and the values a key offers, on small manuals written for the
test (each says one thing one way)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.evaluate import translate_goal
from apbot.read.shown import shown_words


def _read(text: str, actions: list[str]):
    model = read_manual(text, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    return model


def test_the_words_shown_for_running_and_lock_come_from_the_manual():
    text = (
        "Press START/STOP. The flame icon lights and the digits show the temperature.\n\n"
        "To lock, press and hold − and + together for 3 seconds. The padlock icon appears.\n"
    )
    model = _read(text, ["press_power", "press_start", "press_minus", "press_plus",
                         "hold_minus_plus"])  # fmt: skip
    assert model.variables["running"].show == {"off": "", "on": "FLAME"}
    assert model.variables["child_lock"].show == {"off": "", "on": "PADLOCK"}
    assert shown_words("Touch START. RUN appears.", {"START"}) == ["RUN"]


def test_an_icon_named_with_its_printed_glyph_shows_the_glyph():
    # the glyph in brackets after "the ... symbol" is what the screen prints, and a star
    # alone in brackets is no emphasis mark
    text = (
        "Press START to heat.\n\nWhile the grill is heating, other keys are ignored and the sun "
        "symbol (*) stays lit.\n\n*(Optional)* Press STOP to end.\n"
    )
    model = _read(text, ["press_start", "press_stop"])
    assert model.variables["running"].show == {"off": "", "on": "*"}
    assert shown_words("the bell symbol (BUZ) lights when the alarm is set") == ["BUZ"]
    assert shown_words("the bell icon (optional) lights") == ["BELL"]


def test_no_sign_of_running_leaves_running_unread_on_the_display():
    model = _read("Press START to begin.", ["press_start"])
    assert model.variables["running"].visible is False


def test_switching_on_shows_the_idle_screen_or_a_lit_one():
    model = _read("Press POWER to switch on or off.", ["press_power"])
    assert model.variables["power"].show == {"off": "", "on": ""}


def test_preset_keys_give_their_amount_a_starting_value_not_a_one_value_domain():
    text = (
        "Press GREEN TEA, COFFEE or BOIL to choose a preset. Use − and + to fine-tune the "
        "temperature. Out of the box the kettle is set for coffee.\n\n"
        "| Preset key | Temperature |\n|---|---|\n| GREEN TEA | 80 °C |\n| COFFEE | 93 °C |\n"
        "| BOIL | 100 °C |\n\n| Item | Value |\n|---|---|\n| Set temperature range | 40–100 °C |\n"
    )
    actions = ["press_green", "press_coffee", "press_boil", "press_minus", "press_plus"]
    model = _read(text, actions)
    preset = model.variables["preset"]
    assert preset.initial == "coffee"
    temp = next(v for v in model.variables.values() if v.depends_on == "preset")
    assert temp.cases["green tea"].initial == 80
    assert temp.cases["boil"].ranges[0][0] == 40  # the whole range, from the specifications


def test_a_table_of_durations_after_a_colon_is_the_keys_values():
    text = (
        "Press HOLD to choose a hold time. Keep pressing to go round the times:\n\n"
        "| Shown | Hold time |\n|---|---|\n| `--` | no hold |\n| `10` | 10 minutes |\n"
        "| `30` | 30 minutes |\n| `90` | 1 ½ hours |\n"
    )
    model = _read(text, ["press_hold"])
    ranges = model.variables["hold"].ranges
    assert ranges[0][0] == "00:00:00" and ranges[-1][1] == "01:30:00"


def test_end_time_is_a_setting_not_a_stop_key():
    text = "Press END TIME. Press again to move the end further away, by up to 19 hours."
    model = _read(text, ["press_start", "press_end_time"])
    assert "end_time" in model.variables


def test_a_knob_named_before_its_noun_with_its_marks_after_a_colon():
    text = (
        "HUMIDISTAT knob (left). This is also the on/off switch. Printed round the knob:\n\n"
        "OFF · 1 · 2 · 3 · CONT\n\nThe knob stops at OFF and at CONT.\n"
    )
    model = _read(text, ["turn_knob_cw", "turn_knob_ccw"])
    knob = model.variables["knob"]
    assert knob.values == ["off", "1", "2", "3", "cont"]
    assert knob.label == "HUMIDISTAT" and knob.wrap is False
    assert any(g.when == {"knob": "off"} for g in model.guards)  # OFF switches it off


def test_values_printed_in_a_keys_name_and_lamp_lists_that_are_not_values():
    text = "FAN HI/LO changes the fan speed.\n\nLamps (top row): FAN HI, FAN LO, PUMP.\n"
    model = _read(text, ["press_fan"])
    fan = next(iter(model.variables.values()))
    assert fan.values == ["hi", "lo"] and fan.label == "FAN"


def test_a_table_headed_by_key_names_gives_each_key_its_column():
    text = (
        "Above TEMP. and SPIN is a column of lamps for each:\n\n"
        "| TEMP. | SPIN |\n|---|---|\n| Hot | High |\n| Warm | Low |\n| Cold | No Spin |\n"
    )
    model = _read(text, ["press_temp", "press_spin"])
    assert model.variables["temp"].values == ["hot", "warm", "cold"]
    assert model.variables["spin"].values == ["high", "low", "no spin"]


def test_keys_of_an_options_section_are_toggles():
    text = (
        "## Options\n\nOptions are turned on and off by touching their pad.\n\n### PRE-SOAK\n\n"
        "The washer lets the load soak for up to 30 minutes.\n"
    )
    model = _read(text, ["press_presoak"])
    assert model.variables["presoak"].values == ["off", "on"]


def test_names_in_capitals_and_amounts_in_a_keys_own_sentence():
    text = (
        "COLOUR – crust colour, LIGHT, MEDIUM or DARK.\n\n"
        "SIZE – loaf size, 750 g, 1000 g or 1250 g."
    )
    model = _read(text, ["press_colour", "press_size"])
    assert model.variables["colour"].values == ["light", "medium", "dark"]
    assert model.variables["size"].ranges == [(750, 1250, 250)]


def test_a_numbered_menu_key_sets_a_number():
    text = "| Key | Use |\n|---|---|\n| MENU | Next menu number (1–15) |\n\nMENU 1 is Basic."
    model = _read(text, ["press_menu"])
    assert model.variables["menu"].type == "numeric"


def test_translated_goals_use_the_beliefs_spelling():
    true = loads_model(
        """
appliance: {id: t, category: oven, name: t}
controls: [{id: f, label: F}, {id: d, label: D}]
variables:
  function: {type: discrete, values: [bake, convection bake, fan high]}
  delay: {type: time, ranges: [["00:00:00", "12:00:00", 600]]}
actions: {press_f: {control: f}, press_d: {control: d}}
features:
  f: [{actions: [press_f], variable: function, effect: next}]
  d: [{actions: [press_d], variable: delay, effect: next}]
"""
    )
    read = loads_model(
        """
appliance: {id: r, category: oven, name: r}
controls: [{id: f, label: F}, {id: d, label: D}]
variables:
  function: {type: discrete, values: [bake, conv bake, fan hi]}
  delay: {type: numeric, unit: h, ranges: [[0, 12, 1]]}
actions: {press_f: {control: f}, press_d: {control: d}}
features:
  f: [{actions: [press_f], variable: function, effect: next}]
  d: [{actions: [press_d], variable: delay, effect: next}]
"""
    )
    assert translate_goal(read, true, {"function": "convection bake"}) == {"function": "conv bake"}
    assert translate_goal(read, true, {"function": "fan high"}) == {"function": "fan hi"}
    assert translate_goal(read, true, {"delay": "09:00:00"}) == {"delay": 9}
    assert translate_goal(read, true, {"delay": "00:30:00"}) == {"delay": 0.5}


def test_a_key_word_with_on_is_display_text_only_in_a_display_legend():
    # a legend of beeps is no display legend, and POWER ON names the power key's job
    beeps = (
        "Keys\n\n"
        "  POWER        switches the purifier on and off\n"
        "  NIGHT        switches night mode on / off\n\n"
        "Beeps\n\n"
        "  POWER ON     a short double beep\n"
        "  NIGHT ON     a single low beep\n"
    )
    model = _read(beeps, ["press_power", "press_night"])
    assert model.variables["power"].show != {"off": "", "on": "POWER ON"}
    assert "NIGHT ON" not in str(model.variables["night"].show)
    lit = beeps.replace("Beeps", "Symbols on the screen")
    model = _read(lit, ["press_power", "press_night"])
    assert model.variables["night"].show == {"off": "", "on": "NIGHT ON"}
    assert model.variables["power"].show != {"off": "", "on": "POWER ON"}
