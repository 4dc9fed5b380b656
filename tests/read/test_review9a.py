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


# a key table whose hold column releases the door lock: no lock of the keys
WASHER = """Aquaclean Washer WM-5

KEYS

| Key | Press | Hold 3 s |
|---|---|---|
| SPIN | spin speed 400 / 800 / 1200 | - |
| PAUSE | pause / go on | door lock released |
| START | start the programme | - |

Press SPIN to choose the spin speed.
"""


def test_a_hold_cell_releasing_the_door_lock_is_no_key_lock() -> None:
    actions = ["press_spin", "press_pause", "hold_pause", "press_start"]
    model = read_manual(WASHER, actions).model
    assert "child_lock" not in model.variables, list(model.variables)


def test_a_hold_cell_naming_the_key_lock_still_is_the_lock() -> None:
    text = WASHER.replace("door lock released", "key lock on / off")
    model = read_manual(text, ["press_spin", "press_pause", "hold_pause", "press_start"]).model
    assert "child_lock" in model.variables, list(model.variables)


# a delay told span by span under DELAY's own sentence, next to COOK TIME with no range
RICE = """Ricey Cooker RC-8

TIMERS

Press COOK TIME to set how long it cooks.
Press DELAY to set when the rice is ready:
- from 1:00 to 4:00 each press adds 30 minutes;
- from 4:00 to 12:00 each press adds 1 hour.
Press START to begin.
"""


def test_spans_under_another_keys_sentence_are_not_this_keys() -> None:
    model = read_manual(RICE, ["press_cook_time", "press_delay", "press_start"]).model
    delay = model.variables["delay"].model_dump(mode="json")
    assert len(delay["ranges"]) == 2, delay
    cook = model.variables["cook_time"].model_dump(mode="json")
    assert cook.get("ranges") != delay["ranges"], cook


def test_a_capacity_the_user_is_told_to_choose_in_ah_still_is_a_setting() -> None:
    from apbot.read.values import find_ranges

    told = find_ranges("Press SIZE to choose the battery capacity from 20 - 200 Ah.")
    assert [(r.low, r.high) for r in told] == [(20, 200)], told
    assert find_ranges("Battery sizes  4 - 14 Ah   charging current 1 A") == []
    assert find_ranges("Set the room size, 10 - 50 m², with + and -.")
