"""Each semantic check fires on the mistake it exists for, with a path and a way out."""

from __future__ import annotations

import time

import pytest

from apbot.examples import example_names, load_example
from apbot.model.limits import MAX_MODEL_VALUES, MAX_PARTS
from apbot.model.problems import ModelError
from apbot.model.validate import check_goal, check_model
from tests.helpers import model_from

BASE = """
controls:
  - {id: b1, label: A}
  - {id: b2, label: B}
  - {id: k1, kind: key, label: "1"}
variables:
  mode: {type: discrete, values: [a, b, c]}
  level: {type: numeric, ranges: [[0, 10, 5]]}
actions:
  press_a: {control: b1}
  press_b: {control: b2}
features:
  mode:
    - {actions: [press_a], variable: mode, effect: next}
  level:
    - {actions: [press_b], variable: level, effect: next}
"""


def problems(text: str) -> list[tuple[str, str, str]]:
    model = model_from(text, check=False)
    return [(p.check, p.where, p.message) for p in check_model(model) if p.severity == "error"]


def only(text: str) -> tuple[str, str, str]:
    found = problems(text)
    assert len(found) == 1, found
    return found[0]


@pytest.mark.parametrize("name", example_names())
def test_examples_are_clean(name: str) -> None:
    assert [p for p in check_model(load_example(name)) if p.severity == "error"] == []


def test_base_is_clean() -> None:
    assert problems(BASE) == []


def test_missing_variable() -> None:
    found = problems(
        BASE.replace(
            "{actions: [press_b], variable: level, effect: next}",
            "{actions: [press_b], effect: next}",
        )
    )
    assert ("missing-variable", "features.level[0].effect") in [f[:2] for f in found]
    assert ("missing-variable", "features.level") in [f[:2] for f in found]


def test_empty_and_unknown_actions() -> None:
    assert only(BASE.replace("[press_b], variable: level", "[], variable: level"))[:2] == (
        "empty-action",
        "features.level[0].actions",
    )
    assert only(BASE.replace("[press_b], variable", "[press_c], variable"))[:2] == (
        "unknown-action",
        "features.level[0].actions[0]",
    )


def test_action_and_variable_coverage() -> None:
    unused_action = BASE.replace("actions:\n", "actions:\n  press_x: {control: b1}\n")
    assert only(unused_action)[:2] == ("action-coverage", "actions.press_x")
    unused_variable = BASE.replace(
        "variables:\n", "variables:\n  spare: {type: discrete, values: [p, q]}\n"
    )
    assert only(unused_variable)[:2] == ("variable-coverage", "variables.spare")


def test_duplicate_sequences_and_unstartable_features() -> None:
    duplicate = BASE + "  mode_again:\n    - {actions: [press_a], variable: mode, effect: next}\n"
    found = problems(duplicate)
    assert ("duplicate-sequence", "features.mode_again") in [f[:2] for f in found]
    assert any("can never start" in f[2] for f in found)


def test_keypad_actions_without_keypad() -> None:
    text = BASE.replace("press_b: {control: b2}", "press_b: {control: b2, digit: 1}")
    text = text.replace(
        "level: {type: numeric, ranges: [[0, 10, 5]]}",
        "level: {type: numeric, ranges: [[0, 10, 5]], entry: {format: number}}",
    )
    text = text.replace(
        "{actions: [press_b], variable: level, effect: next}",
        "{actions: [press_b], variable: level}",
    )
    check, where, message = only(text)
    assert (check, where) == ("keypad", "actions.press_b.digit")
    assert "kind `key`" in message


def test_keypad_buffer_needs_an_entry_format() -> None:
    text = BASE.replace("press_b: {control: b2}", "press_b: {control: k1, digit: 1}")
    text = text.replace(
        "{actions: [press_b], variable: level, effect: next}",
        "{actions: [press_b], variable: level}",
    )
    check, where, message = only(text)
    assert (check, where) == ("keypad-buffer", "variables.level.entry")
    assert "no `entry` format" in message


def test_action_variable_consistency() -> None:
    check, where, message = only(
        BASE.replace("variable: mode, effect: next", "variable: mode, effect: toggle")
    )
    assert (check, where) == ("action-variable", "features.mode[0].effect")
    assert "exactly two values" in message
    check, _, message = only(
        BASE.replace("variable: mode, effect: next", "variable: mode, effect: {to: d}")
    )
    assert "go-to value 'd'" in message


def test_goal_validity() -> None:
    washer = load_example("washing_machine")
    found = check_goal(washer, {"programme": "wool", "temperature": "60", "speed": 3})
    messages = {p.where: p.message for p in found}
    assert "when programme is 'wool'" in messages["goal.temperature"]
    assert "unknown variable 'speed'" in messages["goal.speed"]


def test_unreachable_values() -> None:
    one_way = BASE.replace("variable: level, effect: next", "variable: level, effect: prev")
    check, where, message = only(one_way)
    assert (check, where) == ("unreachable-value", "variables.level")
    assert "5, 10" in message


def test_values_declared_unreachable() -> None:
    one_way = BASE.replace("variable: level, effect: next", "variable: level, effect: prev")
    marked = one_way.replace("ranges: [[0, 10, 5]]", "ranges: [[0, 10, 5]], unreachable: [5]")
    check, where, message = only(marked)  # 10 is still unreached and undeclared
    assert (check, where) == ("unreachable-value", "variables.level") and "10" in message
    assert problems(marked.replace("unreachable: [5]", 'unreachable: [5, "10"]')) == []


def test_unreachable_declarations_are_checked() -> None:
    text = BASE.replace("values: [a, b, c]", "values: [a, b, c], unreachable: [d]")
    check, where, message = only(text)
    assert (check, where) == ("unreachable-value", "variables.mode.unreachable[0]")
    assert "'d'" in message
    initial = BASE.replace("values: [a, b, c]", "values: [a, b, c], unreachable: [a]")
    assert only(initial)[1:] == (
        "variables.mode.unreachable[0]",
        "'a' is 'mode''s initial value (or a programme's default), so the appliance reaches "
        "it; remove it from `unreachable`",
    )
    reached = BASE.replace("values: [a, b, c]", "values: [a, b, c], unreachable: [b]")
    [warning] = [p for p in check_model(model_from(reached, check=False)) if p.check != "control"]
    assert (warning.severity, warning.where) == ("warning", "variables.mode.unreachable")
    assert "'b' is declared unreachable but an action of the model reaches it" in warning.message


def test_a_guard_nothing_can_lift() -> None:
    text = BASE + "guards:\n  - {when: {mode: b}, only: [press_b]}\n"
    check, where, message = only(text)
    assert (check, where) == ("guard", "guards[0].only")
    assert "nothing can lift it" in message


def test_dependent_cases_name_parent_values() -> None:
    text = BASE.replace(
        "variables:\n",
        "variables:\n  size: {type: discrete, depends_on: mode, cases: {a: [s, m], z: [l]}}\n",
    )
    text += "  size:\n    - {actions: [press_b], variable: size}\n"
    found = problems(text)
    assert ("dependent", "variables.size.cases.z") in [f[:2] for f in found]


def test_turn_needs_a_dial() -> None:
    text = BASE.replace("press_a: {control: b1}", "press_a: {control: b1, skill: turn_cw}")
    check, where, _message = only(text)
    assert (check, where) == ("control", "actions.press_a.skill")


# --- size limits -----------------------------------------------------------------------------


def _wide_model(actions: int, values: int = 2) -> str:
    lines = ["controls: [{id: b, label: B}]", "variables:"]
    lines += [f"  v{i}: {{type: numeric, ranges: [[1, {values}, 1]]}}" for i in range(actions)]
    lines += ["actions:"] + [f"  a{i}: {{control: b}}" for i in range(actions)]
    lines += ["features:"]
    lines += [f"  f{i}: [{{actions: [a{i}], variable: v{i}}}]" for i in range(actions)]
    return "\n".join(lines) + "\n"


def test_past_the_part_and_step_limits_is_one_size_problem_each() -> None:
    model = model_from(_wide_model(MAX_PARTS + 1), check=False)
    problems = check_model(model)
    assert {(p.where, p.check) for p in problems} == {
        ("variables", "size"),
        ("actions", "size"),
        ("features", "size"),
    }
    assert all(f"at most {MAX_PARTS:,}" in p.message for p in problems)


def test_past_the_model_value_limit_is_refused_before_any_domain_is_built() -> None:
    per_variable = MAX_MODEL_VALUES // 10
    model = model_from(_wide_model(11, per_variable), check=False)
    started = time.perf_counter()
    [problem] = check_model(model)
    assert problem.check == "size" and "1,100,000 values in all" in problem.message
    assert time.perf_counter() - started < 0.5


def test_infinite_or_nan_numbers_are_schema_errors() -> None:
    with pytest.raises(ModelError, match="finite number"):
        model_from(_wide_model(1).replace("[[1, 2, 1]]", "[[0, .inf, 1]]"))
    with pytest.raises(ModelError, match="finite number"):
        model_from(_wide_model(1).replace("[[1, 2, 1]]", "[[0, 10, .nan]]"))
