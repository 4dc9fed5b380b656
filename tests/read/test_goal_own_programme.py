""" "My own settings", "my own recipe": the one selector with a value kept for the user's own
settings (CUSTOM, MANUAL, USER beside presets) is set to it, even when no setting is named in
that clause. Checked on a soup maker written for these tests and on a read-like model that
says nothing of which settings depend on the programme."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

SOUP = """
appliance: {id: soup_1, category: soup_maker, name: "Brothy B5 soup maker", brand: B}
controls:
  - {id: prog_button, kind: button, label: "PROG"}
  - {id: minus_button, kind: button, label: "-"}
  - {id: plus_button, kind: button, label: "+"}
variables:
  programme:
    type: discrete
    values: [smooth, chunky, soya, {values}]
  cook_time:
    type: numeric
    unit: min
    ranges: [[5, 60, 5]]
    initial: 20
actions:
  press_prog: {control: prog_button}
  press_minus: {control: minus_button}
  press_plus: {control: plus_button}
features:
  programme:
    - {actions: [press_prog], variable: programme, effect: next}
  cook_time:
    - actions: [press_minus, press_plus]
      variable: cook_time
      effect: {press_minus: prev, press_plus: next}
display:
  idle: ""
"""


@pytest.fixture(scope="module", params=["custom", "manual", "user"])
def soup(request: pytest.FixtureRequest) -> ApplianceModel:
    return loads_model(SOUP.replace("{values}", request.param))


@pytest.mark.parametrize(
    "text",
    [
        "My own recipe, 25 minutes.",
        "Leek soup with my own settings - 40 min",
        "Use my own programme for 15 minutes",
    ],
)
def test_my_own_recipe_is_the_users_programme(soup: ApplianceModel, text: str) -> None:
    goal = parse_instruction(soup, text)
    assert goal["programme"] not in ("smooth", "chunky", "soya")


@pytest.mark.parametrize("text", ["Chunky, I'll stir it on my own", "Smooth, my own bowl"])
def test_own_without_a_programme_word_sets_nothing(soup: ApplianceModel, text: str) -> None:
    assert parse_instruction(soup, text).get("programme") in ("smooth", "chunky")
