"""What the user said that the goal as read does not hold (:mod:`apbot.agent.unread`)."""

from __future__ import annotations

from apbot.agent.unnamed import unnamed_settings
from apbot.agent.unread import unknown_names, unplaced_numbers, unread_parts
from tests.helpers import model_from

CHARGER = """
controls: [{id: mode, label: MODE}, {id: timer, label: TIMER}]
variables:
  mode: {type: discrete, values: [normal, cold], label: MODE}
  timer: {type: discrete, values: ["2 h", "4 h", "8 h", "12 h"], label: TIMER}
actions:
  press_mode: {control: mode}
  press_timer: {control: timer}
features:
  set_mode: [{actions: [press_mode], variable: mode, effect: next}]
  set_timer: [{actions: [press_timer], variable: timer, effect: next}]
display:
  idle: "{mode}"
"""


def test_a_quantity_no_goal_value_holds_is_unread() -> None:
    goal = {"style": "mozzarella", "ripen": "01:00:00", "running": "on"}
    said = "Mozzarella with 4 litres of milk and a one hour ripening time, then start."
    assert unplaced_numbers(said, goal) == ["4 litres"]


def test_numbers_held_in_any_form_are_read() -> None:
    # a duration as minutes or hours, a clock's hour and minute apart, the other scale, a zone
    assert unplaced_numbers("Heat for two and a half hours", {"time": 150}) == []
    assert unplaced_numbers("Set the clock to 21:50", {"hour": 21, "minute": 50}) == []
    assert unplaced_numbers("Reds at 64 °F", {"temperature": 18}) == []
    assert unplaced_numbers("Smoke at 93 °C", {"temperature": 200}) == []
    assert unplaced_numbers("Zone 2 at 190 degrees", {"temperature_2": 190}) == []
    assert unplaced_numbers("The freezer at minus 20", {"freezer": "-20"}) == []


def test_numbers_that_ask_nothing_are_not_unread() -> None:
    assert unplaced_numbers("Toast two slices", {"mode": "toast"}) == []  # a count of things
    assert unplaced_numbers("Run P4 now", {"running": "on"}) == []  # a code
    assert unplaced_numbers("Programme 5, the sweet bread", {"menu": "sweet"}) == []
    assert unplaced_numbers("At 50% power (level 5)", {"power": "50%"}) == []
    assert unplaced_numbers("Day 5 of 17", {"day": 5}) == []  # the whole
    assert unplaced_numbers("Bake at 190... no, make it 180", {"temp": 180}) == []
    assert unplaced_numbers("A kilo and a half of meat", {"weight": 1500}) == []


def test_a_whole_hour_is_not_held_by_the_zero_of_another_value() -> None:
    # "6 am" is 6:00; its minute 0 is no form of it where only a 20-minute run was placed
    assert unplaced_numbers("Mist at 6 am for 20 minutes", {"run": "00:20:00"}) == ["6 am"]
    assert unplaced_numbers("Wake me at 6:00", {"hour": 6, "minute": 0}) == []


def test_a_corrected_number_left_in_the_goal_is_unread() -> None:
    # the parser kept the first figure: the corrected one is what the user wants
    assert unplaced_numbers("Speed 8 - no, make it seven", {"speed": 8}) == ["seven"]


def test_a_named_value_the_setting_lacks_is_unread() -> None:
    model = model_from(CHARGER)
    assert unknown_names(model, "The winter mode for 8 hours") == ["winter mode"]
    assert unread_parts(model, "The winter mode for 8 hours", {"timer": "8 h"}) == ["winter mode"]
    assert unread_parts(model, "The cold mode for 8 hours", {"mode": "cold", "timer": "8 h"}) == []


BREWER = """
controls: [{id: mode, label: MODE}, {id: boil, label: BOIL}, {id: pump, label: RECIRC},
  {id: light, label: NIGHT LIGHT}]
variables:
  mode: {type: discrete, values: [stout, lager], label: MODE}
  boil: {type: discrete, values: ["60", "90"], label: BOIL}
  recirc: {type: discrete, values: ["off", "on"], label: RECIRC}
  night_light: {type: discrete, values: ["off", "on"], label: NIGHT LIGHT}
actions:
  press_mode: {control: mode}
  press_boil: {control: boil}
  press_pump: {control: pump}
  press_light: {control: light}
features:
  set_mode: [{actions: [press_mode], variable: mode, effect: next}]
  set_boil: [{actions: [press_boil], variable: boil, effect: next}]
  pump: [{actions: [press_pump], variable: recirc, effect: toggle}]
  light: [{actions: [press_light], variable: night_light, effect: toggle}]
display:
  idle: "{mode}"
"""


def test_a_setting_named_but_left_out_of_the_goal_is_unread() -> None:
    model = model_from(BREWER)
    said = "A stout with a 90 minute boil and the recirculation pump on"
    # a shortened name said in full; the rest of the goal placed
    assert unnamed_settings(model, said, {"mode": "stout", "boil": "90"}) == ["recirculation"]
    assert unnamed_settings(model, said, {"mode": "stout", "boil": "90", "recirc": "on"}) == []
    # one word of a two-word name is not the name ("light" of a lager's light body)
    assert unnamed_settings(model, "A light lager", {"mode": "lager"}) == []
    # a word beside the goal's own describes that setting (the boil's recirculation)
    assert unnamed_settings(model, "Boil recirculation 90", {"boil": "90"}) == []
    # a setting the user sets aside is not asked for
    assert unnamed_settings(model, "A stout, ignoring the recirculation", {"mode": "stout"}) == []
    # nor one left as it is, or said to matter not
    for left in (
        "A stout, but don't change the recirculation",
        "A stout and leave the recirculation as it is",
        "A stout; the recirculation does not matter",
        "A stout at any recirculation",
    ):
        assert unnamed_settings(model, left, {"mode": "stout"}) == [], left
    # a reason said after the request leaves it a request
    said = "A stout with the recirculation on as it is cold"
    assert unnamed_settings(model, said, {"mode": "stout"}) == ["recirculation"]
    # the unread part stops a claim of success: the goal as read is only a part
    assert unread_parts(model, said, {"mode": "stout", "boil": "90"}) == ["recirculation"]


def test_an_end_of_a_range_asked_in_words_must_be_placed() -> None:
    from apbot.agent.extremes import unmet_extremes

    belief = model_from(CHARGER)
    said = "Charge on the longest timer"
    assert unmet_extremes(belief, said, {"timer": "4 h"}) == ["the longest"]
    assert unmet_extremes(belief, said, {"timer": "12 h"}) == []
    assert unmet_extremes(belief, "Charge as long as it can go", {"timer": "8 h"}) == [
        "as long as it can go"
    ]
    # said beside its figure, the number check answers for it; a request for no end is none
    assert unmet_extremes(belief, "Timer at 4 h, the longest I need", {"timer": "4 h"}) == []
    assert unmet_extremes(belief, "Timer 4 h, the best for the battery", {"timer": "4 h"}) == []


def test_a_setting_named_by_two_capitals_left_out_of_the_goal_is_unread() -> None:
    # a reclining chair with a preset called "PC" (reading at the computer)
    chair = BREWER.replace("label: NIGHT LIGHT}", "label: PC}").replace("night_light", "pc")
    model = model_from(chair)
    assert unnamed_settings(model, "PC recline with a stout", {"mode": "stout"}) == ["pc"]
    assert unnamed_settings(model, "PC recline with a stout", {"mode": "stout", "pc": "on"}) == []
    # two small letters are a word ("go", "up"), not a name
    assert unnamed_settings(model, "a stout, pc style", {"mode": "stout"}) == []
