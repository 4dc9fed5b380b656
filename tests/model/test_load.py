"""A malformed model gives an error naming the exact path (and line), never a traceback."""

from __future__ import annotations

import shutil
import time
from pathlib import Path

import pytest

from apbot.bench.suite import bundled_suite_dir
from apbot.model.limits import MAX_FILE_BYTES, MAX_YAML_DEPTH, MAX_YAML_NODES
from apbot.model.load import load_model, loads_model, model_to_yaml
from apbot.model.problems import ModelError
from apbot.model.yaml_text import read_yaml
from tests.helpers import model_from

GOOD = """\
appliance: {id: fan, category: test}
controls:
  - {id: power_button, label: POWER}
  - {id: speed_button, label: SPEED}
variables:
  power: {type: discrete, values: ["off", "on"]}
  speed: {type: numeric, ranges: [[1, 3, 1]], unit: level}
actions:
  press_power: {control: power_button}
  press_speed: {control: speed_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  set_speed:
    - {actions: [press_speed], variable: speed, effect: next}
"""


def errors_of(text: str) -> list[tuple[str, str, int | None]]:
    with pytest.raises(ModelError) as caught:
        loads_model(text, source="fan.yaml")
    return [(p.where, p.message, p.line) for p in caught.value.problems if p.severity == "error"]


def test_good_model_loads_and_round_trips() -> None:
    model = loads_model(GOOD)
    assert loads_model(model_to_yaml(model)) == model


def test_bad_yaml_names_the_line() -> None:
    broken = GOOD.replace("  speed: {type: numeric", "  speed: {type: numeric,, ")
    [(_where, message, line)] = errors_of(broken)
    assert message.startswith("YAML syntax")
    assert line == 7


def test_unknown_action_in_a_step() -> None:
    bad = GOOD.replace("- {actions: [press_speed]", "- {actions: [press_sped]")
    [(where, message, line)] = errors_of(bad)
    assert where == "features.set_speed[0].actions[0]"
    assert "unknown action 'press_sped'; did you mean 'press_speed'?" in message
    assert line == 15


def test_overlapping_ranges() -> None:
    bad = GOOD.replace("ranges: [[1, 3, 1]]", "ranges: [[1, 3, 1], [2, 5, 1]]")
    [(where, message, line)] = errors_of(bad)
    assert where == "variables.speed"
    assert "range 2 starts at 2, inside range 1" in message
    assert line == 7


def test_initial_value_out_of_domain() -> None:
    bad = GOOD.replace('values: ["off", "on"]}', 'values: ["off", "on"], initial: standby}')
    [(where, message, _)] = errors_of(bad)
    assert where == "variables.power"
    assert "initial value 'standby' is not one of ['off', 'on']" in message


def test_unknown_key_suggests_the_right_one() -> None:
    bad = GOOD.replace("variable: speed, effect: next", "varable: speed, effect: next")
    problems = errors_of(bad)
    assert (
        "features.set_speed[0].varable",
        "unknown key 'varable'; did you mean 'variable'?",
        15,
    ) in problems


def test_a_key_in_the_wrong_place_says_where_it_belongs() -> None:
    """``wrap`` is a variable's key: on a feature step it is misplaced, not misspelt (the hint
    used to be "did you mean 'wrap'?")."""
    bad = GOOD.replace("variable: speed, effect: next", "variable: speed, effect: next, wrap: true")
    [(where, message, _)] = errors_of(bad)
    assert where == "features.set_speed[0].wrap"
    assert message == "unknown key 'wrap'; 'wrap' is a key of a variable, not of this part"


def test_bad_effect_lists_the_vocabulary() -> None:
    bad = GOOD.replace("effect: next}", "effect: up}")
    [(where, message, _)] = errors_of(bad)
    assert where == "features.set_speed[0].effect"
    assert "next, prev, toggle" in message


def test_missing_section_and_wrong_variable_type() -> None:
    problems = errors_of(GOOD.replace("type: numeric", "type: number"))
    assert problems[0][0] == "variables.speed"
    assert "`type` must be discrete, numeric or time" in problems[0][1]
    problems = errors_of("appliance: {id: x, category: y}\ncontrols: []\n")
    assert {p[0] for p in problems} >= {"controls", "variables", "actions", "features"}


def test_a_model_is_a_mapping() -> None:
    [(_where, message, _)] = errors_of("- just\n- a list\n")
    assert "a model is a mapping" in message


def test_warnings_do_not_stop_loading() -> None:
    model = model_from(
        GOOD + "  extra:\n    - {actions: [press_power], variable: power}\n", check=False
    )
    assert "extra" in model.features


def test_yaml_booleans_are_explained() -> None:
    bad = GOOD.replace("label: POWER}", "label: OFF}")
    bad = bad.replace("  power:\n    - {", "  off:\n    - {")
    problems = errors_of(bad)
    assert (
        "controls[0].label",
        'YAML read this as the boolean False (it does so for off/no/false); quote it, e.g. "off"',
        3,
    ) in problems
    assert any(where == "features.false" and "boolean" in message for where, message, _ in problems)


def test_repeated_keys_are_errors() -> None:
    bad = GOOD.replace(
        "  press_speed: {control: speed_button}",
        "  press_speed: {control: speed_button}\n  press_power: {control: speed_button}",
    )
    [(where, message, line)] = errors_of(bad)
    assert where == "actions.press_power" and line == 11
    assert "given twice (first on line 9)" in message


# --- hostile documents: refused fast, before anything is expanded -------------------------------


def billion_laughs(levels: int = 10) -> str:
    """The classic alias bomb: ten lines that expand to 10**levels strings."""
    lines = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    lines += [f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 10)}]" for i in range(1, levels)]
    return "\n".join(lines) + "\n"


def test_an_alias_bomb_is_refused_in_well_under_a_second() -> None:
    started = time.perf_counter()
    with pytest.raises(ModelError) as caught:
        read_yaml(billion_laughs() + GOOD, "bomb.yaml")
    elapsed = time.perf_counter() - started
    [problem] = caught.value.problems
    assert "alias bomb" in problem.message and f"{MAX_YAML_NODES:,} nodes" in problem.message
    assert problem.line is not None and problem.line <= 10
    assert elapsed < 2.0  # it took minutes when the repeated-key walk followed every alias


def test_a_suite_file_that_is_an_alias_bomb_is_refused(tmp_path: Path) -> None:
    from apbot.bench.suite import load_suite

    source = bundled_suite_dir() / "kettle_1"
    target = tmp_path / "kettle_1"
    shutil.copytree(source, target)
    tasks = (source / "tasks.yaml").read_text(encoding="utf-8")
    (target / "tasks.yaml").write_text(billion_laughs() + tasks, encoding="utf-8")
    with pytest.raises(ModelError, match="alias bomb"):
        load_suite(tmp_path)


def test_aliases_that_share_a_value_list_still_work() -> None:
    text = GOOD.replace(
        'power: {type: discrete, values: ["off", "on"]}',
        'power: {type: discrete, values: &switch ["off", "on"]}\n'
        "  light: {type: discrete, values: *switch}",
    ).replace(
        "    - {actions: [press_power], variable: power, effect: toggle}",
        "    - {actions: [press_power], variable: power, effect: toggle, set: {light: 'on'}}",
    )
    model = loads_model(text)
    assert model.variables["light"].values == ["off", "on"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("a: &a [1, *a]\n", "recursive alias"),
        ("a: &a {b: {c: *a}}\n", "recursive alias"),
        ("a: " + "[" * (MAX_YAML_DEPTH + 1) + "]" * (MAX_YAML_DEPTH + 1) + "\n", "nested more"),
        ("a: [" + ", ".join(["1"] * MAX_YAML_NODES) + "]\n", "more than 200,000 nodes"),
        ("a: *nowhere\n", "undefined alias"),
        ('a: "\x01"\n', "control characters are not allowed: U+0001 in column 5"),
    ],
)
def test_hostile_yaml_gets_one_clear_problem(text: str, expected: str) -> None:
    with pytest.raises(ModelError) as caught:
        read_yaml(text, "hostile.yaml")
    [problem] = caught.value.problems
    assert expected in problem.message
    assert "\n" not in problem.render("hostile.yaml")
    assert problem.line == 1


def test_a_huge_file_is_refused_before_it_is_read(tmp_path: Path) -> None:
    path = tmp_path / "model.yaml"
    with path.open("w", encoding="utf-8") as handle:
        handle.write("# padding\n" * (MAX_FILE_BYTES // 10 + 1))
    with pytest.raises(ModelError, match="bytes; at most"):
        load_model(path)


def test_a_repeated_key_inside_an_anchor_is_reported_once() -> None:
    text = "base: &b {x: 1, x: 2}\none: *b\ntwo: *b\n"
    with pytest.raises(ModelError) as caught:
        read_yaml(text)
    assert [(p.where, p.line) for p in caught.value.problems] == [("base.x", 1)]


def test_a_key_with_a_line_break_is_quoted_so_the_problem_stays_one_line() -> None:
    """Found by the loader fuzzer: the path printed the raw key across two lines."""
    header = "appliance: {id: fan, category: test}"
    with pytest.raises(ModelError) as caught:
        loads_model(GOOD.replace(header, header[:-1] + ', "\\n\\n": 1}'))
    [problem] = caught.value.problems
    assert problem.where == "appliance['\\n\\n']"
    assert "\n" not in problem.render("fan.yaml")


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="needs /dev/zero")
def test_an_endless_device_is_refused_after_the_size_limit() -> None:
    started = time.perf_counter()
    with pytest.raises(ModelError, match="more than 4,000,000 bytes"):
        load_model("/dev/zero")  # its size is 0, so only a bounded read stops it
    assert time.perf_counter() - started < 5.0


def test_thousands_of_problems_are_capped_with_a_count_of_the_rest() -> None:
    header = "appliance: {id: fan, category: test}"
    extra = ", ".join(f"k{i}: 1" for i in range(5_000))
    started = time.perf_counter()
    with pytest.raises(ModelError) as caught:
        loads_model(GOOD.replace(header, header[:-1] + ", " + extra + "}"))
    problems = caught.value.problems
    assert len(problems) == 101 and problems[0].where == "appliance.k0"
    assert problems[-1].message.startswith("… and 4,900 more problem(s) like these")
    assert time.perf_counter() - started < 15.0  # a did-you-mean search per key took minutes
