"""Round-9 reader rules that fired on ordinary manual text (fresh-eyes review), each on a
small manual of our own words."""

from __future__ import annotations

from apbot.read import read_manual

# the stepping pair moves what HOURS chose; the clock's wrap is HOURS', not the pair's own
MOWER = """Gardenbot Mower RM-2

Press START to start mowing.

WORKING HOURS

Press HOURS, then press ▲ or ▼. Each press moves the time by one hour.
The mower keeps its own clock: after 23:00 comes 00:00.
"""


def test_a_wrap_beside_a_keys_step_gives_the_pair_no_setting_of_its_own() -> None:
    model = read_manual(MOWER, ["press_hours", "press_up", "press_down", "press_start"]).model
    assert set(model.variables) == {"running", "hours"}, list(model.variables)


def test_each_press_after_a_key_then_the_pair_in_one_sentence_is_the_pairs() -> None:
    text = MOWER.replace(
        "Press HOURS, then press ▲ or ▼. Each press moves the time by one hour.\nThe",
        "Press HOURS, then press ▲ or ▼. Each press moves the time by one hour. The",
    )
    model = read_manual(text, ["press_hours", "press_up", "press_down", "press_start"]).model
    assert set(model.variables) == {"running", "hours"}, list(model.variables)
    steps = [s for f in model.features.values() for s in f]
    assert any(
        set(s.actions) == {"press_up", "press_down"} and s.variable == "hours" for s in steps
    )
