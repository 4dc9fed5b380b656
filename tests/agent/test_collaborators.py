"""Each collaborator of the closed loop on its own: the session's press, the explorer, the
procedure repairer and the greedy executor, each driven directly against a true simulator."""

from __future__ import annotations

import pytest

from apbot.agent import guards
from apbot.agent.budget import Budget
from apbot.agent.displays import DisplayLearner
from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.explorer import Explorer
from apbot.agent.greedy import GreedyExecutor
from apbot.agent.guards import GuardLearner
from apbot.agent.perception import MISSING, Seen
from apbot.agent.procedures import ProcedureRepairer
from apbot.agent.repair import RepairError
from apbot.agent.session import AgentConfig, Session
from apbot.agent.side_effects import SideEffectLearner
from apbot.model.schema import ApplianceModel
from apbot.plan.plan import plan
from tests.helpers import model_from, suite_model

FAN = """
controls: [{id: power}, {id: speed}, {id: timer}, {id: up}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  speed: {type: discrete, values: [%(speeds)s], label: SPEED}
  timer: {type: numeric, unit: h, ranges: [[0, %(hours)s, 1]], wrap: true, label: TIMER}
actions:
  press_power: {control: power}
  press_speed: {control: speed}
  press_timer: {control: timer}
  press_up: {control: up}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  speed: [{actions: [press_speed], variable: speed, effect: next}]
  timer:
%(timer)s
guards:
  - {name: switched off, when: {power: "off"}, only: [press_power], display: "", hide: true}
"""
TIMER_STEPS = """    - {actions: [press_timer]}
    - {actions: [press_up], variable: timer, effect: next}"""
NO_ENTRY = """    - {actions: [press_timer, press_up], variable: timer,
       effect: {press_timer: none, press_up: next}}"""


def fan(speeds: str = "low, mid, high", hours: int = 4, timer: str = TIMER_STEPS) -> ApplianceModel:
    return model_from(FAN % {"speeds": speeds, "hours": hours, "timer": timer})


def session(truth: ApplianceModel, belief: ApplianceModel, feedback: str = "display") -> Session:
    env = SimulatorEnvironment(truth, feedback)  # type: ignore[arg-type]
    context = TaskContext("fan", "test", "t", "", {}, belief, actions=tuple(env.actions))
    started = Session(AgentConfig(), context, env, Budget())
    started.start()
    return started


def test_a_press_as_predicted_has_no_surprise_and_is_believed() -> None:
    s = session(fan(), fan())
    done = s.press(s.planned("press_power"))
    assert not done.surprising and s.belief.value("power") == "on"
    done = s.press(s.planned("press_speed"))
    assert done.variable == "speed" and not done.surprises and s.shown("speed") == "mid"


def test_a_press_not_as_predicted_keeps_the_observed_value_as_a_surprise() -> None:
    s = session(fan(speeds="low, mid, high"), fan(speeds="low, high"))
    s.press(s.planned("press_power"))
    done = s.press(s.planned("press_speed"))
    assert done.surprises == {"speed": ("high", "mid")}  # mid: a value the belief lacks
    assert s.contradicted == {"speed": "mid"}


def test_a_key_the_appliance_ignores_leaves_the_belief_where_it_was() -> None:
    s = session(fan(), fan(timer=NO_ENTRY))  # the belief misses the TIMER entry step
    s.press(s.planned("press_power"))
    before = s.belief.state
    done = s.press(s.planned("press_up"))
    assert done.unchanged and s.belief.state == before


def test_the_explorer_walks_until_a_value_repeats_and_repairs_the_domain() -> None:
    s = session(fan(hours=6), fan(hours=4))
    for action in ("press_power", "press_timer", "press_up"):
        last = s.press(s.planned(action))
    Explorer(s, DisplayLearner(s)).explore("timer", last)
    assert s.belief.model.variables["timer"].ranges == [(0, 6, 1)]
    assert s.episode.repairs and s.belief.value("timer") == s.shown("timer")


def test_the_explorer_learns_an_entry_format_from_typed_digits() -> None:
    # covered end to end in test_soundness; here: a format that already fits is left alone
    s = session(fan(), fan())
    s.press(s.planned("press_power"))
    last = s.press(s.planned("press_speed"))
    assert not Explorer(s, DisplayLearner(s)).learn_entry_format(
        "speed", last, "mid", unchanged=False
    )


def test_the_repairer_finds_a_missing_entry_step_among_the_procedures_keys() -> None:
    s = session(fan(), fan(timer=NO_ENTRY))
    s.press(s.planned("press_power"))
    done = s.press(s.planned("press_up"))
    ProcedureRepairer(s, GuardLearner(s)).repair_procedure([done])
    steps = s.belief.model.features["timer"]
    assert steps[0].actions == ["press_timer"] and steps[0].variable is None
    s.belief.set_pointer(None)
    target = (s.belief.value("timer") + 2) % 5
    planned = plan(s.belief.compiled, s.belief.state, {"timer": target})
    assert [a.name for a in planned.actions] == ["press_timer", "press_up", "press_up"]
    assert s.shown("timer") is not MISSING  # the probe left the setting on the display


def test_the_guard_learner_explains_a_refusal_by_a_guard_once() -> None:
    s = session(fan(), fan(), feedback="values")
    s.belief.set_value("power", "on")  # the belief wrongly thinks the fan is on
    done = s.press(s.planned("press_speed"))
    guards = GuardLearner(s)
    assert done.refused and guards.explain(done)
    assert s.belief.value("power") == "off"
    s.belief.set_value("power", "on")
    assert not guards.explain(done)  # once only


def test_the_greedy_executor_decides_every_press_from_the_display() -> None:
    truth = fan()
    s = session(truth, truth)
    s.press(s.planned("press_power"))
    macro = plan(s.belief.compiled, s.belief.state, {"speed": "high"}).macro_actions[0]
    reasoning = s.episode.reasoning_steps
    executed = GreedyExecutor(s).execute_greedily(macro)
    assert s.shown("speed") == "high" and len(executed) == 2
    assert s.episode.reasoning_steps == reasoning + 1  # the entry press was planned


def test_a_setting_due_on_the_display_but_unreadable_stays_unconfirmed() -> None:
    # the belief labels the speed "FAN"; the panel says "SPEED": the press is believed, but the
    # display never confirmed it, so success cannot be claimed on it
    s = session(
        fan(),
        model_from(
            (FAN % {"speeds": "low, mid, high", "hours": 4, "timer": TIMER_STEPS}).replace(
                "label: SPEED", "label: FAN"
            )
        ),
    )
    s.press(s.planned("press_power"))
    done = s.press(s.planned("press_speed"))
    assert "speed" in done.surprises and s.belief.value("speed") == "mid"
    assert s.unconfirmed({"speed", "power"}) == ["speed"]


def test_a_setting_found_on_the_panel_must_fit_the_goal_value() -> None:
    from apbot.agent.discovery import _fits

    grams = {"type": "numeric", "ranges": [[100, 500, 100]], "unit": "g"}
    assert _fits(grams, "300 g") and _fits(grams, 700)  # the walk may not have gone so far
    assert not _fits(grams, "70%")  # a walk of grams is not the power level asked for
    words = {"type": "discrete", "values": ["white rice", "brown rice"]}
    assert _fits(words, "Brown Rice") and not _fits(words, "porridge")


def test_the_finder_never_walks_a_power_or_lock_key_after_an_entry_key() -> None:
    from apbot.agent.discovery import VariableFinder

    s = session(fan(), fan())
    adjusters = VariableFinder(s, GuardLearner(s))._adjusters("press_timer")
    assert "press_power" not in adjusters  # switching off would end what it is looking at
    assert adjusters[0] == "press_up"  # the stepping keys first


def test_no_side_effect_is_learnt_from_a_dark_panel() -> None:
    # the belief says switching off slows the fan; the dark panel shows no speed at all, so
    # nothing can be learnt about that from it
    belief = model_from(
        (FAN % {"speeds": "low, mid, high", "hours": 4, "timer": TIMER_STEPS}).replace(
            "effect: toggle}]", "effect: toggle, set: {speed: low}}]"
        )
    )
    s = session(fan(), belief)
    s.press(s.planned("press_power"))
    s.press(s.planned("press_speed"))
    off = s.press(s.planned("press_power"))
    assert not off.feedback.text.strip()
    assert not SideEffectLearner(s).learn_side_effect("speed", off, "mid")


def test_no_guard_is_supposed_wrong_when_even_all_of_them_relaxed_cannot_reach_the_goal(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # each setting's key resets the other: no guard, relaxed or not, makes both hold
    apart = model_from(
        (FAN % {"speeds": "low, mid, high", "hours": 4, "timer": TIMER_STEPS})
        .replace(
            "variable: speed, effect: next}", "variable: speed, effect: next, set: {timer: 0}}"
        )
        .replace(
            "variable: timer, effect: next}", "variable: timer, effect: next, set: {speed: low}}"
        )
        .replace('only: [press_power], display: ""', 'only: [press_power, press_up], display: ""')
    )
    s = session(apart, apart)
    searches: list[dict[str, object]] = []
    real = guards.plan
    monkeypatch.setattr(
        guards,
        "plan",
        lambda m, st, goal, *a, **k: searches.append(goal) or real(m, st, goal, *a, **k),
    )
    target = {"speed": "high", "timer": 2}
    learner = GuardLearner(s)
    assert not learner.relax(target)
    assert len(searches) == 1  # the union of every supposed relaxation, not one search each
    assert not learner.relax(target) and len(searches) == 1  # the same question: remembered
    assert s.episode.repairs == []


def test_a_guard_relaxation_that_makes_the_goal_reachable_is_still_found() -> None:
    # the belief has the timer's UP key locked whenever the fan runs: the timer is out of reach
    locked = model_from(
        (FAN % {"speeds": "low, mid, high", "hours": 4, "timer": TIMER_STEPS}).replace(
            "  - {name: switched off",
            '  - {name: timer lock, when: {power: "on"}, '
            "only: [press_power, press_speed, press_timer]}\n"
            "  - {name: switched off",
        )
    )
    s = session(fan(), locked)
    assert GuardLearner(s).relax({"timer": 2})
    assert s.episode.repairs == ["timer lock may let press_up work (to be seen)"]


def _timer_locked() -> ApplianceModel:
    return model_from(
        (FAN % {"speeds": "low, mid, high", "hours": 4, "timer": TIMER_STEPS}).replace(
            "  - {name: switched off",
            '  - {name: timer lock, when: {power: "on"}, '
            "only: [press_power, press_speed, press_timer]}\n"
            "  - {name: switched off",
        )
    )


def test_a_relaxation_whose_search_ran_out_is_not_remembered_as_in_vain(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    s = session(fan(), _timer_locked())
    learner = GuardLearner(s)
    budget = guards.RELAX_BUDGET
    monkeypatch.setattr(guards, "RELAX_BUDGET", 1)  # every search gives up at once
    assert not learner.relax({"timer": 2})
    monkeypatch.setattr(guards, "RELAX_BUDGET", budget)
    assert learner.relax({"timer": 2})  # asked again with room to search: found


def test_a_goal_tried_in_vain_is_asked_again_once_the_display_moved_a_value(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    s = session(fan(), _timer_locked())
    learner = GuardLearner(s)
    guesses: list[str] = []

    def refuse(model: ApplianceModel, index: int, action: str) -> ApplianceModel:
        guesses.append(action)
        raise RepairError("no such guess here")

    monkeypatch.setattr(guards, "allow", refuse)
    assert not learner.relax({"timer": 2})
    tried = len(guesses)
    assert tried and not learner.relax({"timer": 2}) and len(guesses) == tried  # remembered
    assert s.belief.value("speed") != "high"
    s.sync(Seen("SPEED high", {"speed": "high"}))  # the display says otherwise than the belief
    assert not learner.relax({"timer": 2})
    assert len(guesses) == 2 * tried  # a new question: asked again


LOCKED_FAN = """
controls: [{id: power}, {id: speed}, {id: lock}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  speed: {type: discrete, values: [low, mid, high], label: SPEED}
  child_lock: {type: discrete, values: ["off", "on"], show: {"off": "%s", "on": "LOCKED"}}
actions:
  press_power: {control: power}
  press_speed: {control: speed}
  hold_lock: {control: lock, skill: hold, seconds: 3}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  speed: [{actions: [press_speed], variable: speed, effect: next}]
  lock: [{actions: [hold_lock], variable: child_lock, effect: toggle}]
guards:
  - {name: switched off, when: {power: "off"}, only: [press_power], display: "", hide: true}
  - {name: lock, when: {child_lock: "on"}, only: [hold_lock], display: "LOCKED"}
display:
  idle: "{speed}"
"""


def test_a_value_printed_as_nothing_is_seen_in_the_absence_of_the_other_values_word() -> None:
    # the manual says the lock shows LOCKED; unlocked, the panel goes back to the speed with a
    # word the belief does not print ("mid  FAN"): the lock is off, no surprise
    truth = model_from(LOCKED_FAN % "{speed}  FAN")
    s = session(truth, model_from(LOCKED_FAN % ""))
    s.press(s.planned("press_power"))
    locked = s.press(s.planned("hold_lock"))
    assert not locked.surprising and s.belief.value("child_lock") == "on"
    unlocked = s.press(s.planned("hold_lock"))
    assert unlocked.feedback.text == "low  FAN"
    assert not unlocked.surprising and s.belief.value("child_lock") == "off"


def test_a_time_on_a_partly_read_display_that_contradicts_a_time_seen_before_is_looked_at() -> None:
    # the belief missed that CANCEL clears the delay, and prints no delay on the idle screen:
    # after CANCEL the panel shows "white  0:00" where the belief reads only the programme
    truth = suite_model("bread_maker_5")
    belief = suite_model(
        "bread_maker_5",
        ('effect: {to: "off"}, reset: [delay]}', 'effect: {to: "off"}}'),
        ('show: {"off": "{programme}  {delay}", "on": "BAKING"}', 'show: {"on": "BAKING"}'),
        ('show: {"off": "{programme}  {delay}", "on": "LOCKED"}', 'show: {"on": "LOCKED"}'),
        ('idle: "{programme}  {delay}"', 'idle: "{programme}"'),
    )
    s = session(truth, belief)
    for _ in range(2):
        s.press(s.planned("press_plus"))
    assert s.belief.value("delay") == "00:30:00" and s.evidence["delay"] == "00:30:00"
    s.press(s.planned("press_start"))
    cancelled = s.press(s.planned("press_cancel"))
    assert "0:00" in cancelled.feedback.text and cancelled.seen is not None
    assert cancelled.seen.partial
    assert s.belief.value("delay") == "00:30:00"  # nothing the belief could read said otherwise
    assert s.unconfirmed(["delay"]) == ["delay"]  # but it is to be seen again before a claim


SILENT_LOCK = """
controls: [{id: power}, {id: function}, {id: lock}, {id: sound}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  function: {type: discrete, values: [fry, soup], label: FUNC}
  child_lock: {type: discrete, values: ["off", "on"], initial: "on",
               show: {"on": LOCKED, "off": ""}}
  beep: {type: discrete, values: ["off", "on"], visible: false}
actions:
  press_power: {control: power}
  press_function: {control: function}
  press_lock: {control: lock}
  press_sound: {control: sound}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  function: [{actions: [press_function], variable: function, effect: next}]
  lock: [{actions: [press_lock], variable: LOCK_KEY}]
  sound: [{actions: [press_sound], variable: SOUND_KEY, effect: toggle}]
display:
  idle: "{function}"
  indicators: [power]
"""


def test_an_unlock_that_failed_is_not_seen_as_unlocked_by_a_silent_other_screen() -> None:
    # the belief's unlock key is the panel's function key: the function screen comes up, with
    # no LOCKED on it — as it would be whatever the lock holds. Unlocked is not seen
    truth = model_from(
        SILENT_LOCK.replace("LOCK_KEY}", "function, effect: next}")
        .replace("SOUND_KEY", "child_lock")
        .replace('  beep: {type: discrete, values: ["off", "on"], visible: false}\n', "")
    )
    belief = model_from(
        SILENT_LOCK.replace("LOCK_KEY}", "child_lock, effect: toggle}").replace("SOUND_KEY", "beep")
    )
    s = session(truth, belief)
    s.press(s.planned("press_power"))
    done = s.press(s.planned("press_lock"))
    assert done.observed("child_lock") is MISSING
    assert "child_lock" in done.surprises
    assert s.evidence.get("child_lock") != "off" and s.belief.value("child_lock") == "on"


def test_an_unlock_is_seen_by_the_silence_of_its_own_screen() -> None:
    model = model_from(
        SILENT_LOCK.replace("LOCK_KEY}", "child_lock, effect: toggle}").replace("SOUND_KEY", "beep")
    )
    s = session(model, model)
    s.press(s.planned("press_power"))
    done = s.press(s.planned("press_lock"))
    assert not done.surprising and s.evidence["child_lock"] == "off"


def test_the_display_learner_reads_values_that_share_their_start_as_whole_values() -> None:
    """'1/2+0.7' and '1/2+0.3' are two powers printed alone, not a template '1/2+0.{value}'
    of words 7 and 3 (a flash's output in thirds of a stop)."""
    speeds = '"1/2", "1/2+0.3", "1/2+0.7"'
    truth = model_from(
        (FAN % {"speeds": speeds, "hours": 4, "timer": TIMER_STEPS}).replace(
            "label: SPEED}", 'label: SPEED, show: "{value}"}'
        )
    )
    s = session(truth, fan(speeds=speeds))
    assert DisplayLearner(s).learn("speed", ["1/2+0.7", "1/2+0.3"])
    assert s.belief.model.variables["speed"].show == "{value}"
