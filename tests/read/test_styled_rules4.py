"""Rules found on the fourth round of styled manuals (written blind: a bottle washer whose
programme pads sit beside a DRY TIME pad the prose calls "the drying time"), each on a small
manual of our own."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read import read_manual

# a food warmer: two programme pads and a two-word time pad the prose names with its first
# word inflected ("the warming time" for WARM TIME)
WARMER = """PANEL

POWER   SOFT   CRISP   WARM TIME   -   +   START

Touch SOFT or CRISP to pick a programme.
To change the warming time, touch WARM TIME, then + or - to change it.
The warming time can be set from 5 to 45 min in 5-minute steps.
START   starts the programme.
"""
WARMER_ACTIONS = ["press_power", "press_soft", "press_crisp", "press_warm_time"]
WARMER_ACTIONS += ["press_minus", "press_plus", "press_start"]


def test_a_two_word_key_named_with_its_first_word_inflected_takes_the_range() -> None:
    model = read_manual(WARMER, WARMER_ACTIONS).model
    timer = model.variables["warm_time"]
    assert [tuple(r) for r in getattr(timer, "ranges", [])] == [("00:05:00", "00:45:00", 300)]
    for pad in ("soft", "crisp"):  # the programme pads are no timers
        var = model.variables.get(pad)
        assert var is None or isinstance(var, DiscreteVariable), var


# a hob whose HEAT TIME key sets minutes: the name's last word, not its first, says what it is
HOB = """KEYS

HEAT TIME   sets how long the zone stays on: 1 to 90 min, one minute per touch of + or -.
-  +        change the value shown.
START       switches the zone on.
"""


def test_a_name_ending_in_time_is_a_time_whatever_its_first_word() -> None:
    model = read_manual(HOB, ["press_heat_time", "press_minus", "press_plus", "press_start"]).model
    timer = model.variables["heat_time"]
    assert [tuple(r) for r in getattr(timer, "ranges", [])] == [("00:01:00", "01:30:00", 60)]


# a sandwich toaster whose programme chart puts a code first and the pad's name second; the
# first pad's name is broken across two lines of the chart and the action name is not its label
TOASTER = """PANEL

POWER   CHEESE+HAM   CHEESE   PLAIN   START

The display shows the code of the chosen programme.

PROGRAMME CHART

| Code | Pad     | Minutes |
|------|---------|---------|
| A1   | CHEESE+ HAM | 4   |
| A2   | CHEESE  | 3       |
| A3   | PLAIN   | 2       |
"""


def test_a_chart_with_a_column_of_pads_and_one_of_codes_makes_one_choice() -> None:
    actions = ["press_power", "press_deluxe", "press_cheese", "press_plain", "press_start"]
    model = read_manual(TOASTER, actions).model
    choice = next(
        n
        for n, v in model.variables.items()
        if isinstance(v, DiscreteVariable) and "plain" in [str(x).lower() for x in v.values]
    )
    var = model.variables[choice]
    assert isinstance(var, DiscreteVariable)
    assert sorted(str(x).lower() for x in var.values) == ["cheese", "cheese+ham", "plain"]
    assert sorted((var.show or {}).values()) == ["A1", "A2", "A3"]


# a grill whose timer steps are printed as a list with dot leaders between time span and step
GRILL_TIMER = """SETTING THE TIMER

Touch TIMER, then + or -.
     0:00 to 0:20 ........ 1 minute per touch
     0:20 to 2:00 ........ 10 minutes per touch
The timer stops at 2:00.
START    starts grilling.
"""


def test_dot_leaders_between_a_span_and_its_step_keep_both_pieces() -> None:
    model = read_manual(GRILL_TIMER, ["press_timer", "press_minus", "press_plus", "press_start"])
    timer = model.model.variables["timer"]
    assert [tuple(r) for r in getattr(timer, "ranges", [])] == [
        ("00:00:00", "00:20:00", 60),
        ("00:20:00", "02:00:00", 600),
    ]
