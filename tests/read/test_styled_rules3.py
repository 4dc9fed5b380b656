"""Rules found on the third round of styled manuals (written blind: a bread maker's numbered
programme chart, a rice cooker's touch-count row), each on a small manual of our own."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read import read_manual


def _values(model, name: str) -> list[str]:  # type: ignore[no-untyped-def]
    var = model.variables[name]
    assert isinstance(var, DiscreteVariable), var
    return [str(v).lower() for v in var.values]


# a steam oven whose PROG key only points to the chart; the chart numbers its rows and heads
# its names "Programme", not PROG
STEAMER = """KEYS

PROG      Steps on to the next cooking programme, in the order of the overview in chapter 4.
START     Starts the chosen programme.

4  PROGRAMME OVERVIEW

No.   Programme        Suitable for                   Time
1     VEGETABLES       broccoli, carrots, beans       0:15
2     FISH             fillets up to 3 cm thick       0:12
3     REHEAT           plated meals, leftovers        0:10
4     DEFROST          frozen bread and berries       0:30
"""


def test_a_numbered_chart_lends_a_programme_key_its_programme_column() -> None:
    model = read_manual(STEAMER, ["press_prog", "press_start"]).model
    name = next(n for n in model.variables if "prog" in n)
    assert _values(model, name) == ["vegetables", "fish", "reheat", "defrost"]


# a toaster-grill whose BROWN key's values are quoted as the display prints them, the key's
# name in front of each level
GRILL = """KEYS

BROWN     Browning level. Each press goes one level darker and after the darkest back to
          the lightest. The display reads BROWN 1, BROWN 2, BROWN 3 or BROWN 4.
START     Starts toasting.
"""


def test_values_quoted_with_the_keys_own_name_in_front_are_the_levels_alone() -> None:
    model = read_manual(GRILL, ["press_brown", "press_start"]).model
    name = next(n for n in model.variables if "brown" in n)
    var = model.variables[name]
    values = [str(v).lower() for v in getattr(var, "values", [])] or [
        str(x) for r in getattr(var, "ranges", []) for x in (r[0], r[1])
    ]
    assert "brown 1" not in values and "brown 4" not in values, values
    assert {"1", "4"} <= {v.removesuffix(".0") for v in values}, values


# a dehumidifier whose TIMER steps are drawn as a chart printed sideways: a row counting the
# presses over a row of what the display then shows, with an ellipsis for the columns between
DRIER = """TIMER

Each press of TIMER moves the switch-off time on by one step:

     presses    1       2       3      ...     12      13
     shows      1 h     2 h     3 h    ...     12 h    (off)

START     Starts drying.
"""


def test_a_sideways_chart_is_read_upright_with_its_ellipsis_filled() -> None:
    from apbot.read.text import parse_manual

    rows = [u.cells for u in parse_manual(DRIER).units if u.header]
    assert rows[0] == ("1", "1 h") and rows[-1] == ("13", "off"), rows
    assert ("7", "7 h") in rows and len(rows) == 13, rows


def test_a_sideways_touch_chart_gives_the_timer_its_hours() -> None:
    model = read_manual(DRIER, ["press_timer", "press_start"]).model
    name = next(n for n in model.variables if "timer" in n)
    ranges = getattr(model.variables[name], "ranges", [])
    hours = {(str(r[1]), str(r[2])) for r in ranges}
    # twelve hours in steps of one hour, as a number of hours or as a clock time
    assert hours & {("12", "1"), ("12.0", "1.0"), ("12:00:00", "3600")}, ranges


# a juicer whose program table lists a key whose name is also a function word (QUICK)
JUICER = """PROGRAM TABLE

Program        Speed     Time
HARD FRUIT     high      60 s
SOFT FRUIT     medium    45 s
GREENS         low       90 s
QUICK JUICE    high      20 s

Touch the key of the program, then START.
"""


def test_a_key_in_a_programme_tables_first_column_is_one_of_its_choices() -> None:
    actions = ["press_hard_fruit", "press_soft_fruit", "press_greens", "press_quick"]
    model = read_manual(JUICER, [*actions, "press_start"]).model
    group = next(v for v in model.variables.values() if "greens" in getattr(v, "values", []))
    assert "quick juice" in [str(x) for x in group.values], group  # type: ignore[union-attr]


# a bread maker whose delay steps are drawn as a small chart of arrows, each row a piece with
# its own step; three rows split by a wide gap are a chart, not two columns of prose
BAKER = """DELAY

Press DELAY once for each further step:

   0 h → 0.5 h → … → 2 h       30 minutes per press
   2 h → 3 h → … → 10 h        one hour per press
   after 10 h                  back to no delay

START     Starts the programme.
"""


def test_a_chart_of_arrow_pieces_gives_the_delay_both_steps() -> None:
    model = read_manual(BAKER, ["press_delay", "press_start"]).model
    name = next(n for n in model.variables if "delay" in n)
    ranges = [tuple(str(x) for x in r) for r in getattr(model.variables[name], "ranges", [])]
    assert ranges == [("00:00:00", "02:00:00", "1800"), ("02:00:00", "10:00:00", "3600")], ranges


# a fan heater whose legend gives FAN one row per way of touching it: the short press picks
# the fan's level, the hold switches something else on or off
HEATER = """KEYS

FAN (short press)     changes between LOW and HIGH (display FAN low / FAN high).
FAN (hold 2 s)        switches the night glow on or off. A short press leaves it as it is.
START                 starts the heater.
"""


def test_a_legend_row_for_holding_a_key_lends_its_on_off_to_the_hold_only() -> None:
    model = read_manual(HEATER, ["press_fan", "hold_fan", "press_start"]).model
    fan = next((v for v in model.variables.values() if "low" in getattr(v, "values", [])), None)
    assert fan is not None and set(fan.values) == {"low", "high"}, model.variables  # type: ignore[union-attr]
    glow = [n for n in model.variables if "glow" in n]
    assert glow, list(model.variables)


# a dryer whose MODE list has a mode that shares its name with the FAN key
DRYER = """KEYS

MODE                  Each press moves on: NORMAL → DRY → FAN → NORMAL.
FAN                   Press to change between LOW and HIGH (the FAN lamp shows which).
"""


def test_a_list_naming_the_key_itself_among_three_or_more_is_not_that_keys() -> None:
    model = read_manual(DRYER, ["press_mode", "press_fan"]).model
    fan = next(v for n, v in model.variables.items() if n.startswith("fan"))
    assert set(getattr(fan, "values", [])) == {"low", "high"}, fan


# a washer whose delay is set with + and − after the delay key; its two steps are told in one
# sentence, the first piece as "between 0:00 and 4:00", the step as "half an hour"
WASHER = """KEYS

Key    Name           What it does
A      Delay key      Opens the delay start setting (clock symbol)
B      Plus key  +    Lengthens the delay
C      Minus key  −   Shortens the delay

DELAY START
Touch the clock key first; the display shows 0:00. Then touch + or −. Between 0:00 and 4:00 each
touch changes the delay by half an hour; above 4 hours each touch changes it by two hours,
up to 12:00.
"""


def test_a_delay_whose_step_changes_above_a_bound_told_with_clock_figures() -> None:
    model = read_manual(WASHER, ["press_delay", "press_plus", "press_minus"]).model
    delay = next(v for v in model.variables.values() if getattr(v, "ranges", None))
    ranges = [tuple(str(x) for x in r) for r in delay.ranges]  # type: ignore[union-attr]
    assert ranges == [("00:00:00", "04:00:00", "1800"), ("04:00:00", "12:00:00", "7200")], ranges


# a dryer whose legend names its keys by letters, and whose marks over two keys are printed
# after those letters
LETTERED = """THE PANEL

Key    Name              Description
A      Heat key          Steps the heat down one mark with each touch
B      Dryness key       Steps the dryness down one mark with each touch
C      Start key         Starts drying

The marks over keys A and B read:
  A:  high   medium   low   cool air (fan symbol)
  B:  extra dry   cupboard dry   iron dry
"""


def test_marks_printed_after_a_keys_legend_letter_are_its_values() -> None:
    model = read_manual(LETTERED, ["press_heat", "press_dryness", "press_start"]).model
    heat = next(v for n, v in model.variables.items() if n.startswith("heat"))
    dry = next(v for n, v in model.variables.items() if n.startswith("dry"))
    assert getattr(heat, "values", None) == ["high", "medium", "low", "cool air"], heat
    assert getattr(dry, "values", None) == ["extra dry", "cupboard dry", "iron dry"], dry


def test_an_arrow_cycle_ends_at_an_ellipsis() -> None:
    from apbot.read.value_lists import find_list

    found = find_list(
        "Each touch: 0.5 kg → 1 kg → 1.5 kg → 0.5 kg … Then the display reads WEIGHT."
    )
    assert found == (["0.5 kg", "1 kg", "1.5 kg"], "arrows"), found
