"""The planner breaks ties between plans of one length by the order the actions are listed in;
the agent reorders the plan found so that the manual decides instead: the settings in the order
the manual gives them (a start stays where the search put it), and only where the belief accepts
the new order."""

from __future__ import annotations

from apbot.agent.plan_order import in_manual_order
from apbot.plan.plan import plan
from apbot.sim.compiled import CompiledModel
from tests.helpers import model_from

POT = """
controls: [{{id: heat, label: HEAT}}, {{id: warm, label: WARM}}, {{id: go, label: GO}}]
variables:
  heat: {{type: discrete, values: [low, mid, high], label: HEAT}}
  warm: {{type: discrete, values: ["off", "on"], label: WARM}}
  running: {{type: discrete, values: ["off", "on"], label: RUN}}
actions:
{actions}
features:
  set_heat:
    - {{actions: [press_heat], variable: heat, effect: {{press_heat: next}}}}
  keep_warm:
    - {{actions: [press_warm], variable: warm, effect: {{press_warm: next}}}}
  start:
    - {{actions: [press_go], variable: running, effect: {{to: "on"}}}}
{guards}
display: {{idle: "READY"}}
"""

ACTIONS = ["  press_heat: {control: heat}", "  press_warm: {control: warm}",
           "  press_go: {control: go}"]  # fmt: skip


def _features(actions: list[str], goal: dict[str, str], guards: str = "") -> list[str]:
    model = model_from(POT.format(actions="\n".join(actions), guards=guards))
    compiled = CompiledModel(model)
    start = compiled.initial_state()
    found = in_manual_order(compiled, start, plan(compiled, start, goal))
    return [m.feature for m in found.macro_actions]


def test_the_same_plan_whatever_the_order_of_the_actions() -> None:
    goal = {"heat": "mid", "warm": "on"}
    given = _features(ACTIONS, goal)
    assert given == _features(ACTIONS[::-1], goal)
    assert given == _features([ACTIONS[1], ACTIONS[2], ACTIONS[0]], goal)
    assert given == ["set_heat", "keep_warm"]  # the manual's order of the settings


def test_the_start_stays_where_the_search_put_it() -> None:
    # only the settings on either side of the start are reordered
    goal = {"heat": "mid", "warm": "on", "running": "on"}
    for actions in (ACTIONS, ACTIONS[::-1], [ACTIONS[1], ACTIONS[2], ACTIONS[0]]):
        features = _features(actions, goal)
        before = features[: features.index("start")]
        assert before == sorted(before, key=["set_heat", "keep_warm"].index)


def test_an_order_the_belief_refuses_is_not_taken() -> None:
    # keeping warm is only possible once running: the start cannot go last
    guard = 'guards: [{when: {running: "off"}, only: [press_heat, press_go]}]'
    goal = {"warm": "on", "running": "on"}
    for actions in (ACTIONS, ACTIONS[::-1]):
        assert _features(actions, goal, guard) == ["start", "keep_warm"]
