"""Rules found on the second round of styled manuals (keypad microwave, knob washer, twin-zone
fryer, commercial hob), each on a small manual of our own."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read import read_manual

# a dryer whose dial positions are only listed in full by a chart's first column; a sentence
# elsewhere names two of them, one a "Cool/Airing" with a slash
DRYER = """CONTROLS

Key    Name            Description
A      Mode dial       Turn it to pick a mode. OFF lies between Cool/Airing and Cotton
                       Dry.
B      START           Starts or pauses drying.

MODE CHART
The chart gives each mode's heat and load. Check the care label first.

Mode            Heat       Max. load   Notes
Cotton Dry      high       8 kg        towels, jeans
Iron Dry        high       8 kg        leaves items damp
Mixed           medium     4 kg
Delicate        low        2 kg        acrylics
Cool/Airing     none       1 kg        freshens

Turn the dial to a mode, then press START.
"""


def _values(model, name: str) -> list[str]:  # type: ignore[no-untyped-def]
    var = model.variables[name]
    assert isinstance(var, DiscreteVariable)
    return [str(v).lower() for v in var.values]


def test_a_charts_first_column_headed_by_the_dials_word_beats_a_sentence_naming_two() -> None:
    model = read_manual(DRYER, ["turn_mode_cw", "turn_mode_ccw", "press_start"]).model
    name = next(n for n in model.variables if "mode" in n)
    values = _values(model, name)
    for mode in ("cotton dry", "iron dry", "mixed", "delicate", "cool/airing"):
        assert mode in values, values


# a grill whose MENU key's chart sits a few sentences under its own heading, its first
# column counting the touches
GRILL = """KEYS
MENU      Chooses an automatic programme. Repeated touches go round the list.
START     Starts cooking.

MENU CHART
Touch MENU until the programme shows, then touch START.
If you touch nothing, the first programme is used.

Touches   Programme       Weight        Hints
1         TOAST           2 – 4 slices  turn halfway
2         CHEESE MELT     1 – 2 plates
3         SAUSAGES        4 – 8 pcs     prick them
4         FISH            200 – 600 g   oil the rack
"""


def test_a_touch_counted_chart_a_few_lines_under_the_keys_heading_lists_its_values() -> None:
    model = read_manual(GRILL, ["press_menu", "press_start"]).model
    name = next(n for n in model.variables if "menu" in n)
    values = _values(model, name)
    assert values == ["toast", "cheese melt", "sausages", "fish"], values
