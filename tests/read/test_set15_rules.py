"""Set15's reader rules, each on short manuals of other appliances written for the test: a run
of codes named by its wrap, cycles printed one per key, a box table's rows under a spanning
group label, a knob's positions followed by their direction, a start confirmed by a second
press (and the keys locked while it runs), and START aiming at "on" of a three-state run."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.code_cycles import code_run
from apbot.read.goal import parse_instruction
from apbot.read.text_boxes import unbox
from apbot.read.value_lists import find_list

_PATTERNS_MANUAL = """\
# Glowmaster bath lamp

## Keys

SCENE — next colour pattern.
DIM + / DIM − — brightness.

## Colour patterns

Each press of SCENE changes to the next pattern. After C6 the lamp shows C1 again.

The brightness is 1 to 5.
"""


def test_a_wrap_between_two_codes_names_the_run() -> None:
    assert code_run("After P8 the display shows P1 again.") == [f"P{n}" for n in range(1, 9)]
    assert code_run("After F05 it returns to F01.") == ["F01", "F02", "F03", "F04", "F05"]
    assert code_run("After P8 the display shows L1 again.") is None  # two kinds of code
    assert code_run("After P8 press START.") is None


def test_the_key_of_a_wrapping_code_run_steps_through_it() -> None:
    model = read_manual(_PATTERNS_MANUAL, ["press_scene", "press_dim_up", "press_dim_down"]).model
    stepped = next(
        s.variable for f in model.features.values() for s in f if "press_scene" in s.actions
    )
    assert stepped is not None
    values = [str(v) for v in getattr(model.variables[stepped], "values", [])]
    assert [v.upper() for v in values] == ["C1", "C2", "C3", "C4", "C5", "C6"]


_CHANNELS_MANUAL = """\
# Tidebox fountain pump

## Keys

SPRAY — next spray pattern of the jet.
FLOW — next flow pattern.

## Patterns

Each key steps through its own patterns and starts again after the last:
   SPRAY:  J1 → J2 → J3 → J1 …
   FLOW:   W1 → W2 → W1 …
"""


def test_cycles_printed_one_per_key_are_each_keys_values() -> None:
    model = read_manual(_CHANNELS_MANUAL, ["press_spray", "press_flow"]).model
    by_key = {
        a: s.variable for f in model.features.values() for s in f for a in s.actions if s.variable
    }
    spray = [str(v) for v in getattr(model.variables[by_key["press_spray"]], "values", [])]
    flow = [str(v) for v in getattr(model.variables[by_key["press_flow"]], "values", [])]
    assert spray == ["j1", "j2", "j3"]
    assert flow == ["w1", "w2"]


def test_rows_under_a_spanning_group_label_are_rows_of_their_own() -> None:
    box = "\n".join(
        [
            "┌───────┬──────┬────────────────┐",
            "│ Group │ Code │ Pattern        │",
            "├───────┼──────┼────────────────┤",
            "│ CALM  │ C1   │ Slow pulse     │",
            "│       │ C2   │ Soft glow      │",
            "├───────┼──────┼────────────────┤",
            "│ PARTY │ X1   │ Strobe, fast   │",
            "│       │      │ and bright     │",
            "└───────┴──────┴────────────────┘",
        ]
    )
    lines = [line for line in unbox(box).split("\n") if line.startswith("| ") and "---" not in line]
    assert "| CALM | C2 | Soft glow |" in lines  # its own row, the group's label carried down
    assert "| PARTY | X1 | Strobe, fast and bright |" in lines  # a wrap still joins its row


def test_a_knobs_positions_end_before_their_direction() -> None:
    found = find_list("FAN knob — four positions, OFF → LOW → MID → HIGH from left to right.")
    assert found == (["OFF", "LOW", "MID", "HIGH"], "arrows")
    found = find_list("Turn the dial clockwise: ECO → NORMAL → INTENSE clockwise; it stops there.")
    assert found is not None and found[0][-1] == "INTENSE"


_KETTLE_MANUAL = """\
# Boilwell tea urn

## Keys

⏻ — on / off.
MODE — next brew mode.
START — two-press start (see below).

## Brew modes

Each press of MODE selects the next mode: GREEN → BLACK → HERBAL → GREEN …

## Starting

For safety the urn asks you to confirm every start.

| You press | Display shows | What happens |
|---|---|---|
| START (1st) | READY? (flashing) | nothing heats yet |
| START (2nd) | HEAT | heating starts |
| START (3rd) | – | heating stops |

While HEAT is shown, MODE is locked: pressing it shows WAIT.
"""


def test_a_start_confirmed_by_a_second_press_is_off_request_on() -> None:
    model = read_manual(_KETTLE_MANUAL, ["press_power", "press_mode", "press_start"]).model
    running = model.variables["running"]
    assert [str(v) for v in getattr(running, "values", [])] == ["off", "confirm", "on"]
    shows = running.show if isinstance(running.show, dict) else {}
    assert shows.get("on") == "HEAT" and shows.get("confirm") == "READY?"
    guard = next(g for g in model.guards if g.when == {"running": "on"})
    assert "press_mode" not in guard.only and "press_start" in guard.only
    assert guard.display == "WAIT"


def test_start_aims_at_on_of_an_off_request_on_run() -> None:
    model = read_manual(_KETTLE_MANUAL, ["press_power", "press_mode", "press_start"]).model
    goal = parse_instruction(model, "Herbal tea, and start it.")
    assert goal.get("running") == "on"  # not the request the first press makes


_BOTTLE_MANUAL = """\
# Fillrite bottle filler

## Keys

⏻ — on / off.
500 — half-litre bottle.
750 — 0.75 litre bottle.

## Bottle size (500 / 750 / 1000)

Press 500 or 750 to choose the bottle size. The display shows the size.

There is no key for the litre bottle: hold 500 and 750 together for 2 seconds; the
display shows 1000.
"""


def test_keys_named_by_their_figures_select_one_setting() -> None:
    actions = ["press_power", "press_500", "press_750", "hold_500_750"]
    model = read_manual(_BOTTLE_MANUAL, actions).model
    size = model.variables["size"]
    assert [str(v) for v in getattr(size, "values", [])] == ["500", "750", "1000"]
    steps = [s for f in model.features.values() for s in f if s.variable == "size"]
    assert len(steps) == 1 and set(steps[0].actions) == set(actions[1:])


def test_a_slot_left_open_while_setting_opens_no_setting() -> None:
    from apbot.read.roles_common import _OPENS_SETTING_RE

    assert (
        _OPENS_SETTING_RE.search("CODE  opens the arming-delay setting").group(1) == "arming-delay"
    )
    assert _OPENS_SETTING_RE.search("the lid was left open while setting the clock") is None
