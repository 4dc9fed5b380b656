"""STOP that may clear what was set for the cycle it stops, whatever the manual says: a setting
the display showed before the STOP is in doubt afterwards, so the agent looks at it (or types it
again) before it claims, rather than claim it on the belief's word (styled microwave_1 t09: a
cook time set, the cycle stopped to set the kitchen timer, started again and claimed at 0:00)."""

from __future__ import annotations

from apbot.agent.budget import Budget
from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.session import AgentConfig, Session
from tests.agent.test_closing_key import BELIEF
from tests.helpers import model_from, run_checked


def _session() -> Session:
    belief = model_from(BELIEF)
    env = SimulatorEnvironment(belief, "display")
    goal = {"cook_time": "00:12:00", "running": "on"}
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    session = Session(AgentConfig(), context, env, Budget())
    session.start()
    return session


def _press(session: Session, *actions: str) -> None:
    for action in actions:
        session.press(session.planned(action))


def test_a_setting_shown_before_a_stop_is_in_doubt_after_it() -> None:
    session = _session()
    _press(session, "press_cook", "press_1", "press_2", "press_0", "press_0", "press_go")
    assert session.unverified({"cook_time"}) == []  # shown: COOK 12:00
    _press(session, "press_go")  # START again stops the cycle (toggle)
    assert session.belief.value("running") == "off"
    assert session.unverified({"cook_time"}) == ["cook_time"]


def test_a_start_puts_nothing_in_doubt() -> None:
    session = _session()
    _press(session, "press_cook", "press_1", "press_2", "press_0", "press_0", "press_go")
    assert session.belief.value("running") == "on"
    assert session.unverified({"cook_time"}) == []


# A massage cushion whose HEAT key switches a heating lamp: switching it off, as the goal asks,
# stops no cycle (review19's probe: the level was looked at again, 6 presses for 5).
CUSHION = """
controls: [{id: power, label: POWER}, {id: mode, label: MODE}, {id: level, label: LEVEL},
           {id: heat, label: HEAT}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  mode:
    type: discrete
    values: [shiatsu, knead, roll]
    show: {shiatsu: SHIATSU, knead: KNEAD, roll: ROLL}
  level: {type: numeric, ranges: [[1, 3, 1]], label: LV}
  heating: {type: discrete, values: ["on", "off"]}
actions:
  press_power: {control: power}
  press_mode: {control: mode}
  press_level: {control: level}
  press_heat: {control: heat}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  level:
    - {actions: [press_level], variable: level, effect: next}
  heat:
    - {actions: [press_heat], variable: heating, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
display:
  idle: "{mode} LV {level}"
  indicators: [heating]
"""


def test_a_run_state_switched_off_as_the_goal_asks_stops_no_cycle() -> None:
    model = model_from(CUSHION)
    goal = {"power": "on", "mode": "knead", "level": 3, "heating": "off"}
    episode, reached = run_checked(model, model, goal)
    assert reached and episode.claimed_success
    assert episode.execution_steps == 5  # power, mode, level twice, heat: no second look
