"""A number said beside a setting's own name, outside the values a read belief holds for it.

Each belief below was read with a wrong range for one setting (the spec table's first row; two
listed values with the middle skipped). On a read belief (``outside`` given) the number is
kept for that setting as said, with a note naming the words and why; without ``outside`` (the
true model) nothing changes.
"""

from __future__ import annotations

from apbot.read.goal import parse_instruction
from tests.helpers import model_from

# a fondue pot: BASE and KEEP each with − / +; KEEP's range was read as BASE's 60 … 90
POT = model_from(
    """
    controls: [{id: base}, {id: keep}, {id: minus}, {id: plus}, {id: start}]
    variables:
      base: {type: numeric, ranges: [[60, 90, 1]], unit: "°C", label: BASE}
      keep: {type: numeric, ranges: [[60, 90, 1]], unit: "°C", label: KEEP}
      running: {type: discrete, values: ["off", "on"]}
    actions:
      press_base: {control: base}
      press_keep: {control: keep}
      press_minus: {control: minus}
      press_plus: {control: plus}
      press_start: {control: start}
    features:
      set_base:
        - {actions: [press_base]}
        - {actions: [press_plus, press_minus], variable: base,
           effect: {press_plus: next, press_minus: prev}}
      set_keep:
        - {actions: [press_keep]}
        - {actions: [press_plus, press_minus], variable: keep,
           effect: {press_plus: next, press_minus: prev}}
      start:
        - {actions: [press_start], variable: running, effect: {to: "on"}}
    """
)

# a chest freezer whose listed settings skipped the middle ones
CHEST = model_from(
    """
    controls: [{id: cold}]
    variables:
      cold: {type: discrete, values: ["-15", "-16", "-22", "-23"], label: COLD}
    actions:
      press_cold: {control: cold}
    features:
      set_cold:
        - {actions: [press_cold], variable: cold, effect: next}
    """
)


def test_a_number_beside_a_settings_name_is_kept_and_noted_on_a_read_belief() -> None:
    notes: list[str] = []
    goal = parse_instruction(POT, "base at 80, keep at 45", outside=notes)
    assert goal["base"] == 80 and goal["keep"] == 45, goal
    assert len(notes) == 1 and "'45'" in notes[0] and "keep can be" in notes[0], notes


def test_the_true_model_keeps_its_old_answer() -> None:
    goal = parse_instruction(POT, "base at 80, keep at 45")
    assert "keep" not in goal, goal


def test_a_number_with_no_setting_word_beside_it_is_not_kept() -> None:
    notes: list[str] = []
    goal = parse_instruction(POT, "base at 80, then 45 later", outside=notes)
    assert "keep" not in goal and not notes, (goal, notes)


def test_a_negative_setting_keeps_its_sign() -> None:
    notes: list[str] = []
    goal = parse_instruction(CHEST, "cold at minus 19 please", outside=notes)
    assert goal == {"cold": "-19"}, goal
    goal = parse_instruction(CHEST, "cold at 19 please", outside=[])
    assert "cold" not in goal, goal  # a sign lost, not a value to try


def test_a_number_refused_bounded_or_counted_is_not_kept() -> None:
    """Beside KEEP, but no value asked for it: refused, a limit, or a count of events."""
    for said in (
        "base at 80, but not keep at 45",
        "base at 80, keep never below 45",
        "base at 80, I opened the keep lid 25 times",
    ):
        notes: list[str] = []
        goal = parse_instruction(POT, said, outside=notes)
        assert goal.get("keep") is None and not notes, (said, goal, notes)
