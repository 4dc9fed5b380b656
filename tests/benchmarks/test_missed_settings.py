"""The missed-settings diagnostic's origin columns: the shape of a manual line, where the values'
line stands from the key, how the values are printed, and which reader module made a variable
(checked on development data only: a newcats appliance and lines written here)."""

from __future__ import annotations

import re

from apbot.bench.suite import load_suite
from apbot.read.evaluate import align_variables
from apbot.read.reader import read_manual
from benchmarks.missed_settings import (
    NOTE_ORIGINS,
    key_place,
    line_shape,
    note_kind,
    note_origins,
    origin,
    origin_tags,
    written_case,
)


def test_line_shape_marks_place_and_contents() -> None:
    assert (
        line_shape("| **TIMER** | Sets 1–8 h (see below) |") == "table+timedig+range+paren+cells2"
    )
    assert line_shape("- Choose LOW, MEDIUM, HIGH or AUTO.") == "item+or+commas"
    assert line_shape("Press MODE: Eco → Normal → Boost") == "prose+arrows"
    assert line_shape("") == "none"


def test_key_place_and_written_case() -> None:
    manual = "Intro\nPress FAN to choose Low or High.\nMore\n"
    line = "Press FAN to choose Low or High."
    assert key_place(manual, line, {"press_fan"}) == "key-on"
    assert key_place(manual, "More", {"press_fan"}) == "key-near"
    assert key_place(manual, "Intro", {"press_heat"}) == "key-far"
    assert written_case(line, ["low", "high"]) == "title"
    assert written_case("LOW or high", ["low", "high"]) == "caps+lower"


def test_note_kind_uses_the_readers_phrasing_never_the_manuals_words() -> None:
    assert note_kind("range 1–8 h (the manual gives none)") == "range"
    assert note_kind("an on/off setting") == "onoff"
    assert note_kind("cotton, wool, silk") == "values-or-other"  # (a values note: not printed)


def test_origin_rows_name_kinds_module_and_shapes_on_development_data() -> None:
    suite = load_suite("benchmarks/data/newcats")
    appliance = next(a for a in suite.appliances if a.id == "bp_monitor_1")
    truth = appliance.model
    with note_origins():
        reading = read_manual(appliance.manual, list(truth.actions))
    try:
        aligned = align_variables(reading.model, truth)
        modules = {origin(reading, v).split()[0] for v in reading.model.variables}
        assert modules and all(m.startswith("from:") for m in modules)
        assert not any(m.startswith("from:build:") for m in modules)  # the rule, not its helper
        missed = [v for v in truth.variables if v not in set(aligned.values())]
        rows = [
            r for v in missed for r in origin_tags(reading, truth, v, aligned, appliance.manual)
        ]
        pattern = r"(own|other) read:\w+ true:\w+ from:\w+:[\w-]+ src:\S+ vals:\S+( tab:\S+)?"
        assert rows and all(re.fullmatch(pattern, row) for row in rows)
        plain = [
            r
            for v in missed
            for r in origin_tags(reading, truth, v, aligned, appliance.manual, detail=False)
        ]  # what --held-out prints: no table build marks of an unseen manual
        assert plain == [re.sub(r" tab:\S+$", "", row) for row in rows]
        assert any(" tab:" in row for row in rows) and not any(" tab:" in r for r in plain)
    finally:
        NOTE_ORIGINS.clear()


def test_table_detail_tells_a_drawn_line_from_a_table_row() -> None:
    from benchmarks.missed_shapes import table_detail

    drawn = "  MAINS  |  BLEND   PULSE  SMOOTH  CRUSH  |  START"
    manual = f"Panel\n\n```\n{drawn}\n```\n"
    detail = table_detail(manual, drawn, {"press_blend"}, ["pulse", "smooth", "crush"])
    assert detail.startswith("tab:unparsed+ends0+block1+norule+unit:sentence")
    assert "+fence+seg@later" in detail and "+vper0-3-0+keyat1+" in detail
    assert "shape:A_A_A_A" in detail and "+drawn:3+" in detail
    row = "| 2 | BLEND | PULSE | SMOOTH |"
    table = f"| No. | Key | Steps | |\n|---|---|---|---|\n{row}\n"
    assert table_detail(table, row, {"press_blend"}, ["pulse"]) == "tab:rowh4+k@later+lead-digit"
    assert table_detail("Press BLEND.\n", "Press BLEND.", {"press_blend"}, []) == "tab:n/a"
