"""A value named by the everyday name its manual gives it in brackets. The model, the manual
excerpt and the sentences are written for these tests (a grain mill no suite has)."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction
from apbot.read.goal_aliases import bracket_aliases

MILL = """
appliance: {id: mill_1, category: grain_mill, name: "Kornwerk M3 grain mill", brand: Kornwerk}
controls:
  - {id: grind_key, kind: button, label: "GRIND"}
variables:
  grind:
    type: discrete
    values: [fine, medium, coarse, flakes]
    show: {fine: "FINE", medium: "MED", coarse: "COARSE", flakes: "FLK"}
actions:
  press_grind: {control: grind_key}
features:
  grind:
    - {actions: [press_grind], variable: grind, effect: next}
display:
  idle: "{grind}"
"""

MANUAL = """
GRIND SETTINGS
  Setting    Use                              Time per 500 g
  FINE       bread flour, cakes               4 min
             (pastry)
  MED        wholemeal bread                  3 min
  COARSE     porridge, groats                 2 min
  MED (portion)
  FLK (muesli, oat)    rolled grain (spelt) for breakfast
Press GRIND to go from FINE (default) to FLK (or back to FINE); COARSE (coolest) grinds slowly.
The fine setting (sifted) suits sponge cakes.
"""


@pytest.fixture(scope="module")
def mill() -> ApplianceModel:
    return loads_model(MILL)


@pytest.mark.parametrize(
    ("text", "grind"),
    [("Grind some pastry flour", "fine"), ("Muesli please", "flakes"), ("Oat flakes", "flakes")],
)
def test_a_bracketed_everyday_name_names_the_value(
    mill: ApplianceModel, text: str, grind: str
) -> None:
    assert parse_instruction(mill, text, MANUAL) == {"grind": grind}


def test_only_plain_names_in_brackets_count(mill: ApplianceModel) -> None:
    """No remark ("or back"), no default, no superlative, no count noun ("portion"), no prose
    word ("fine setting"), no bracket inside a description ("rolled grain (spelt)")."""
    shown = {"fine": "FINE", "medium": "MED", "coarse": "COARSE", "flakes": "FLK"}
    forms = {"grind": {value: [value, text] for value, text in shown.items()}}
    names = {stems for _n, _v, stems in bracket_aliases(forms, MANUAL)}
    assert names == {("pastry",), ("muesli",), ("oat",)}


def test_a_bracket_naming_a_setting_names_no_value() -> None:
    """ "AUTO (humidity)": the setting AUTO follows, not another name of AUTO ("set the
    humidity to 50" would choose AUTO too)."""
    forms = {"mode": {"auto": ["auto", "AUTO"]}, "humidity": {"40": ["40"]}}
    manual = "  AUTO (humidity)   keeps the room at the humidity you set\n"
    assert [a for _n, _v, a in bracket_aliases(forms, manual)] == [("humidity",)]
    assert bracket_aliases(forms, manual, ("mode", "humidity")) == []
