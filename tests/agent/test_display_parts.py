"""A display that prints several parts apart by a wide gap (the setting being adjusted, then
a lamp or a second readout the belief does not know): a word of the first part the belief
lacks is still read as that setting's value, so the walk can learn it."""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.reader import DisplayReader
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from tests.helpers import model_from

HEATER = """
controls: [{id: heat, label: HEAT}, {id: swing, label: SWING}]
variables:
  heat: {type: discrete, values: [{values}], label: HEAT, wrap: true}
  swing: {type: discrete, values: ["off", "on"], label: SWING, initial: "on"}
actions:
  press_heat: {control: heat}
  press_swing: {control: swing}
features:
  set_heat:
    - {actions: [press_heat], variable: heat, effect: next}
  swing:
    - {actions: [press_swing], variable: swing, effect: toggle}
display: {idle: "HEAT {heat}", indicators: [{lamps}]}
"""


def _heater(values: str, lamps: str) -> str:
    return HEATER.replace("{values}", values).replace("{lamps}", lamps)


def test_a_word_the_belief_lacks_is_read_beside_a_lamp_it_does_not_know() -> None:
    belief = model_from(_heater("low, high, boo", ""))
    reading = DisplayReader(belief).read("HEAT boost  SWING")
    assert reading.hypotheses  # (its own screen, and the idle one printing it alike)
    assert all(h.outside == {"heat": "boost"} and h.partial for h in reading.hypotheses)
    # text the belief cannot place at all stays unknown
    assert DisplayReader(belief).read("ERR  42").unknown


def test_the_panel_spelling_a_value_out_beside_a_lamp_is_still_reached() -> None:
    truth = model_from(_heater("low, high, boost", "swing"))
    belief = model_from(_heater("low, high, boo", ""))  # the manual's short word, no lamp
    env = SimulatorEnvironment(truth, "display")
    assert env.reset().text == "HEAT low  SWING"  # the lamp lit beside the setting
    goal = {"heat": "boo"}  # in the belief's words, as the goal parser read it
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, {"heat": "boost"}))
    assert episode.claimed_success, episode.failure


# a second setting the belief reads with its own label, for a part beside the first
GRILL = HEATER.replace(
    "{id: swing, label: SWING}", "{id: swing, label: SWING}, {id: fan, label: FAN}"
)
GRILL = GRILL.replace(
    "  swing: {type: discrete",
    "  fan: {type: discrete, values: [slow, fast], label: FAN, wrap: true}\n"
    "  swing: {type: discrete",
)
GRILL = GRILL.replace(
    "  press_swing: {control: swing}",
    "  press_swing: {control: swing}\n  press_fan: {control: fan}",
)
GRILL = GRILL.replace(
    "  swing:\n",
    "  set_fan:\n    - {actions: [press_fan], variable: fan, effect: next}\n  swing:\n",
)


def test_a_status_word_or_two_unknown_parts_side_by_side_read_as_no_screen() -> None:
    belief = model_from(GRILL.replace("{values}", "low, high, boo").replace("{lamps}", ""))
    reader = DisplayReader(belief)
    # ON / OFF first is a lamp's status, not a heat value outside the belief's list
    assert reader.read("HEAT ON  FAN").unknown
    assert reader.read("HEAT OFF  TIMER 2 h").unknown
    # two settings each showing a word the belief lacks: which is the main screen is a guess
    assert reader.read("HEAT boost  FAN turbo").unknown
    # one unknown word beside a part the belief reads whole stays the first part's reading
    assert reader.read("HEAT boost  SWING").hypotheses
