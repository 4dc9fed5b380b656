"""A quantity the user said that the goal as read holds nowhere is looked for on the panel.

The goal parser leaves out a quantity it cannot place ("a 250 ml cup" where the belief has no
volume at all); the agent hands it to the variable finder under its kind's name, which walks
the keys the belief gives no role. Small panels written for these tests.
"""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.agent.said_entries import said_entries
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from

PANEL = """
controls: [{id: power}, {id: fan}, {id: cup}]
variables:
  power:
    {type: discrete, values: ["off", "on"], initial: "on", show: {"off": "", "on": "FAN {fan}"}}
  fan: {type: numeric, ranges: [[1, 5, 1]], initial: 1, wrap: true, label: FAN}
  cup: {type: numeric, unit: ml, ranges: [[100, 400, 50]], initial: 100, wrap: true, label: CUP}
actions:
  press_power: {control: power}
  press_fan: {control: fan}
  press_cup: {control: cup}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  set_fan:
    - {actions: [press_fan], variable: fan, effect: next}
  set_cup:
    - {actions: [press_cup], variable: cup, effect: next}
guards:
  - {name: switched off, when: {power: "off"}, only: [press_power], display: "", hide: true}
"""


CUP_LINE = next(line + "\n" for line in PANEL.splitlines() if line.startswith("  cup:"))


def _belief() -> ApplianceModel:
    """The panel as a reader that missed the cup altogether would write it."""
    text = PANEL.replace(
        CUP_LINE,
        "",
    ).replace("{actions: [press_cup], variable: cup, effect: next}", "{actions: [press_cup]}")
    return model_from(
        text, check=False
    )  # CUP kept as a plain step: "press CUP" with nothing it sets


def test_a_quantity_no_goal_value_holds_becomes_an_entry_named_by_its_kind() -> None:
    belief = _belief()
    assert said_entries(belief, "Fan on 3 and a 250 ml cup.", {"fan": 3}) == {"volume": "250 ml"}
    assert said_entries(belief, "Run for 20 minutes at fan 2.", {"fan": 2}) == {"time": "20 min"}


def test_held_numbers_counts_and_bare_numbers_open_nothing() -> None:
    belief = _belief()
    assert said_entries(belief, "Fan 3, please.", {"fan": 3}) == {}  # the goal holds it
    assert said_entries(belief, "Fan 3 for two slices.", {"fan": 3}) == {}  # a count of things
    assert said_entries(belief, "Code 2580 and fan 3.", {"fan": 3}) == {}  # no kind to match


def test_an_entry_is_never_named_like_a_belief_setting() -> None:
    belief = model_from(PANEL)  # has "cup", and none named "volume": the name is free
    entries = said_entries(belief, "Fan 2, 300 ml.", {"fan": 2})
    assert entries == {"volume": "300 ml"}
    fan_named = model_from(
        PANEL.replace("  fan: {", "  volume: {")
        .replace("{fan}", "{volume}")
        .replace("variable: fan,", "variable: volume,")
    )
    assert "volume" not in said_entries(fan_named, "Set 2, 300 ml.", {"volume": 2})


def test_the_finder_finds_the_setting_the_parser_left_out_and_sets_it_without_a_claim() -> None:
    truth = model_from(PANEL)
    env = SimulatorEnvironment(truth, "display")
    instruction = "Fan 3 and a 250 ml cup."
    goal = {"fan": 3}  # as parsed: the cup's 250 ml went nowhere
    context = TaskContext("unit", "test", "t", instruction, goal, _belief(), actions=env.actions)
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, {"fan": 3, "cup": 250}))
    assert not episode.claimed_success  # which setting "250 ml" was for is the agent's guess
    assert "whose setting it is was the agent's guess" in episode.failure
    assert any(r.startswith("volume: found under press_cup") for r in episode.repairs)


def test_without_the_setting_on_the_panel_the_run_sets_the_rest_and_claims_nothing() -> None:
    no_cup = PANEL.replace("{id: cup}", "{id: cup2}").replace(
        "press_cup: {control: cup}", "press_cup: {control: cup2}"
    )
    truth = model_from(
        no_cup.replace(
            CUP_LINE,
            "",
        ).replace("{actions: [press_cup], variable: cup, effect: next}", "{actions: [press_cup]}"),
        check=False,
    )
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext(
        "unit", "test", "t", "Fan 3 and a 250 ml cup.", {"fan": 3}, _belief(), actions=env.actions
    )
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, {"fan": 3}))
    assert not episode.claimed_success


def test_a_goal_made_only_of_said_quantities_is_set_and_not_claimed() -> None:
    # the goal reader placed nothing of "warm water only, 250 ml, and pour it": the cup found
    # and set is all the agent can show, and what else was asked is unknown
    truth = model_from(PANEL)
    env = SimulatorEnvironment(truth, "display")
    instruction = "Warm water only, 250 ml, and pour it."
    context = TaskContext("unit", "test", "t", instruction, {}, _belief(), actions=env.actions)
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, {"cup": 250}))
    assert not episode.claimed_success
    assert "whose setting it is was the agent's guess" in episode.failure
