"""A choice of two named values that is no switch (left/right plate, upper/lower zone) selects
the part the other keys act on: it is planned first, like a programme, for each part may keep
its own settings though the manual (and so the belief) does not say so."""

from __future__ import annotations

from apbot.agent.programmes import programmes
from tests.helpers import model_from
from tests.helpers import run_checked as run

# A twin hot plate: PLATE picks the left or the right plate, HEAT steps the picked plate's level.
PLATES = """
controls: [{id: plate, label: PLATE}, {id: heat, label: HEAT}]
variables:
  plate: {type: discrete, values: [left, right], show: {left: "L", right: "R"}}
  heat:
    type: numeric
    label: HEAT
    depends_on: plate
    remember: true
    cases: {left: {ranges: [[0, 5, 1]], initial: 0}, right: {ranges: [[0, 5, 1]], initial: 0}}
actions: {press_plate: {control: plate}, press_heat: {control: heat}}
features:
  plate: [{actions: [press_plate], variable: plate, effect: toggle}]
  heat: [{actions: [press_heat], variable: heat, effect: next}]
display: {idle: "{plate}"}
"""


def test_a_part_chosen_between_two_names_is_planned_before_the_settings_it_may_own() -> None:
    belief = model_from(
        PLATES.replace("    depends_on: plate\n    remember: true\n", "").replace(
            "    cases: {left: {ranges: [[0, 5, 1]], initial: 0}, right: {ranges: [[0, 5, 1]], "
            "initial: 0}}",
            "    ranges: [[0, 5, 1]]\n    initial: 0",
        )
    )
    assert belief.variables["heat"].depends_on is None
    assert "plate" in programmes(belief)
    episode, reached = run(model_from(PLATES), belief, {"plate": "right", "heat": 2})
    assert reached and episode.claimed_success, episode.failure


def test_a_switch_or_a_lock_is_no_selector() -> None:
    model = model_from(
        """
        controls: [{id: k, label: K}, {id: j, label: J}]
        variables:
          sound: {type: discrete, values: ["off", "on"]}
          lock: {type: discrete, values: [unlocked, locked]}
        actions: {press_k: {control: k}, press_j: {control: j}}
        features:
          sound: [{actions: [press_k], variable: sound, effect: toggle}]
          lock: [{actions: [press_j], variable: lock, effect: toggle}]
        """
    )
    assert programmes(model) == set()


# The same plates with a mode each (off, warm, boil): the plate is chosen before its mode.
MODES = """
controls: [{id: plate, label: PLATE}, {id: mode, label: MODE}]
variables:
  plate: {type: discrete, values: [left, right], show: {left: "L", right: "R"}}
  mode:
    type: discrete
    label: MODE
    depends_on: plate
    remember: true
    cases:
      left: {values: ["off", warm, boil]}
      right: {values: ["off", warm, boil]}
actions: {press_plate: {control: plate}, press_mode: {control: mode}}
features:
  mode: [{actions: [press_mode], variable: mode, effect: next}]
  plate: [{actions: [press_plate], variable: plate, effect: toggle}]
display: {idle: "{plate}"}
"""


def test_a_part_is_chosen_before_the_programme_it_may_keep_its_own_of() -> None:
    belief = model_from(
        MODES.replace("    depends_on: plate\n    remember: true\n", "")
        .replace('      left: {values: ["off", warm, boil]}\n', "")
        .replace('      right: {values: ["off", warm, boil]}\n', "")
        .replace("    cases:\n", '    values: ["off", warm, boil]\n')
    )
    episode, reached = run(model_from(MODES), belief, {"plate": "right", "mode": "boil"})
    assert reached and episode.claimed_success, episode.failure
