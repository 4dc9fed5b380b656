"""The display reader inverts the belief's own display rules, and says when it cannot."""

from __future__ import annotations

import random

import pytest

from apbot.agent.perception import choose
from apbot.agent.reader import DisplayReader
from apbot.bench.suite import load_suite
from apbot.examples import load_example
from apbot.sim.simulator import Simulator
from tests.helpers import model_from

OVEN = """
controls: [{id: power}, {id: mode}, {id: time}, {id: temp}, {id: lock}, {id: start}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  mode: {type: discrete, values: [bake, grill, fan], label: MODE}
  cook_time: {type: time, ranges: [["00:00:00", "02:00:00", 300]], format: "h:mm", label: TIME}
  temperature: {type: numeric, unit: "°C", ranges: [[100, 250, 10]], initial: 180, wrap: true,
                show: "{value} {cook_time}"}
  level: {type: numeric, ranges: [[1, 10, 1]], initial: 5, wrap: true, show: "PL{value}"}
  child_lock: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "LOCK"}}
  running: {type: discrete, values: ["off", "on"]}
  hidden_mode: {type: discrete, values: [a, b], visible: false}
actions:
  press_power: {control: power}
  press_mode: {control: mode}
  press_time: {control: time}
  press_temp: {control: temp}
  press_level: {control: temp}
  hold_lock: {control: lock, skill: hold, seconds: 3}
  press_start: {control: start}
  press_hidden: {control: mode}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_mode: [{actions: [press_mode], variable: mode, effect: next}]
  set_time: [{actions: [press_time], variable: cook_time, effect: next}]
  set_temperature: [{actions: [press_temp], variable: temperature, effect: next}]
  set_level: [{actions: [press_level], variable: level, effect: next}]
  lock: [{actions: [hold_lock], variable: child_lock, effect: toggle}]
  start: [{actions: [press_start], variable: running, effect: {to: "on"}}]
  hidden: [{actions: [press_hidden], variable: hidden_mode, effect: next}]
guards:
  - {name: switched off, when: {power: "off"}, only: [press_power], display: "", hide: true}
  - {name: lock, when: {child_lock: "on"}, only: [hold_lock], display: "LOCKED"}
display:
  idle: "READY {cook_time}"
  indicators: [child_lock, running]
"""


@pytest.fixture(scope="module")
def reader() -> DisplayReader:
    return DisplayReader(model_from(OVEN))


def focus_readings(reader: DisplayReader, text: str, name: str) -> list[dict[str, object]]:
    return [
        {**h.values, **h.outside}
        for h in reader.read(text).hypotheses
        if h.screen.kind == "focus" and h.screen.variable == name
    ]


def test_values_are_read_in_the_variables_own_notation(reader: DisplayReader) -> None:
    assert focus_readings(reader, "TIME 1:35", "cook_time") == [{"cook_time": "01:35:00"}]
    assert focus_readings(reader, "PL7", "level") == [{"level": 7}]
    assert focus_readings(reader, "MODE grill", "mode") == [{"mode": "grill"}]


def test_a_label_abbreviated_or_spelt_out_on_the_display_is_still_read(
    reader: DisplayReader,
) -> None:
    assert focus_readings(reader, "MOD grill", "mode") == [{"mode": "grill"}]
    assert focus_readings(reader, "MODES grill", "mode") == [{"mode": "grill"}]
    spelt = DisplayReader(model_from(OVEN.replace("label: TIME", "label: TIMER")))
    assert focus_readings(spelt, "TIME 1:35", "cook_time") == [{"cook_time": "01:35:00"}]
    assert focus_readings(reader, "MO grill", "mode") == []  # two letters say too little


def test_a_template_naming_another_variable_reads_both(reader: DisplayReader) -> None:
    assert focus_readings(reader, "190°C 0:45", "temperature") == [
        {"temperature": 190, "cook_time": "00:45:00"}
    ]


def test_values_the_belief_lacks_are_kept_apart_as_evidence(reader: DisplayReader) -> None:
    (hypothesis,) = [h for h in reader.read("PL12").hypotheses if h.screen.variable == "level"]
    assert hypothesis.outside == {"level": 12} and not hypothesis.values
    (word,) = [h for h in reader.read("MODE turbo").hypotheses if h.screen.variable == "mode"]
    assert word.outside == {"mode": "turbo"}


def test_lamps_after_the_main_text_give_the_indicators(reader: DisplayReader) -> None:
    (idle,) = [h for h in reader.read("READY 0:30  LOCK  RUNNING").hypotheses]
    assert idle.screen.kind == "idle" and idle.values == {"cook_time": "00:30:00"}
    assert idle.lamps == {"child_lock": {"on"}, "running": {"on"}}
    (unlit,) = [h for h in reader.read("READY 0:30").hypotheses]
    assert unlit.lamps == {"child_lock": {"off"}, "running": {"off"}}


def test_blank_unknown_and_guard_messages_are_different_things(reader: DisplayReader) -> None:
    blank = reader.read("")
    assert blank.blank and not blank.unknown
    kinds = {(h.screen.kind, h.screen.variable) for h in blank.hypotheses}
    assert ("guard", None) in kinds  # switched off
    assert ("focus", "hidden_mode") in kinds  # an invisible setting being adjusted
    assert reader.read("LOCKED").hypotheses[0].screen.kind == "guard"
    unknown = reader.read("E-07 SERVICE")
    assert unknown.unknown and not unknown.blank


def test_a_transient_typing_display_is_unknown_not_a_value() -> None:
    reader = DisplayReader(load_example("microwave_keypad"))
    assert reader.read("COOK 00:80").unknown


def test_more_on_the_display_than_the_belief_prints_is_a_partial_reading(
    reader: DisplayReader,
) -> None:
    reading = reader.read("MODE fan  DOOR OPEN")
    (hypothesis,) = [h for h in reading.hypotheses if h.screen.variable == "mode"]
    assert hypothesis.partial and hypothesis.values == {"mode": "fan"}


def test_an_unknown_word_in_the_first_part_is_read_beside_a_screen_found_after_it(
    reader: DisplayReader,
) -> None:
    # the main screen comes first; another setting's screen printed after it (PL7) must not
    # hide a word there that spells a value short (GR for grill): both are kept as readings
    assert {"mode": "GR"} in focus_readings(reader, "MODE GR  PL7", "mode")
    assert {"level": 7} in focus_readings(reader, "MODE GR  PL7", "level")
    # a word like none of the values stays unread: it may be a part, not a value
    assert focus_readings(reader, "MODE turbo  PL7", "mode") == []
    # a first part the belief reads itself needs nothing more
    assert focus_readings(reader, "MODE grill  PL7", "mode") == [{"mode": "grill"}]


def test_lamps_are_read_around_a_screen_found_inside_unknown_text(
    reader: DisplayReader,
) -> None:
    (idle,) = [h for h in reader.read("READY 0:30  DOOR OPEN").hypotheses]
    assert idle.partial and idle.lamps == {"child_lock": {"off"}, "running": {"off"}}
    (lit,) = [h for h in reader.read("READY 0:30  DOOR OPEN  LOCK").hypotheses]
    assert lit.partial and lit.lamps == {"child_lock": {"on"}, "running": {"off"}}
    (word,) = [h for h in reader.read("READY 0:30  UNLOCKED").hypotheses]
    assert word.lamps["child_lock"] == {"off"}  # a lamp's word inside another word is not it


def test_spacing_and_case_do_not_matter(reader: DisplayReader) -> None:
    assert focus_readings(reader, "  mode   GRILL ", "mode") == [{"mode": "grill"}]


def test_ambiguous_readings_stay_candidates_and_the_prediction_decides() -> None:
    model = model_from(
        """
        controls: [{id: a}, {id: b}]
        variables:
          left: {type: numeric, ranges: [[0, 9, 1]], show: "{value}"}
          right: {type: numeric, ranges: [[0, 9, 1]], show: "{value}"}
        actions: {press_a: {control: a}, press_b: {control: b}}
        features:
          left: [{actions: [press_a], variable: left, effect: next}]
          right: [{actions: [press_b], variable: right, effect: next}]
        """
    )
    reading = DisplayReader(model).read("4")
    assert len(reading.hypotheses) >= 2
    expecting_right = choose(reading, {"left": 0, "right": 3}, ("focus", "right"))
    assert expecting_right.values == {"right": 4} and expecting_right.screen == "right"
    undecided = choose(reading, {"left": 0, "right": 3}, None)
    assert undecided.candidates == {"left": frozenset({4}), "right": frozenset({4})}
    assert undecided.screen_kind is None


def test_every_display_of_every_bundled_appliance_reads_back_as_its_true_state() -> None:
    """The reader is the exact inverse of the simulator's rendering on the true model: along
    random walks, some reading of every display agrees with the true state."""
    for appliance in load_suite().appliances:
        sim, reader = Simulator(appliance.model), DisplayReader(appliance.model)
        rng = random.Random(appliance.id)
        for _ in range(3):
            sim.reset()
            for _ in range(40):
                observation = sim.step(rng.choice(sim.actions))
                truth = sim.assignment()
                reading = reader.read(observation.text, truth)
                assert any(
                    not h.outside
                    and all(truth[n] == v for n, v in h.values.items())
                    and all(truth[n] in allowed for n, allowed in h.lamps.items())
                    and all(truth[n] is None for n in h.absent)
                    for h in reading.hypotheses
                ), (appliance.id, observation.text)


def test_an_unlit_lamp_of_a_programme_dependent_setting_allows_its_absence() -> None:
    """In FAN mode the air conditioner has no TURBO: its dark lamp must not claim "off"."""
    model = model_from(
        """
        controls: [{id: m}, {id: t}]
        variables:
          mode: {type: discrete, values: [cool, fan], show: "{value}"}
          turbo:
            type: discrete
            depends_on: mode
            show: {"off": "", "on": "TURBO"}
            cases: {cool: ["off", "on"]}
        actions: {press_m: {control: m}, press_t: {control: t}}
        features:
          mode: [{actions: [press_m], variable: mode, effect: next}]
          turbo: [{actions: [press_t], variable: turbo, effect: toggle}]
        display: {idle: "{mode}", indicators: [turbo]}
        """
    )
    reader = DisplayReader(model)
    (dark,) = [h for h in reader.read("fan").hypotheses if h.screen.variable == "mode"]
    assert dark.values == {"mode": "fan"} and dark.lamps["turbo"] == {"off", None}
    (lit,) = [h for h in reader.read("cool  TURBO").hypotheses if h.screen.variable == "mode"]
    assert lit.lamps["turbo"] == {"on"}


def test_a_bare_number_is_not_read_out_of_a_lamp_like_1_4() -> None:
    # "1-4" (the small-batch lamp of a coffee maker) is no reading of keep-warm hours shown as
    # a bare number: a value found inside a longer text must stand apart from its neighbours
    model = model_from(
        """
        controls: [{id: warm}, {id: bold}]
        variables:
          keep_warm:
            {type: numeric, unit: h, ranges: [[1, 4, 1]], initial: 2, wrap: true, show: "{value}"}
          strength: {type: discrete, values: [regular, bold], show: {regular: "", bold: BOLD}}
        actions:
          press_warm: {control: warm}
          press_bold: {control: bold}
        features:
          keep_warm: [{actions: [press_warm], variable: keep_warm, effect: next}]
          bold: [{actions: [press_bold], variable: strength, effect: toggle}]
        display:
          indicators: [strength]
        """
    )
    reader = DisplayReader(model)
    assert not any("keep_warm" in h.values for h in reader.read("1-4  BOLD").hypotheses)
    assert any(h.values.get("keep_warm") == 3 for h in reader.read("3 h  BOLD  1-4").hypotheses)


DELAYED_WASHER = """
controls: [{id: prog}, {id: delay}, {id: up}]
variables:
  programme: {type: discrete, values: [cotton, wool, quick], label: PROG}
  delay_on: {type: discrete, values: ["off", "on"], label: END}
  end_time: {type: time, ranges: [["00:00:00", "23:30:00", 1800]], format: "hh:mm", label: END}
actions:
  press_prog: {control: prog}
  press_delay: {control: delay}
  press_up: {control: up}
features:
  programme: [{actions: [press_prog], variable: programme, effect: next}]
  delay:
    - {actions: [press_delay], variable: delay_on, effect: toggle}
    - {actions: [press_up], variable: end_time, effect: next}
display:
  idle: "{programme}"
  indicators: [delay_on]
"""


def test_a_time_in_dashes_is_shown_blank_and_its_switch_is_off() -> None:
    # a finish time switched off shows dashes in its clock's places; the switch's lamp text is
    # the time's own label, so the words tell the switch only by what follows them
    reader = DisplayReader(model_from(DELAYED_WASHER))
    (blank,) = [h for h in reader.read("END --:--").hypotheses if h.screen.variable == "end_time"]
    assert blank.absent == {"end_time"} and blank.lamps["delay_on"] == {"off"}
    (shown,) = [h for h in reader.read("END 06:30").hypotheses if h.screen.variable == "end_time"]
    assert shown.values == {"end_time": "06:30:00"} and shown.lamps["delay_on"] == {"on"}


def test_a_label_in_dashes_beside_another_screen_is_no_lit_lamp() -> None:
    # "END --:--" after the programme: the finish time shown blank, not the delay lamp lit, and
    # not the finish time's screen either (the programme's is the one on show)
    reader = DisplayReader(model_from(DELAYED_WASHER))
    readings = reader.read("PROG wool  MODE 2  END --:--").hypotheses
    assert readings and all(h.values == {"programme": "wool"} for h in readings)
    assert all(h.lamps["delay_on"] == {"off"} for h in readings)


def test_settings_shown_side_by_side_are_read_each_by_its_own_screen() -> None:
    # the belief knows "MENU 2" and "BROWN light" only as screens of their own; the panel
    # prints them together after a running word. Each is read, and "light" (a browning
    # value) is not the LIGHT lamp
    model = model_from(
        """
        controls: [{id: menu}, {id: brown}, {id: lamp}, {id: go}]
        variables:
          menu: {type: numeric, ranges: [[1, 6, 1]], label: MENU}
          browning: {type: discrete, values: [light, dark], label: BROWN}
          lamp: {type: discrete, values: ["off", "on"], label: LIGHT}
          running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "WORKING"}}
        actions:
          press_menu: {control: menu}
          press_brown: {control: brown}
          press_lamp: {control: lamp}
          press_go: {control: go}
        features:
          menu: [{actions: [press_menu], variable: menu, effect: next}]
          browning: [{actions: [press_brown], variable: browning, effect: next}]
          lamp: [{actions: [press_lamp], variable: lamp, effect: toggle}]
          go: [{actions: [press_go], variable: running, effect: toggle}]
        display:
          indicators: [lamp]
        """
    )
    reader = DisplayReader(model)
    (working,) = [
        h
        for h in reader.read("WORKING  MENU 2  BROWN light").hypotheses
        if h.screen.variable == "running"
    ]
    assert working.value("menu") == 2 and working.value("browning") == "light"
    assert working.lamps["lamp"] == {"off"}


def test_a_one_word_lamp_shortened_on_the_display_is_still_its_lamp() -> None:
    # the manual names the lamp SPINNING, the panel prints SPIN; a word that merely starts
    # like it (SPINACH, a menu value) is no lamp
    model = model_from(
        """
        controls: [{id: menu}, {id: spin}]
        variables:
          menu: {type: discrete, values: [soup, spinach], label: MENU}
          spinning: {type: discrete, values: ["off", "on"], label: SPINNING}
        actions:
          press_menu: {control: menu}
          press_spin: {control: spin}
        features:
          menu: [{actions: [press_menu], variable: menu, effect: next}]
          spin: [{actions: [press_spin], variable: spinning, effect: toggle}]
        display:
          idle: "{menu}"
          indicators: [spinning]
        """
    )
    reader = DisplayReader(model)
    (lit,) = [h for h in reader.read("soup  SPIN").hypotheses if h.screen.kind == "idle"]
    assert lit.lamps["spinning"] == {"on"}
    (dark,) = [h for h in reader.read("spinach").hypotheses if h.screen.kind == "idle"]
    assert dark.values == {"menu": "spinach"} and dark.lamps["spinning"] == {"off"}


def test_a_label_of_two_words_may_be_shown_by_its_last_word_alone() -> None:
    # the manual calls it DRY TIME, the narrow panel prints TIME; with a COOK TIME beside it
    # the word alone would say nothing, so it is not read so
    text = """
        controls: [{id: dry}, {id: cook}]
        variables:
          dry_time: {type: time, ranges: [["00:10:00", "01:00:00", 600]], label: DRY TIME}
          OTHER
        actions:
          press_dry: {control: dry}
          press_cook: {control: cook}
        features:
          dry: [{actions: [press_dry], variable: dry_time, effect: next}]
          cook: [{actions: [press_cook], variable: cook_level, effect: next}]
        """
    alone = DisplayReader(
        model_from(text.replace("OTHER", "cook_level: {type: discrete, values: [a, b]}"))
    )
    assert focus_readings(alone, "TIME 40 min", "dry_time") == [{"dry_time": "00:40:00"}]
    beside = DisplayReader(
        model_from(
            text.replace("OTHER", "cook_level: {type: discrete, values: [a, b], label: COOK TIME}")
        )
    )
    assert focus_readings(beside, "TIME 40 min", "dry_time") == []


SHARPENER = """
controls: [{id: stage, label: STAGE}, {id: fn, label: FUNCTION}]
variables:
  stage: {type: discrete, values: [1 coarse, 2 fine, 3 hone], label: STAGE, wrap: true}
  function: {type: discrete, values: [bake, conv bake, broil], label: FUNCTION}
actions:
  press_stage: {control: stage}
  press_function: {control: fn}
features:
  set_stage: [{actions: [press_stage], variable: stage, effect: next}]
  set_function: [{actions: [press_function], variable: function, effect: next}]
display:
  idle: "{function}"
"""


def test_a_name_printed_in_its_other_length_is_read_as_that_value() -> None:
    # the manual names the stages "3 hone", the panel prints STAGE 3; the manual abbreviates
    # "conv bake", the panel spells "convection bake": each is the one value spelt otherwise
    reader = DisplayReader(model_from(SHARPENER))
    assert focus_readings(reader, "STAGE 3", "stage") == [{"stage": "3 hone"}]
    assert focus_readings(reader, "FUNCTION convection bake", "function") == [
        {"function": "conv bake"}
    ]


def test_a_value_is_not_read_out_of_a_longer_name_it_ends() -> None:
    # "convection bake" holds the word bake, but as the end of a name the belief does not
    # print: no partial reading of bake (a gap, or a word the belief knows, would allow one)
    reader = DisplayReader(model_from(SHARPENER.replace("conv bake", "grill")))
    assert all(h.values != {"function": "bake"} for h in reader.read("fan bake").hypotheses)
    assert any(h.values == {"function": "bake"} for h in reader.read("bake  DOOR").hypotheses)


def test_a_switch_shown_blank_when_off_is_not_read_off_beside_its_own_lit_lamp() -> None:
    # the manual's legend: "PAUSE — the child guard is on"; the panel prints nothing when it
    # is off, so a screen of the guard being switched is blank for off: PAUSE beside a blank
    # (here beside the ECO lamp) is the guard on, never the guard switched off
    model = model_from(
        """
        controls: [{id: eco}, {id: key}]
        variables:
          eco: {type: discrete, values: ["off", "on"], label: ECO, show: {"off": "", "on": ECO}}
          guard: {type: discrete, values: ["off", "on"], label: PAUSE,
                  show: {"off": "", "on": PAUSE}}
        actions:
          press_eco: {control: eco}
          hold_key: {control: key, skill: hold, seconds: 3}
        features:
          eco: [{actions: [press_eco], variable: eco, effect: toggle}]
          guard: [{actions: [hold_key], variable: guard, effect: toggle}]
        display:
          indicators: [eco, guard]
        """
    )
    reader = DisplayReader(model)
    for text in ("ECO  PAUSE", "PAUSE"):
        readings = reader.read(text).hypotheses
        assert readings and all(h.value("guard") == "on" for h in readings)
    assert any(h.value("guard") == "off" for h in reader.read("ECO").hypotheses)
