"""``apbot suite stats`` counts each format construct on the models that use it, and only them."""

from __future__ import annotations

import pytest

from apbot.bench.stats import CONSTRUCTS, PROCEDURE_CONSTRUCTS, construct_counts
from apbot.examples import example_names, load_example
from tests.helpers import model_from

# the procedure constructs are counted in tests/sim/test_procedures.py
VALUE_CONSTRUCTS = sorted(set(CONSTRUCTS) - set(PROCEDURE_CONSTRUCTS))

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
    "settings remembered per programme or zone": """
        controls: [{id: z, label: ZONE}, {id: b, label: "+"}]
        variables:
          zone: {type: discrete, values: [front, rear]}
          level:
            type: numeric
            depends_on: zone
            remember: true
            cases: {front: {ranges: [[0, 3, 1]]}, rear: {ranges: [[0, 3, 1]]}}
        actions: {press_zone: {control: z}, press_plus: {control: b}}
        features:
          zone: [{actions: [press_zone], variable: zone, effect: next}]
          level: [{actions: [press_plus], variable: level, effect: next}]
    """,
    "cycles that end by themselves": """
        controls: [{id: b, label: START}, {id: u, label: "+"}]
        variables:
          minutes: {type: numeric, unit: min, ranges: [[0, 3, 1]]}
          running: {type: discrete, values: ["off", "on"]}
        actions: {press_start: {control: b}, press_up: {control: u}}
        features:
          start: [{actions: [press_start], variable: running, effect: toggle}]
          minutes: [{actions: [press_up], variable: minutes, effect: next}]
        cycles:
          - {when: {running: "on"}, lasts: minutes, set: {running: "off"}}
    """,
    "skip effects (hold to scroll)": """
        controls: [{id: b, label: UP}]
        variables: {menu: {type: discrete, values: [a, b, c, d]}}
        actions: {press_up: {control: b}, hold_up: {control: b, skill: hold, seconds: 2}}
        features:
          menu:
            - actions: [press_up, hold_up]
              variable: menu
              effect: {press_up: next, hold_up: {skip: 2}}
    """,
    "conditional effects": """
        controls: [{id: b, label: START}]
        variables: {cook: {type: numeric, ranges: [[0, 90, 30]]}}
        actions: {press_start: {control: b}}
        features:
          start:
            - actions: [press_start]
              variable: cook
              effect: {when: {cook: 0}, then: {add: 30}, otherwise: next}
    """,
    "other_than conditions (one dial position)": """
        controls: [{id: d, kind: dial, label: MODE}, {id: b, label: GO}]
        variables:
          mode: {type: discrete, values: ["off", timer]}
          go: {type: discrete, values: ["off", "on"]}
        actions:
          turn: {control: d, skill: turn_cw}
          press_go: {control: b}
        features:
          mode: [{actions: [turn], variable: mode, effect: next}]
          go: [{actions: [press_go], variable: go, effect: toggle}]
        guards:
          - {when: {mode: {other_than: timer}}, only: [turn]}
    """,
}


def test_every_construct_has_a_model_using_it() -> None:
    assert set(USING) == set(VALUE_CONSTRUCTS) and len(PROCEDURE_CONSTRUCTS) == 7


@pytest.mark.parametrize("name", VALUE_CONSTRUCTS)
def test_a_construct_is_counted_where_used(name: str) -> None:
    model = model_from(USING[name])
    examples = [load_example(e) for e in example_names()]
    counts = construct_counts([model, *examples])
    assert counts[name] == 1, counts  # the bundled examples use none of the new constructs
