"""``apbot suite stats`` counts each format construct on the models that use it, and only them."""

from __future__ import annotations

import pytest

from apbot.bench.stats import CONSTRUCTS, construct_counts
from apbot.examples import example_names, load_example
from tests.helpers import model_from

# one small model per construct (the examples of docs/model-format.md, shortened)
USING: dict[str, str] = {
    "values declared unreachable": """
        controls: [{id: b, label: START}]
        variables:
          stage: {type: discrete, values: [idle, drying, cooling], unreachable: [cooling]}
        actions: {press_start: {control: b}}
        features:
          start: [{actions: [press_start], variable: stage, effect: {to: drying}}]
    """,
}


def test_every_construct_has_a_model_using_it() -> None:
    assert set(USING) == set(CONSTRUCTS)


@pytest.mark.parametrize("name", sorted(CONSTRUCTS))
def test_a_construct_is_counted_where_used(name: str) -> None:
    model = model_from(USING[name])
    examples = [load_example(e) for e in example_names()]
    counts = construct_counts([model, *examples])
    assert counts[name] == 1, counts  # the bundled examples use none of the new constructs
