"""The checker on the procedure-structure options: each mistake is named with its path."""

from __future__ import annotations

import pytest

from apbot.model.problems import ModelError
from apbot.model.validate import check_model
from tests.helpers import model_from

BASE = """
controls:
  - {id: b1, label: A}
  - {id: b2, label: B}
  - {id: b3, label: C}
  - {id: b4, label: START}
variables:
  mode: {type: discrete, values: [a, b, c]}
  level: {type: numeric, ranges: [[0, 10, 5]]}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_a: {control: b1}
  press_b: {control: b2}
  press_c: {control: b3}
  press_start: {control: b4}
  wait_5s: {skill: wait, seconds: 5}
features:
  settings:
    - {actions: [press_a], timeout: 5}
    - {actions: [press_b], variable: mode, effect: next, optional: true}
    - {actions: [press_c], variable: level, effect: next}
anywhere:
  - {actions: [press_start], variable: running, effect: toggle}
"""


def found(text: str, severity: str = "error") -> list[tuple[str, str, str]]:
    model = model_from(text, check=False)
    return [(p.check, p.where, p.message) for p in check_model(model) if p.severity == severity]


def test_base_is_clean() -> None:
    assert found(BASE) == [] and found(BASE, "warning") == []


def test_the_first_and_last_steps_cannot_be_optional() -> None:
    first = found(
        BASE.replace(
            "{actions: [press_a], timeout: 5}", "{actions: [press_a], optional: true, timeout: 5}"
        )
    )
    assert [f[:2] for f in first] == [("optional-step", "features.settings[0].optional")]
    last = found(BASE.replace("effect: next}\nanywhere", "effect: next, optional: true}\nanywhere"))
    assert [f[:2] for f in last] == [("optional-step", "features.settings[2].optional")]
    assert "no step follows it" in last[0][2]


def test_a_timeout_needs_a_wait_and_a_wait_a_timeout() -> None:
    no_wait = found(BASE.replace("  wait_5s: {skill: wait, seconds: 5}\n", ""), "warning")
    assert [f[:2] for f in no_wait] == [("timeout", "features.settings[0].timeout")]
    assert "wait_5s: {skill: wait, seconds: 5}" in no_wait[0][2]
    no_timeout = found(BASE.replace(", timeout: 5}", "}"), "warning")
    assert [f[:2] for f in no_timeout] == [("timeout", "actions.wait_5s.seconds")]


def test_a_wait_belongs_to_no_step() -> None:
    text = BASE.replace("[press_c], variable: level", "[press_c, wait_5s], variable: level")
    text = text.replace("effect: next}\nanywhere", "effect: {press_c: next}}\nanywhere")
    assert [f[:2] for f in found(text)] == [("timeout", "actions.wait_5s")]


@pytest.mark.parametrize(
    "action, message",
    [
        ("{control: b1, skill: wait, seconds: 5}", "a wait touches no control"),
        ("{skill: wait}", "a wait needs `seconds`"),
        ("{control: b1, too_short: enters}", "`too_short` only applies to holds"),
    ],
)
def test_waits_and_early_releases_are_schema_checked(action: str, message: str) -> None:
    with pytest.raises(ModelError) as error:
        model_from(BASE.replace("{skill: wait, seconds: 5}", action))
    assert message in str(error.value) and "actions.wait_5s" in str(error.value)


def test_an_anywhere_key_belongs_to_no_feature() -> None:
    text = BASE.replace("- {actions: [press_start], variable", "- {actions: [press_c], variable")
    problems = found(text)
    assert ("anywhere", "anywhere[0].actions[0]") in [f[:2] for f in problems]
    assert "also in features.settings[2]" in problems[0][2]


def test_anywhere_references_and_effects_are_checked() -> None:
    unknown = found(
        BASE.replace("[press_start], variable: running", "[press_stat], variable: running")
    )
    assert ("unknown-action", "anywhere[0].actions[0]") in [f[:2] for f in unknown]
    assert any("did you mean 'press_start'" in f[2] for f in unknown)
    typed = found(
        BASE.replace("variable: running, effect: toggle", "variable: running, effect: digit")
    )
    assert [f[:2] for f in typed] == [("keypad-buffer", "anywhere[0].effect")]
    wrong = found(
        BASE.replace("variable: running, effect: toggle", "variable: mode, effect: toggle")
    )
    assert ("action-variable", "anywhere[0].effect") in [f[:2] for f in wrong]
    idle = found(
        BASE.replace(
            "{actions: [press_start], variable: running, effect: toggle}",
            "{actions: [press_start]}",
        )
    )
    assert ("missing-variable", "anywhere[0]") in [f[:2] for f in idle]


def test_a_cancel_that_only_leaves_is_fine() -> None:
    text = BASE.replace(
        "- {actions: [press_start], variable: running, effect: toggle}",
        "- {actions: [press_start], leave: true}",
    ).replace('  running: {type: discrete, values: ["off", "on"]}\n', "")
    assert found(text) == []


def test_a_guard_lifted_by_an_anywhere_key_can_be_lifted() -> None:
    text = BASE + '\nguards: [{when: {running: "on"}, only: [press_start], display: RUN}]\n'
    assert found(text) == []


def test_an_early_release_on_an_anywhere_hold_is_a_warning() -> None:
    text = BASE.replace(
        "press_start: {control: b4}",
        "press_start: {control: b4, skill: hold, seconds: 2, too_short: enters}",
    )
    assert found(text) == []
    assert [f[:2] for f in found(text, "warning")] == [("anywhere", "anywhere[0].actions[0]")]
