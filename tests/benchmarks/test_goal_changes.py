"""The generality check lists the goals a parser change moved and the appliances per set."""

from __future__ import annotations

from benchmarks.goal_changes import diff


def _entry(parsed: dict[str, str], stored: dict[str, str]) -> dict[str, object]:
    return {"instruction": "Heat it to 80 degrees", "parsed": parsed, "expected": stored}


def test_diff_counts_the_appliances_whose_outcome_changed_per_set() -> None:
    want = {"temperature": "80"}
    before = {
        "suite-true/kettle_1/t01": _entry({}, want),
        "newcats-true/grill_1/t02": _entry(want, want),
        "newcats-read/grill_1/t02": _entry({"temp": "70"}, want),
        "suite-true/kettle_1/t02": _entry(want, want),
    }
    after = {
        "suite-true/kettle_1/t01": _entry(want, want),
        "newcats-true/grill_1/t02": _entry({}, want),
        "newcats-read/grill_1/t02": _entry({"temp": "80"}, want),
        "suite-true/kettle_1/t02": _entry(want, want),
    }
    lines = diff(before, after)
    assert lines[0].startswith("+ suite-true/kettle_1/t01")
    assert lines[4].startswith("- newcats-true/grill_1/t02")
    assert not any("newcats-read" in line for line in lines)  # exactness unchanged
    assert lines[-2:] == [
        "newcats-true: outcome changed on 1: grill_1",
        "suite-true: outcome changed on 1: kettle_1",
    ]
    assert any(line.startswith("= newcats-read/grill_1/t02") for line in diff(before, after, True))


def test_no_change_gives_no_lines() -> None:
    same = {"suite-true/kettle_1/t01": _entry({}, {})}
    assert diff(same, same) == []
