"""A walk none of whose texts the belief could read stops as soon as the display's template is
learnt from two of them, so the range it leaves is read from two values. Before a goal value is
taken to be missing, the setting is walked once more, readable now — the same whether other
settings were set before it (and a second walk came anyway) or not."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

# A massage chair: time first, then the intensity, stepping one by one, shown "INT 7".
TRUTH = """
controls: [{id: time, label: TIME}, {id: up, label: "+"}]
variables:
  time: {type: numeric, unit: min, ranges: [[5, 20, 5]], initial: 5, show: "{value} MIN",
         wrap: true}
  intensity: {type: numeric, ranges: [[1, 30, 1]], initial: 10, show: "INT {value}", wrap: true}
actions: {press_time: {control: time}, press_up: {control: up}}
features:
  time: [{actions: [press_time], variable: time, effect: next}]
  intensity: [{actions: [press_up], variable: intensity, effect: next}]
display: {idle: "{time} MIN"}
"""

# The belief read the intensity in steps of five, printed another way ("L7").
BELIEF = """
controls: [{id: time, label: TIME}, {id: up, label: "+"}]
variables:
  time: {type: numeric, unit: min, ranges: [[5, 20, 5]], initial: 5, show: "{value} MIN",
         wrap: true}
  intensity: {type: numeric, ranges: [[1, 56, 5]], initial: 1, wrap: true, show: "L{value}"}
actions: {press_time: {control: time}, press_up: {control: up}}
features:
  time: [{actions: [press_time], variable: time, effect: next}]
  intensity: [{actions: [press_up], variable: intensity, effect: next}]
display: {idle: "{time} MIN"}
"""


def test_a_walk_read_only_after_it_ended_is_walked_again() -> None:
    episode, reached = run(model_from(TRUTH), model_from(BELIEF), {"intensity": 25})
    assert reached, episode.failure
    walks = [n for n in episode.trace if n.kind == "explore" and "intensity under" in n.text]
    assert len(walks) >= 2, [n.text for n in episode.trace]
