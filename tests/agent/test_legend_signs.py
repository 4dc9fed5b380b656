"""Signs the display lights for a setting's values, which the belief prints as the values' own
words: the walk of the setting's key shows signs it cannot read, and the manual's legend says
which sign is which value (:mod:`apbot.agent.legend`, :mod:`apbot.agent.legend_walk`)."""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.legend import legend, signs
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from tests.helpers import model_from

KETTLE = """
controls: [{id: temp, label: TEMP}, {id: tone, label: TONE}, {id: keep, label: KEEP}]
variables:
  temp: {type: numeric, unit: "°C", ranges: [[60, 100, 10]], initial: 100, wrap: true, label: TEMP}
  tone: {type: discrete, values: [bell, chirp, silent], label: TONE{tone}}
  keep: {type: discrete, values: ["off", "on"], label: KEEP{keep}}
actions:
  press_temp: {control: temp}
  press_tone: {control: tone}
  press_keep: {control: keep}
features:
  set_temp: [{actions: [press_temp], variable: temp, effect: next}]
  set_tone: [{actions: [press_tone], variable: tone, effect: next}]
  keep: [{actions: [press_keep], variable: keep, effect: toggle}]
display: {idle: "{temp}"{lamps}}
"""

SIGNS = (
    ', show: {"bell": "♫", "chirp": "♪", "silent": "∅"}',
    ', show: {"off": "", "on": "✱"}',
    ", indicators: [tone, keep]",
)

MANUAL = """
The screen
  ♫  bell: a long ring when the water is ready
  ♪  chirp: one short note
  ∅  silent: no sound at all

Keep warm
Press KEEP. The star ✱ lights up: keep warm is on.
Press KEEP again to switch it off.
"""


def _run(manual: str, goal: dict[str, object]) -> tuple[bool, bool]:
    tone, keep, lamps = SIGNS
    truth = model_from(
        KETTLE.replace("{tone}", tone).replace("{keep}", keep).replace("{lamps}", lamps)
    )
    belief = model_from(KETTLE.replace("{tone}", "").replace("{keep}", "").replace("{lamps}", ""))
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext(
        "unit", "test", "t", "", goal, belief, manual=manual, actions=tuple(env.actions)
    )
    episode = get_method("apbot").run(context, env)
    return env.simulator.satisfies(parse_goal(truth, goal)), episode.claimed_success


def test_a_three_way_sound_shown_by_signs_is_set_by_the_manuals_legend() -> None:
    reached, claimed = _run(MANUAL, {"tone": "silent", "temp": 80})
    assert reached and claimed


def test_an_on_off_sign_is_named_on_by_a_sentence_saying_the_setting_is_on() -> None:
    found = signs(["✱  70°C", "70°C"], {"°c"})
    assert legend(MANUAL, found, ["off", "on"], ["KEEP"]) == {"✱": "on"}


def test_without_a_legend_the_signs_are_not_guessed() -> None:
    reached, claimed = _run("", {"tone": "silent", "temp": 80})
    assert reached or not claimed


def test_the_legend_names_the_value_beside_each_sign() -> None:
    found = signs(["70°C  ♪", "70°C  ∅", "70°C  ♫"], {"°c"})
    assert legend(MANUAL, found, ["bell", "chirp", "silent"], ["TONE"]) == {
        "♫": "bell",
        "♪": "chirp",
        "∅": "silent",
    }
    # a state in words with its lamp's colour in brackets, and a shortened mark after a label
    text = "Heat: off -> mild (lamp amber) -> strong (lamp crimson)\nBEAM N ..... narrow beam"
    assert legend(text, ["AMBER", "CRIMSON"], ["off", "mild", "strong"], ["HEAT"]) == {
        "AMBER": "mild",
        "CRIMSON": "strong",
    }
    assert legend(text, ["N"], ["wide", "narrow"], ["BEAM"]) == {"N": "narrow"}


def test_a_sign_the_manual_ties_to_two_values_is_left_alone() -> None:
    text = "♪ chirp: one note\nIn night mode ♪ means bell"
    assert legend(text, ["♪"], ["bell", "chirp"], ["TONE"]) == {}


def test_a_value_of_several_words_counts_only_said_whole() -> None:
    text = "Door: ⇐ back only · ⇒ front only · ✕ shut · ⇔ both ways"
    values = ["both ways", "back only", "front only", "shut"]
    assert legend(text, ["⇐", "⇒", "✕", "⇔"], values, ["DOOR"]) == {
        "⇐": "back only",
        "⇒": "front only",
        "✕": "shut",
        "⇔": "both ways",
    }
    # one text's parts are each a sign to look up ("⇒" lit beside a range lamp)
    assert sorted(signs(["⇒  ▮▮"], set())) == sorted(["▮▮", "⇒"])


def test_a_screen_that_leaves_a_setting_out_gives_no_value_of_it() -> None:
    """The idle screen of a belief that prints only the temperature says nothing of the tone:
    the walk must see no value there (a 'not read' marker once became one of its values)."""
    from apbot.agent.legend_walk import _one_value, _read

    belief = model_from(KETTLE.replace("{tone}", "").replace("{keep}", "").replace("{lamps}", ""))
    context = {"temp": 100, "tone": "bell", "keep": "off"}
    assert _one_value(belief, "tone", "90", context) is None
    assert not _read(belief, "tone", "90", context)
    assert _one_value(belief, "temp", "90", context) == 90
