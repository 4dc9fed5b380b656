"""Faults in how values are shown and typed: valid models whose display or keypad differs."""

from __future__ import annotations

from apbot.bench.faults import display, entry_format
from tests.bench.faults.models import OVEN, every_candidate, keypad, only, oven, shown, value
from tests.helpers import model_from

ON = ["press_power"]
TYPE_5 = ["press_time", "press_5"]


def test_entry_format_minutes_for_mm_ss_reads_a_typed_5_as_five_minutes() -> None:
    truth = keypad()
    candidates = every_candidate(entry_format, truth, "cook_time")
    assert {f.detail for _, f in candidates} == {
        f"typed as {wrong} instead of mm:ss" for wrong in ("minutes", "seconds", "hh:mm")
    }
    minutes, _ = only(candidates, lambda f: "minutes" in f.detail)
    assert value(truth, TYPE_5, "cook_time") == "00:00:00"  # 00:05 is not a value: unchanged
    assert value(minutes, TYPE_5, "cook_time") == "00:05:00"
    assert shown(minutes, TYPE_5) == "COOK 05:00"  # the display format itself is unchanged
    hours, _ = only(candidates, lambda f: "hh:mm" in f.detail)
    typed = ["press_time", "press_3", "press_0"]
    assert value(truth, typed, "cook_time") == "00:00:00"  # 00:30 s: not a value
    assert value(hours, typed, "cook_time") == "00:30:00"


def test_entry_format_leaves_a_typed_number_alone() -> None:
    text = OVEN.replace(
        '  delay: {type: numeric, unit: h, ranges: [[0, 6, 1]], show: "DL{value}"}',
        "  delay: {type: numeric, unit: h, ranges: [[0, 6, 1]], entry: {format: number}}",
    )
    assert every_candidate(entry_format, model_from(text, check=False), "delay") == []


def test_display_template_with_a_letter_dropped() -> None:
    truth = oven()
    ((faulty, fault),) = every_candidate(display, truth, "delay")
    assert fault.detail == "shows 'D{value}' instead of 'DL{value}'"
    assert shown(truth, [*ON, "press_timer"]) == "DL1 h"
    assert shown(faulty, [*ON, "press_timer"]) == "D1 h"


def test_display_label_shortened() -> None:
    truth = oven()
    ((faulty, fault),) = every_candidate(display, truth, "temperature")
    assert fault.detail == "labelled 'TEMP' instead of 'TEMPERATURE'"
    assert shown(faulty, [*ON, "press_temp"]) == "TEMP 180°C"


def test_display_show_map_with_a_wrong_word() -> None:
    text = OVEN.replace(
        "  mode: {type: discrete, values: [bake, grill, defrost, steam]}",
        "  mode:\n    type: discrete\n    values: [bake, grill, defrost, steam]\n"
        '    show: {bake: "BAKE", grill: "GRL", defrost: "DEF", steam: "STEAM"}',
    )
    truth = model_from(text)
    candidates = every_candidate(display, truth, "mode", seeds=8)
    faulty, fault = only(candidates, lambda f: "for 'grill'" in f.detail)
    assert fault.detail == "shows 'GRILL' for 'grill' instead of 'GRL'"
    assert shown(truth, [*ON, "press_mode"]) == "GRL"
    assert shown(faulty, [*ON, "press_mode"]) == "GRILL"
    words = {f.detail for _, f in candidates}
    assert "shows 'STEA' for 'steam' instead of 'STEAM'" in words  # a long word shortened


def test_display_with_the_label_where_the_bare_value_is_shown() -> None:
    text = OVEN.replace('show: "DL{value}"', 'show: "{value}"')
    ((faulty, fault),) = every_candidate(display, model_from(text), "delay")
    assert fault.detail == "shows '{label} {value}' instead of '{value}'"
    assert shown(faulty, [*ON, "press_timer"]) == "DELAY 1 h"
