"""Rules found on the fifth round of blind styled manuals (a washer's cycle chart whose header
sits on the page before its rows, ...), each on a small manual of our own."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read import read_manual


def _values(model, name: str) -> list[str]:  # type: ignore[no-untyped-def]
    var = model.variables[name]
    assert isinstance(var, DiscreteVariable), var
    return [str(v).lower() for v in var.values]


# a dishwasher-like steamer whose programme chart breaks over a page right under its header:
# the running footer and header of the next page sit between the header and the rows
PAGED = """Lumo Steamer Guide                                            Page 1 of 6
==========================================================================

KEYS

PROGRAM   Turns to the next programme in the chart below.
START     Starts the programme.

PROGRAMME CHART

   Programme        Heat                 Time

Lumo Steamer Guide                                            Page 2 of 6
==========================================================================

   Greens           Low, Medium          8 min
   Fish             Medium               12 min
   Rice             High, Medium         25 min
   Eggs             Low                  10 min

Lumo Steamer Guide                                            Page 3 of 6
==========================================================================

CLEANING

Wipe the tray after use.
"""


def test_a_chart_whose_header_is_on_the_page_before_keeps_its_rows() -> None:
    model = read_manual(PAGED, ["press_program", "press_start"]).model
    name = next(n for n in model.variables if "prog" in n)
    assert _values(model, name) == ["greens", "fish", "rice", "eggs"]


# an oven whose specification table labels its clock-like range as minutes and seconds
LABELLED = """KEYS

COOK TIME   Then type the time on the number keys.
START       Starts cooking.

SPECIFICATIONS

Output              900 W
Cooking time        0:01 - 59:59 (min:s)
"""


def test_a_clock_range_labelled_min_s_is_minutes_and_seconds() -> None:
    digits = [f"press_{d}" for d in range(10)]
    model = read_manual(LABELLED, ["press_cook_time", "press_start", *digits]).model
    name = next(n for n in model.variables if "cook" in n)
    spec = model.variables[name].model_dump()
    assert spec["type"] == "time", spec
    assert spec["ranges"][-1][1] == "00:59:59", spec["ranges"]


# a fan heater whose chart gives the order of one key's presses per mode, each line led by the
# mode's name in capitals and the orders run together when the lines are joined
ORDERS = """KEYS

MODE      Chooses the mode: COMFORT, ECO or NIGHT.
FAN       Changes the fan speed for the mode chosen.
START     Starts heating.

FAN SPEEDS

Sequence of FAN presses:  COMFORT  gentle → brisk → strong → gentle …
                          ECO  gentle → brisk → gentle …
                          NIGHT  gentle → quiet → gentle …
"""


def test_an_order_led_by_a_mode_name_in_capitals_lists_the_lower_case_steps() -> None:
    model = read_manual(ORDERS, ["press_mode", "press_fan", "press_start"]).model
    name = next(n for n in model.variables if "fan" in n)
    assert _values(model, name)[:3] == ["gentle", "brisk", "strong"]


# a washer whose chart lists, per programme, the spin speeds it offers; the default is marked
# with a symbol the text conversion drops, and the SPIN key's own line names no speed
CHART = """KEYS

PROGRAM knob   Chooses the programme.
SPIN           Final spin speed. Each touch lights the next one.
START          Starts the wash.

PROGRAMME CHART

   Program          Spin                     Suitable for
   Cottons          Low, Medium ◆, High      towels, bed linen
   Synthetics       Low ◆, Medium            shirts, blouses
   Wool             Low                      jumpers marked for machine washing
"""


def test_a_chart_listing_a_keys_choices_per_programme_gives_its_values_and_cases() -> None:
    model = read_manual(CHART, ["turn_program_cw", "press_spin", "press_start"]).model
    spin = model.variables["spin"].model_dump()
    assert spin["type"] == "discrete" and spin["depends_on"], spin
    cases = {k: v["values"] for k, v in spin["cases"].items()}
    assert cases["cottons"] == ["low", "medium", "high"]
    assert cases["synthetics"] == ["low", "medium"]


# a microwave whose longest time (99 minutes 59 seconds) is typed as minutes and seconds: every
# second can be typed, however long the range
LONG_TYPED = """KEYS

COOK TIME   Then type the time on the number keys.
START       Starts cooking.

SPECIFICATIONS

Cooking time        0:01 - 99:59 (min:s)
"""


def test_a_time_typed_as_minutes_and_seconds_steps_by_one_second() -> None:
    digits = [f"press_{d}" for d in range(10)]
    model = read_manual(LONG_TYPED, ["press_cook_time", "press_start", *digits]).model
    name = next(n for n in model.variables if "cook" in n)
    spec = model.variables[name].model_dump()
    assert tuple(spec["ranges"][-1][1:]) == ("01:39:59", 1), spec["ranges"]
