"""An order reads the same however politely it is wrapped, and with typographic apostrophes."""

from __future__ import annotations

import pytest

from apbot.examples import load_example
from apbot.read.goal import parse_instruction
from apbot.read.goal_wording import plain_order


@pytest.mark.parametrize(
    ("said", "order"),
    [
        ("Could you please boil the kettle?", "boil the kettle."),
        ("Can you start the dryer now?", "start the dryer now."),
        ("I'd like you to bake a loaf.", "bake a loaf."),
        ("Hey, go ahead and run the quick wash", "run the quick wash"),
        ("Please dry the towels. Could you lock it too?", "dry the towels. lock it too."),
        ("Dry it for an hour, if you could.", "Dry it for an hour, if you could."),
        ("Ready by six o’clock, don’t start it", "Ready by six o'clock, don't start it"),
    ],
)
def test_the_order_inside_the_request(said: str, order: str) -> None:
    assert plain_order(said) == order


def test_a_polite_request_starts_what_the_bare_order_starts() -> None:
    model = load_example("washing_machine")
    bare = parse_instruction(model, "Wash the wool at 30 degrees.")
    assert parse_instruction(model, "Could you please wash the wool at 30 degrees?") == bare
    assert parse_instruction(model, "I'd like you to wash the wool at 30 degrees.") == bare
