"""The variable finder: a goal setting the belief lacks altogether is found on the panel.

Each test writes a small true panel and a belief that misses one setting the way a reader of
the manual misses it, runs the agent on the truth in display mode, and checks the outcome on
the truth (never a false claim of success) and what the repair says it learnt.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.discovery import infer_setting, lamp_word
from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from


def run(truth: ApplianceModel, belief: ApplianceModel, goal: dict[str, Any]) -> Episode:
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    reached = env.simulator.satisfies(parse_goal(truth, goal))
    assert not (episode.claimed_success and not reached), "a false claim of success"
    assert reached and episode.claimed_success, episode.failure
    return episode


DIGITS = ", ".join(f"press_{d}" for d in range(10))
KEYS = "\n".join(f"  press_{d}: {{control: k{d}, digit: {d}}}" for d in range(10))
CONTROLS = ", ".join(f"{{id: k{d}, kind: key}}" for d in range(10))

PANEL = f"""
controls: [{{id: power}}, {{id: fan}}, {{id: sync}}, {{id: cup}}, {{id: level}}, {{id: start}},
           {CONTROLS}]
variables:
  power: {{type: discrete, values: ["off", "on"], show: {{"off": "", "on": "FAN {{fan}}"}}}}
  fan: {{type: numeric, ranges: [[1, 5, 1]], initial: 1, wrap: true, label: FAN}}
  sync: {{type: discrete, values: ["off", "on"], show: {{"off": "", "on": "SYNC"}}}}
  cup:
    type: discrete
    values: [cup, mug, pot]
    show: {{cup: "CUP 150mL", mug: "MUG 300mL", pot: "POT 600mL"}}
  level:
    type: numeric
    unit: "%"
    ranges: [[10, 100, 10]]
    initial: 100
    entry: {{format: number, max_digits: 3}}
    label: P
  running: {{type: discrete, values: ["off", "on"], show: {{"on": "RUN"}}}}
actions:
  press_power: {{control: power}}
  press_fan: {{control: fan}}
  press_sync: {{control: sync}}
  press_cup: {{control: cup}}
  press_level: {{control: level}}
  press_start: {{control: start}}
{KEYS}
features:
  power:
    - {{actions: [press_power], variable: power, effect: toggle}}
  set_fan:
    - {{actions: [press_fan], variable: fan, effect: next}}
  sync:
    - {{actions: [press_sync], variable: sync, effect: toggle}}
  cup:
    - {{actions: [press_cup], variable: cup, effect: next}}
  set_level:
    - {{actions: [press_level]}}
    - {{actions: [{DIGITS}], variable: level}}
  start:
    - {{actions: [press_start], variable: running, effect: {{to: "on"}}}}
guards:
  - {{name: switched off, when: {{power: "off"}}, only: [press_power], display: "", hide: true}}
display:
  indicators: [sync, running]
"""


def panel(*replacements: tuple[str, str]) -> ApplianceModel:
    text = PANEL
    for old, new in replacements:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    return model_from(text)


def without(name: str) -> tuple[str, str]:
    """The line of a setting's variable (or feature), gone."""
    line = next(line for line in PANEL.splitlines() if line.startswith(f"  {name}:"))
    return line + "\n", ""


def test_a_setting_kept_as_a_plain_step_is_found_under_that_key() -> None:
    # the reader kept "press FAN" as a procedure, without the setting it steps
    belief = panel(
        without("fan"),
        ("power: {type: discrete, values", "power: {type: discrete, initial: 'on', values"),
        ('"on": "FAN {fan}"', '"on": ""'),
        (  # and read START as the procedure's next step
            "{actions: [press_fan], variable: fan, effect: next}",
            "{actions: [press_fan]}\n"
            "    - {actions: [press_start], variable: running, effect: {to: 'on'}}",
        ),
    )
    truth = panel(
        ("power: {type: discrete, values", "power: {type: discrete, initial: 'on', values")
    )
    episode = run(truth, belief, {"fan": 3})
    assert any(r.startswith("fan: found under press_fan") for r in episode.repairs)


def test_a_panel_woken_to_a_screen_the_belief_cannot_read_counts_as_woken() -> None:
    # power on shows the fan, which the belief lacks: the screen is unreadable, yet the panel
    # lit up, so the agent must not press POWER again (that would switch it off)
    belief = panel(
        without("fan"),
        ('"on": "FAN {fan}"', '"on": ""'),
        ("  set_fan:\n    - {actions: [press_fan], variable: fan, effect: next}\n", ""),
        ("  press_fan: {control: fan}\n", ""),
    )
    episode = run(panel(), belief, {"fan": 3})
    assert any(r.startswith("fan: found under press_fan") for r in episode.repairs)
    power = [e for e in episode.trace if e.kind == "action" and e.action == "press_power"]
    assert len(power) == 1


def missing(name: str, key: str, feature: str) -> ApplianceModel:
    """A belief without ``name``, its procedure and its key."""
    lines = PANEL.splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if line.startswith(f"  {feature}:"))
    end = next(i for i in range(start + 1, len(lines)) if not lines[i].startswith("    "))
    text = "".join(lines[:start] + lines[end:])
    variable = next(i for i, line in enumerate(text.splitlines()) if line.startswith(f"  {name}:"))
    rows = text.splitlines(keepends=True)
    stop = next(i for i in range(variable + 1, len(rows)) if not rows[i].startswith("    "))
    text = "".join(rows[:variable] + rows[stop:])
    text = text.replace(f"  {key}: {{control: {name}}}\n", "")
    text = text.replace(f"[{name}, running]", "[running]")
    if feature == "set_level":  # the keypad is used nowhere else: the belief never knew it
        text = text.replace(KEYS + "\n", "").replace(",\n           " + CONTROLS, "")
    return model_from(text)


def test_a_key_that_lights_a_word_and_puts_it_out_is_an_on_off_lamp() -> None:
    belief = missing("sync", "press_sync", "sync")
    episode = run(panel(), belief, {"sync": "on"})
    assert "sync: found under press_sync; an on/off lamp shown as 'SYNC'" in episode.repairs


def test_values_with_nothing_in_common_are_named_by_their_own_words() -> None:
    belief = missing("cup", "press_cup", "cup")
    episode = run(panel(), belief, {"cup": "pot"})
    assert any(r.startswith("cup: found under press_cup; values mug, pot") for r in episode.repairs)
    learnt = infer_setting("cup", ["MUG 300mL", "POT 600mL", "CUP 150mL", "MUG 300mL"], "worded")
    assert learnt is not None and learnt.variable["show"]["pot"] == "POT 600mL"


def test_a_keypad_setting_is_found_by_typing_the_goal_after_its_entry_key() -> None:
    belief = missing("level", "press_level", "set_level")
    episode = run(panel(), belief, {"level": 70})
    assert any(
        r.startswith("level: found under press_level, then the digits") for r in episode.repairs
    )


def test_a_lamp_word_is_one_new_word_without_digits() -> None:
    assert lamp_word("SYNC  Z1 air fry", "1: 200°C  Z1 air fry") == "SYNC"
    assert lamp_word("160°C", "") is None  # a value, not a lamp
    assert lamp_word("ECO  TURBO", "") is None  # two words: not one lamp


def test_in_values_mode_a_text_the_belief_cannot_read_is_still_walked() -> None:
    # the paper's simulator names the value ("sync": "on") but the belief has no such setting:
    # the text stays unread, and the finder learns the lamp from it as in display mode
    belief = missing("sync", "press_sync", "sync")
    env = SimulatorEnvironment(panel(), "values")
    context = TaskContext(
        "unit", "test", "t", "", {"sync": "on"}, belief, actions=tuple(env.actions)
    )
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(panel(), {"sync": "on"}))
    assert episode.claimed_success
    assert "sync: found under press_sync; an on/off lamp shown as 'SYNC'" in episode.repairs


def test_a_setting_no_key_shows_leaves_the_rest_of_the_goal_set_and_started() -> None:
    # the words named a setting the panel does not have ("the crumb softness"): the finder
    # finds no key for it, and the rest of the goal — started — is still what can be done;
    # the agent must not claim the whole goal
    truth = panel(
        ("power: {type: discrete, values", "power: {type: discrete, initial: 'on', values")
    )
    env = SimulatorEnvironment(truth, "display")
    goal = {"fan": 3, "running": "on", "softness": "soft"}
    context = TaskContext("unit", "test", "t", "", goal, truth, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, {"fan": 3, "running": "on"}))
    assert not episode.claimed_success
    assert "softness" in episode.failure


THAW = f"""
controls: [{{id: thaw, label: THAW}}, {{id: clock, label: CLOCK}}, {{id: start, label: START}},
           {CONTROLS}]
variables:
  thaw_menu: {{type: discrete, values: [meat, fish], wrap: true, show: "THAW {{value}}"}}
  WEIGHT_VARIABLE
  clock: {{type: time, ranges: [["00:00:00", "23:59:00", 60]], initial: "00:00:00",
          format: "hh:mm", entry: {{format: "hh:mm"}}}}
  running: {{type: discrete, values: ["off", "on"], show: {{"off": "", "on": "RUN"}}}}
actions:
  press_thaw: {{control: thaw}}
  press_clock: {{control: clock}}
  press_start: {{control: start}}
{KEYS}
features:
  set_thaw:
    - {{actions: [press_thaw], variable: thaw_menu, effect: next}}
    WEIGHT_STEP
  set_clock:
    - {{actions: [press_clock]}}
    - {{actions: [{DIGITS}], variable: clock}}
  start:
    - {{actions: [press_start], variable: running, effect: {{to: "on"}}}}
display: {{idle: "READY", indicators: [running]}}
"""
WEIGHT_VARIABLE = """weight:
    type: numeric
    unit: g
    label: WEIGHT
    depends_on: thaw_menu
    entry: {format: number, max_digits: 4}
    cases:
      meat: {ranges: [[100, 2000, 10]], initial: 100}
      fish: {ranges: [[100, 1000, 10]], initial: 100}"""
WEIGHT_STEP = f"- {{actions: [{DIGITS}], variable: weight}}"


def test_a_weight_typed_after_a_menu_is_found_by_choosing_the_menu_again_and_typing() -> None:
    # THAW chooses the food, then the digits give its weight; the reader kept the digits for
    # the clock only. The goal names the weight after the menu it was said with: THAW is
    # pressed round to the fish again and 450 typed, and the display shows WEIGHT 450 g
    truth = model_from(
        THAW.replace("WEIGHT_VARIABLE", WEIGHT_VARIABLE).replace("WEIGHT_STEP", WEIGHT_STEP)
    )
    belief = model_from(THAW.replace("  WEIGHT_VARIABLE\n", "").replace("    WEIGHT_STEP\n", ""))
    env = SimulatorEnvironment(truth, "display")
    goal = {"thaw_menu": "fish", "thaw_menu_weight": "450 g", "running": "on"}
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    judged = {"thaw_menu": "fish", "weight": 450, "running": "on"}
    assert env.simulator.satisfies(parse_goal(truth, judged)), episode.failure
    assert any(
        r.startswith("thaw_menu_weight: found under press_thaw, then the digits")
        for r in episode.repairs
    )


def test_a_one_digit_count_typed_after_a_menu_is_found_from_two_typed_digits() -> None:
    # the same menu, then one digit for how many portions: one digit shows one text, from
    # which nothing can be read, so another digit goes first and the count replaces it
    portions = """portions:
    type: numeric
    label: QTY
    depends_on: thaw_menu
    entry: {format: number, max_digits: 1}
    cases:
      meat: {ranges: [[1, 4, 1]], initial: 1}
      fish: {ranges: [[1, 4, 1]], initial: 1}"""
    step = f"- {{actions: [{DIGITS}], variable: portions}}"
    truth = model_from(THAW.replace("WEIGHT_VARIABLE", portions).replace("WEIGHT_STEP", step))
    belief = model_from(THAW.replace("  WEIGHT_VARIABLE\n", "").replace("    WEIGHT_STEP\n", ""))
    env = SimulatorEnvironment(truth, "display")
    goal = {"thaw_menu": "fish", "thaw_menu_quantity": 3, "running": "on"}
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    judged = {"thaw_menu": "fish", "portions": 3, "running": "on"}
    assert env.simulator.satisfies(parse_goal(truth, judged)), episode.failure
    assert any(
        r.startswith("thaw_menu_quantity: found under press_thaw, then the digits")
        for r in episode.repairs
    )


def test_a_key_read_as_a_switch_is_walked_when_the_goal_says_a_number_for_it() -> None:
    # the reader took FAN for an on/off "boost" switch; the user asks for fan 3, which no
    # switch holds: the key is walked, the steps it shows are the setting, the switch is gone
    lit = ("power: {type: discrete, values", "power: {type: discrete, initial: 'on', values")
    belief = panel(
        lit,
        ('"on": "FAN {fan}"', '"on": ""'),
        without("fan"),
        ("  sync: {type", '  boost: {type: discrete, values: ["off", "on"]}\n  sync: {type'),
        ("{actions: [press_fan], variable: fan, effect: next}", "{actions: [press_fan], "
         "variable: boost, effect: toggle}"),
    )  # fmt: skip
    episode = run(panel(lit), belief, {"fan": 3})
    assert any(r.startswith("fan: found under press_fan") for r in episode.repairs)
    assert "boost" not in episode.repairs[-1]


def test_a_key_whose_role_takes_the_value_is_not_walked_for_another_setting() -> None:
    # the same switch, and a word it holds: the key keeps its role, nothing found under it
    from apbot.model.key_roles import misread_key

    belief = model_from(
        """
        controls: [{id: fan}]
        variables:
          boost: {type: discrete, values: ["off", "on"]}
          speed: {type: numeric, unit: "%", ranges: [[20, 100, 20]]}
        actions:
          press_fan: {control: fan}
        features:
          boost:
            - {actions: [press_fan], variable: boost, effect: toggle}
          speed:
            - {actions: [press_fan], variable: speed, effect: next}
        """,
        check=False,
    )
    assert not misread_key(belief, "press_fan", "on")
    assert not misread_key(belief, "press_fan", 3)  # the speed it also steps holds a number
    assert misread_key(belief, "press_fan", "400 g")  # a weight is neither a switch nor a %


def test_a_walk_round_midnight_is_a_time_of_day_not_a_duration() -> None:
    from apbot.agent.setting_texts import day_walk

    walk = ["SL 22:30  AUTO", "SL 23:00  AUTO", "SL 23:30  AUTO", "SL 00:00  AUTO"]
    assert day_walk(walk, "2 h") and day_walk(walk, "15 min")
    assert not day_walk(walk, "23:00:00")  # a time of day fits it
    assert not day_walk(["WAIT 2 h", "WAIT 4 h", "WAIT 6 h"], "2 h")
