"""A visit's ends as a breadth-first tree: each end's presses are rebuilt from the tree, and
they are the shortest way there (a clock walked both ways round)."""

from __future__ import annotations

from apbot.plan.visits import explore_tree, explore_visit
from apbot.sim.compiled import compiled_model
from tests.helpers import model_from

CLOCK = """
controls: [{id: timer}, {id: plus}, {id: minus}]
variables:
  timer: {type: time, ranges: [["00:00:00", "00:59:00", 60]], wrap: true}
actions: {press_timer: {control: timer}, press_plus: {control: plus},
          press_minus: {control: minus}}
features:
  set_timer:
    - {actions: [press_timer]}
    - {actions: [press_plus, press_minus], variable: timer,
       effect: {press_plus: next, press_minus: prev}}
"""


def test_every_end_of_a_visit_gets_its_shortest_presses_back() -> None:
    compiled = compiled_model(model_from(CLOCK))
    start = compiled.apply(compiled.initial_state(), compiled.action_index["press_timer"])
    assert start is not None
    step = next(s for s, info in enumerate(compiled.steps) if info.variable >= 0)
    entry = [a for a, target in enumerate(compiled.targets[start.step + 1]) if target == step]
    tree = explore_tree(compiled, start, step, entry, lambda s: s.values)
    assert len(tree.ends) == 60  # every minute of the hour
    for i, end in enumerate(tree.ends):
        presses = tree.path(i)
        assert len(presses) == tree.lengths[i]
        state = start
        for action in presses:
            after = compiled.apply(state, action)
            assert after is not None
            state = after
        assert state == end
        minute = end.values[0]  # entering moves it a minute; back to 0:00 takes two
        assert len(presses) == (min(minute, 60 - minute) if minute else 2)
    assert explore_visit(compiled, start, step, entry, lambda s: s.values) == [
        (end, tree.path(i)) for i, end in enumerate(tree.ends)
    ]
