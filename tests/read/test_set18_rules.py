"""Rules of the set18 session, each on a small manual of our own words: a dial's two turns
named by opposite comparatives are one dial (``turn_comparatives``), a step wider than the range
it steps is said in thousands (``build._in_thousands``), a guide table's head with a bracket is
still the key's column (``evidence_tables``), and keys listed as choosing one setting each go
to their own value (``value_keys._named_keys``); a RUN key starts (``roles_running``), a lamp
word in brackets names no value (``code_glosses``), codes take the minutes of their chart rows
(``code_amounts._row_units``), a figure said in full is the thousands the panel shows
(``goal_thousands``) and a superlative printed beside a number is that number
(``goal_printed_ends``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.code_glosses import _name
from apbot.read.goal import parse_instruction

# a spice grinder whose GRIND dial turns coarser one way and finer the other
GRINDER = """
Pepperella SG-5 spice grinder

  ⏻ power key, GO key, GRIND dial.

  GRIND dial ... nine clicks, 1 (finest) to 9 (coarsest).
                 Turn right = coarser, turn left = finer.

Press ⏻ to switch on. Press GO to grind.
"""

# a polisher whose RPM knob shows thousands on a two-digit screen
POLISHER = """
Shinewell P-20 polisher

  ⏻ ... power
  SPEED knob ... right faster, left slower; every click adds 1,000 rpm

The screen shows the speed in thousands: 4 means 4,000 rpm. The knob goes from 2 (slowest)
to 20 (fastest).

 7  PAD AND SPEED GUIDE

  Pad             | Surface           | Speed (screen)
 -----------------+-------------------+----------------
  Soft foam       | wax finish        | 2 – 5
  Wool            | heavy scratches   | 12 – 20
"""

# a baby monitor whose camera keys each show one camera
CAMERAS = """
Nestview BM-3 baby monitor

  Keys: ⏻, C1, C2, C3, TALK

Press C1, C2 or C3 to choose that camera. The screen shows the chosen camera (C1, C2 or C3)
in its top corner. Hold TALK to speak to the room.
"""


def test_a_step_in_thousands_steps_a_range_shown_in_thousands() -> None:
    model = read_manual(POLISHER, ["press_power", "turn_faster", "turn_slower"]).model
    speed = model.variables["speed"]
    assert speed.type == "numeric"  # (not the pad names of the guide)
    assert [tuple(r) for r in speed.ranges] == [(2, 20, 1)]


def test_keys_listed_as_choosing_one_setting_each_go_to_their_own_value() -> None:
    actions = ["press_power", "press_c1", "press_c2", "press_c3", "press_talk"]
    model = read_manual(CAMERAS, actions).model
    camera = model.variables["camera"]
    assert camera.values == ["c1", "c2", "c3"]
    assert camera.show == {"c1": "C1", "c2": "C2", "c3": "C3"}
    (step,) = model.features["camera"]
    assert {key: goto.to for key, goto in step.effect.items()} == {
        "press_c1": "c1", "press_c2": "c2", "press_c3": "c3",
    }  # fmt: skip


# an engraver whose RUN key starts the spindle, with an auto-off chart of codes and minutes
ENGRAVER = """
Etchmate E-4 engraver

  ⏻ ... power
  RUN ... starts or stops the spindle (RUN lamp lit while it turns)
  MODE ... HAND or PEDAL; lamps HAND / PEDAL
  OFF-TIMER ... auto-off after 15, 30 or 45 minutes, or never

The screen shows the speed in thousands: 9 means 9,000 rpm.


Each press of OFF-TIMER moves to the next code: T-OFF → T15 → T30 → T45 → T-OFF …

  Code   | Spindle stops after
 --------+--------------------
  T-OFF  | never
  T15    | 15 minutes
  T30    | 30 minutes
  T45    | 45 minutes
"""
ENGRAVER_ACTIONS = ["press_power", "press_run", "press_mode", "press_off_timer"]


def test_a_key_called_run_starts_and_stops() -> None:
    model = read_manual(ENGRAVER, ENGRAVER_ACTIONS).model
    (step,) = model.features["run"]
    assert step.variable == "running" and step.effect == "toggle"


def test_a_lamp_word_in_brackets_is_no_longer_name_for_the_value() -> None:
    # "HAND/PEDAL (lamp PEDAL)": where the word shows, not a name; "NOISE (white noise)" is one
    assert _name("lamp PEDAL", "pedal", set()) is None
    assert _name("white noise", "noise", set()) == "white noise"


def test_codes_take_the_minutes_their_chart_rows_give() -> None:
    timer = read_manual(ENGRAVER, ENGRAVER_ACTIONS).model.variables["off_timer"]
    assert timer.values == ["off", "15 min", "30 min", "45 min"]
    assert timer.show == {"off": "T-OFF", "15 min": "T15", "30 min": "T30", "45 min": "T45"}


# the polisher's speed said in full, and the grinder's ends said by their printed superlatives
def test_a_speed_said_in_full_is_read_in_the_thousands_the_panel_shows() -> None:
    actions = ["press_power", "turn_faster", "turn_slower"]
    model = read_manual(POLISHER, actions).model
    goal = parse_instruction(model, "Polish at twelve thousand rpm.", POLISHER)
    assert goal["speed"] == 12
    assert parse_instruction(model, "Run it at 15,000 rpm.", POLISHER)["speed"] == 15


def test_a_turn_accepted_only_while_running_is_guarded_while_stopped() -> None:
    text = GRINDER.replace(
        "Press GO to grind.",
        "Press START to grind and again to stop.\n\nFiner clicks are accepted only while the"
        " burrs turn; on a stopped grinder the screen shows GO FIRST.",
    )
    actions = ["press_power", "press_start", "turn_coarser", "turn_finer"]
    model = read_manual(text, actions).model
    (guard,) = [g for g in model.guards if g.when == {"running": "off"}]
    assert "turn_finer" not in guard.only and "turn_coarser" in guard.only
    assert guard.display == "GO FIRST"


# a tea timer typed on a keypad, its examples showing the bare clock
TEA = """
Brewmaster TT-1 tea timer

  Keys: 0–9, START

Type the brewing time as minutes and seconds; the digits fill from the right. For example
3 0 0 shows 03:00 and 4 5 shows 00:45. Press START to count down.
"""


def test_a_typed_time_whose_examples_show_the_bare_clock_is_shown_alone() -> None:
    actions = [f"press_{d}" for d in range(10)] + ["press_start"]
    model = read_manual(TEA, actions).model
    (name,) = [n for n, v in model.variables.items() if v.type == "time"]
    assert model.variables[name].show == "{value}"


def test_the_first_item_of_an_arrow_list_keeps_its_figure() -> None:
    from apbot.read.value_lists import find_list

    assert find_list("SLOT 1 → SLOT 2 → AUX → SLOT 1 …") == (["SLOT 1", "SLOT 2", "AUX"], "arrows")
    assert find_list("Press LEVEL 1 → 2 → 3") == (["LEVEL", "2", "3"], "arrows")  # (as before)
