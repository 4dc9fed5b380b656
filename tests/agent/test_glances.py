"""A claim rests on the display: a goal setting the display never showed, or showed only before
a press the belief did not foresee, is looked at first where a look changes nothing else."""

from __future__ import annotations

from apbot.agent.budget import Budget
from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.loop import ClosedLoop
from apbot.agent.session import AgentConfig, Session
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from, run_checked

KETTLE = """
controls: [{id: temp, label: TEMP}, {id: start, label: START}]
variables:
  running: {type: discrete, values: ["off", "on"], visible: false}
  temp: {type: numeric, unit: "°C", ranges: [[40, 100, 10]], wrap: true, initial: %(initial)s,
         label: TEMP}
actions:
  press_temp: {control: temp}
  press_start: {control: start}
features:
  set_temp: [{actions: [press_temp], variable: temp, effect: next}]
  start: [{actions: [press_start], variable: running, effect: toggle}]
display:
  idle: "%(idle)s"
"""


def kettle(initial: int, idle: str) -> ApplianceModel:
    return model_from(KETTLE % {"initial": initial, "idle": idle})


def test_a_goal_setting_never_shown_is_looked_at_before_the_cycle_starts() -> None:
    # the appliance starts at 100 °C and says so; the reader guessed 40 and no idle screen,
    # so the belief already "holds" 40 °C: only START is left to press
    truth = kettle(100, "{temp}")
    belief = kettle(40, "")
    episode, reached = run_checked(truth, belief, {"temp": 40, "running": "on"})
    assert reached, [e.text or e.action for e in episode.trace]
    looked = [e for e in episode.trace if e.kind == "action" and e.exploring]
    starts = [i for i, e in enumerate(episode.trace) if e.action == "press_start"]
    assert looked and episode.trace.index(looked[0]) < starts[0]


def test_a_setting_already_shown_as_asked_costs_no_look() -> None:
    truth = kettle(40, "{temp}")
    episode, reached = run_checked(truth, truth, {"temp": 40, "running": "on"})
    assert reached  # not claimed: nothing on the display says the kettle runs
    assert not any(e.exploring for e in episode.trace)
    assert episode.execution_steps == 1


FAN = """
controls: [{id: power}, {id: speed}, {id: up}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  speed: {type: discrete, values: [low, mid, high], label: SPEED}
  timer: {type: numeric, unit: h, ranges: [[0, 8, 1]], wrap: true, label: %(label)s}
actions:
  press_power: {control: power}
  press_speed: {control: speed}
  press_up: {control: up}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  speed: [{actions: [press_speed], variable: speed, effect: next}]
  timer: [{actions: [press_up], variable: timer, effect: next}]
guards:
  - {name: switched off, when: {power: "off"}, only: [press_power], display: "", hide: true}
"""


def fan_session(truth_label: str, belief_label: str) -> Session:
    truth = model_from((FAN % {"label": truth_label}).replace("unit: h,", "unit: hr,"))
    belief = model_from(FAN % {"label": belief_label})
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext("fan", "test", "t", "", {}, belief, actions=tuple(env.actions))
    started = Session(AgentConfig(), context, env, Budget())
    started.start()
    return started


def test_a_press_the_belief_did_not_foresee_puts_earlier_readings_in_doubt() -> None:
    s = fan_session("HOURS", "TIMER")
    s.press(s.planned("press_power"))
    s.press(s.planned("press_speed"))
    assert s.shown("speed") == "mid" and s.unverified({"speed"}) == []
    done = s.press(s.planned("press_up"))  # a screen the belief cannot print
    assert done.surprises and done.seen is not None and done.seen.unknown
    assert s.unverified({"speed"}) == ["speed"]
    s.press(s.planned("press_speed"))
    assert s.unverified({"speed"}) == []  # seen again


def test_another_value_of_the_setting_adjusted_puts_nothing_else_in_doubt() -> None:
    truth = model_from(FAN % {"label": "TIMER"})
    belief = model_from((FAN % {"label": "TIMER"}).replace("[[0, 8, 1]]", "[[0, 8, 2]]"))
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext("fan", "test", "t", "", {}, belief, actions=tuple(env.actions))
    s = Session(AgentConfig(), context, env, Budget())
    s.start()
    s.press(s.planned("press_power"))
    s.press(s.planned("press_speed"))
    done = s.press(s.planned("press_up"))  # 1 h where the belief said 2 h: a value, no more
    assert done.surprises and s.unverified({"speed"}) == []


def test_presses_as_predicted_leave_readings_alone() -> None:
    s = fan_session("TIMER", "TIMER")
    for action in ("press_power", "press_speed", "press_up", "press_up"):
        assert not s.press(s.planned(action)).surprising
    assert s.unverified({"speed", "timer"}) == []


def test_a_still_look_leaves_the_setting_where_it_is() -> None:
    from apbot.agent.looking import route_to_screen
    from apbot.sim.compiled import CompiledModel

    model = kettle(40, "")
    compiled = CompiledModel(model)
    start = compiled.initial_state()
    assert route_to_screen(compiled, start, "temp", model.variables, model.actions) == [
        "press_temp"
    ]  # it moves 40 to 50 on the way: a look only where the value is a guess
    assert (
        route_to_screen(compiled, start, "temp", model.variables, model.actions, still=True) is None
    )


TIMER = """
controls: [{id: timer}, %(keys)s]
variables:
  timer: {type: time, ranges: [["00:00:00", "01:30:00", 1]], label: TIMER,
         entry: {format: "mm:ss"}}
actions:
  press_timer: {control: timer}
%(actions)s
features:
  set_timer:
    - {actions: [press_timer]}
    - {actions: [%(digits)s], variable: timer}
"""


def test_a_setting_typed_on_a_keypad_is_not_glanced_at() -> None:
    from apbot.agent.looking import typed

    model = model_from(
        TIMER
        % {
            "keys": ", ".join(f"{{id: k{d}, kind: key}}" for d in range(10)),
            "actions": "\n".join(f"  press_{d}: {{control: k{d}, digit: {d}}}" for d in range(10)),
            "digits": ", ".join(f"press_{d}" for d in range(10)),
        }
    )
    assert typed(model, "timer")
    assert not typed(kettle(40, ""), "temp")


WASHER = """
controls: [{id: wash}, {id: dry}, {id: time}, {id: plus}, {id: minus}, {id: temp}]
variables:
  programme: {type: discrete, values: [wash, dry], label: PROG}
  dry_time: {type: numeric, unit: min, ranges: [[10, 120, 10]], initial: 40, label: DRY, wrap: true}
  temp: {type: numeric, unit: "°C", ranges: [[40, 60, 10]], initial: 40, label: TEMP}
actions:
  press_wash: {control: wash}
  press_dry: {control: dry}
  press_dry_time: {control: time}
  press_plus: {control: plus}
  press_minus: {control: minus}
  press_temp: {control: temp}
features:
  choose:
    - {actions: [press_wash, press_dry], variable: programme,
       effect: {press_wash: {to: wash}, press_dry: {to: dry}}}
  set_dry_time:
%(dry_time)s
  set_temp:
    - {actions: [press_temp]}
    - {actions: [press_plus, press_minus], variable: temp,
       effect: {press_plus: next, press_minus: prev}}
"""
ENTRY_THEN_PAIR = """    - {actions: [press_dry_time]}
    - {actions: [press_plus, press_minus], variable: dry_time,
       effect: {press_plus: next, press_minus: prev}}"""
ONE_KEY = """    - {actions: [press_dry_time], variable: dry_time, effect: next}"""


def washer(dry_time: str) -> ApplianceModel:
    return model_from(WASHER % {"dry_time": dry_time})


def test_a_probe_that_took_the_setting_away_does_not_end_the_search_for_its_keys() -> None:
    # the belief steps the drying time with DRY TIME; the washer only shows it with that key and
    # adjusts it with + and −. The walk stays on 40; the key named like it (DRY) is probed
    # first and brings up the programme: the setting is brought back before + is tried
    episode, reached = run_checked(washer(ENTRY_THEN_PAIR), washer(ONE_KEY), {"dry_time": 60})
    assert reached, [e.text or e.action for e in episode.trace]
    assert any("press_plus, press_minus adjust it" in r for r in episode.repairs)


def test_choosing_a_programme_puts_the_settings_shown_before_in_doubt() -> None:
    truth = washer(ENTRY_THEN_PAIR)
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext("washer", "test", "t", "", {}, truth, actions=tuple(env.actions))
    s = Session(AgentConfig(), context, env, Budget())
    s.start()
    for action in ("press_dry_time", "press_plus"):
        s.press(s.planned(action))
    assert s.shown("dry_time") == 50 and s.unverified({"dry_time"}) == []
    s.press(s.planned("press_dry"))  # many appliances reset settings to the programme's own
    assert s.unverified({"dry_time"}) == ["dry_time"]
    s.press(s.planned("press_dry_time"))
    assert s.unverified({"dry_time"}) == []


DARK_KETTLE = """
controls: [{id: power}, {id: temp, label: TEMP}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  temp: {type: numeric, unit: "°C", ranges: [[40, 100, 10]], wrap: true, initial: %(initial)s,
         label: TEMP}
actions:
  press_power: {control: power}
  press_temp: {control: temp}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_temp: [{actions: [press_temp], variable: temp, effect: next}]
guards:
  - {name: switched off, when: {power: "off"}, only: [press_power], hide: true}
"""


def test_a_never_shown_setting_behind_a_dark_panel_is_looked_at_with_the_panel_switched_on() -> (
    None
):
    # the goal names only the temperature, which the reader guessed already right: without a
    # look the agent would claim on a dark panel
    truth = model_from(DARK_KETTLE % {"initial": 100})
    belief = model_from(DARK_KETTLE % {"initial": 40})
    episode, reached = run_checked(truth, belief, {"temp": 40})
    assert reached, [e.text or e.action for e in episode.trace]
    pressed = [e.action for e in episode.trace if e.kind == "action"]
    assert pressed[:2] == ["press_power", "press_temp"]


OVEN = """
controls: [{id: power}, {id: start}, %(keys)s]
variables:
  power_level: {type: numeric, unit: "%%", ranges: [[10, 100, 10]],%(initial)s
                entry: {format: number, max_digits: 3}, label: P}
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "*"}}
actions:
  press_power: {control: power}
  press_start: {control: start}
%(actions)s
features:
  set_power_level:
    - {actions: [press_power]}
    - {actions: [%(digits)s], variable: power_level}
  start: [{actions: [press_start], variable: running, effect: {to: "on"}}]
"""


def oven(initial: int | None) -> ApplianceModel:
    return model_from(
        OVEN
        % {
            "initial": f" initial: {initial}," if initial is not None else "",
            "keys": ", ".join(f"{{id: k{d}, kind: key}}" for d in range(10)),
            "actions": "\n".join(f"  press_{d}: {{control: k{d}, digit: {d}}}" for d in range(10)),
            "digits": ", ".join(f"press_{d}" for d in range(10)),
        }
    )


def test_a_keypad_setting_never_shown_whose_guessed_start_is_asked_is_typed_anyway() -> None:
    # the reader read no start value for the power, so the belief starts it at 10 %; it starts
    # at 100 %. The goal asks for 10 %, which the belief already "holds": typing it is the only
    # way to be sure
    episode, reached = run_checked(oven(100), oven(None), {"power_level": 10, "running": "on"})
    assert reached, [e.text or e.action for e in episode.trace]
    # a model that states the start value is believed: nothing typed
    episode, reached = run_checked(oven(10), oven(10), {"power_level": 10, "running": "on"})
    assert reached and episode.claimed_success and episode.execution_steps == 1


def test_a_look_at_a_running_cycle_never_stops_it() -> None:
    # START's screen was not what the belief expected; STOP would show "running" (moved to
    # off), but stopping the cycle to look at it undoes it
    from apbot.agent.looking import route_to_screen
    from apbot.sim.compiled import CompiledModel

    text = OVEN % {
        "initial": " initial: 100,",
        "keys": ", ".join(f"{{id: k{d}, kind: key}}" for d in range(10)) + ", {id: stop}",
        "actions": "\n".join(f"  press_{d}: {{control: k{d}, digit: {d}}}" for d in range(10))
        + "\n  press_stop: {control: stop}",
        "digits": ", ".join(f"press_{d}" for d in range(10)),
    }
    text += '  stop: [{actions: [press_stop], variable: running, effect: {to: "off"}}]\n'
    text += "guards:\n  - {name: running, when: {running: 'on'}, only: [press_stop]}\n"
    model = model_from(text)
    compiled = CompiledModel(model)
    state = compiled.apply(compiled.initial_state(), compiled.action_index["press_start"], 0.2)
    assert state is not None
    assert route_to_screen(compiled, state, "running", model.variables, model.actions) is None


def test_a_go_to_key_that_showed_what_the_belief_cannot_read_sets_no_unreadable_value() -> None:
    # the oven shows "*" while it runs, the belief "RUN": START set something unreadable,
    # which is no value START goes to
    truth = oven(100)
    belief = model_from(
        OVEN.replace('"on": "*"', '"on": RUN')
        % {
            "initial": " initial: 100,",
            "keys": ", ".join(f"{{id: k{d}, kind: key}}" for d in range(10)),
            "actions": "\n".join(f"  press_{d}: {{control: k{d}, digit: {d}}}" for d in range(10)),
            "digits": ", ".join(f"press_{d}" for d in range(10)),
        }
    )
    episode, _ = run_checked(truth, belief, {"power_level": 50, "running": "on"})
    logged = [e.text or "" for e in episode.trace if e.kind == "repair"]
    assert not any("could not repair press_start" in t for t in logged), logged


DEFROST = """
controls: [{id: defrost}, {id: start}, %(keys)s]
variables:
  food: {type: discrete, values: [none, meat, fish], wrap: true, label: dEF}
  weight:
    type: numeric
    unit: g
    entry: {format: number, max_digits: 4}
    label: WEIGHT
%(weight)s
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": RUN}}
actions:
  press_defrost: {control: defrost}
  press_start: {control: start}
%(actions)s
features:
  defrost:
    - {actions: [press_defrost], variable: food, effect: next}
    - {actions: [%(digits)s], variable: weight}
  start: [{actions: [press_start], variable: running, effect: {to: "on"}}]
"""


def defrost(weight: str) -> ApplianceModel:
    return model_from(
        DEFROST
        % {
            "weight": weight,
            "keys": ", ".join(f"{{id: k{d}, kind: key}}" for d in range(10)),
            "actions": "\n".join(f"  press_{d}: {{control: k{d}, digit: {d}}}" for d in range(10)),
            "digits": ", ".join(f"press_{d}" for d in range(10)),
        }
    )


def test_choosing_again_what_a_procedure_starts_with_puts_its_later_settings_in_doubt() -> None:
    # the weight belongs to the food chosen: walking round the foods (and back) brings it back
    # to the food's own start, though the reader knew nothing of it
    truth = defrost(
        "    depends_on: food\n    cases:\n"
        "      none: {ranges: [[0, 0, 1]]}\n"
        "      meat: {ranges: [[100, 2000, 10]], initial: 100}\n"
        "      fish: {ranges: [[100, 1000, 10]], initial: 100}"
    )
    belief = defrost("    ranges: [[0, 2000, 10]]")
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext("oven", "test", "t", "", {}, belief, actions=tuple(env.actions))
    s = Session(AgentConfig(), context, env, Budget())
    s.start()
    for action in ("press_defrost", "press_5", "press_0", "press_0"):
        s.press(s.planned(action))
    assert s.shown("weight") == 500 and s.unverified({"weight"}) == []
    for _ in range(3):  # round the foods and back to meat
        s.press(s.planned("press_defrost"))
    assert s.unverified({"weight"}) == ["weight"]


KETTLE_WARM = """
controls: [{id: temp, label: TEMP}, {id: warm, label: WARM}, {id: start, label: START}]
variables:
  running: {type: discrete, values: ["off", "on"], visible: false}
  warm: {type: discrete, values: ["off", "on"], label: WARM}
  temp: {type: numeric, unit: "°C", ranges: [[40, 100, 10]], wrap: true, initial: %(initial)s,
         label: TEMP}
actions:
  press_temp: {control: temp}
  press_warm: {control: warm}
  press_start: {control: start}
features:
  set_temp: [{actions: [press_temp], variable: temp, effect: next}]
  warm: [{actions: [press_warm], variable: warm, effect: toggle}]
  start: [{actions: [press_start], variable: running, effect: toggle}]
display:
  idle: "%(idle)s"
"""


def test_an_unreadable_setting_does_not_spare_a_never_shown_one_its_look() -> None:
    # the keep-warm setting showed what the belief cannot read and its one look is spent;
    # the temperature was never shown (the reader guessed 40): it is still looked at before
    # START locks the panel
    truth = model_from(KETTLE_WARM % {"initial": 100, "idle": "{temp}"})
    belief = model_from(KETTLE_WARM % {"initial": 40, "idle": ""})
    env = SimulatorEnvironment(truth, "display")
    goal = {"temp": 40, "warm": "off", "running": "on"}
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    loop = ClosedLoop(AgentConfig(), context, env)
    loop.session.start()
    loop.session.unread.add("warm")
    loop.session.budget.once("inspect", "look:warm")
    loop.reasoning_step()
    pressed = [e.action for e in loop.session.episode.trace if e.kind == "action"]
    assert pressed == ["press_temp"]
