"""A word the manual lists among one setting's choices, which the read belief lacks.

The belief below took a cheese maker's STYLE key for a switch (off/on) and its MODE key with
the short presses' two modes only. The manual (a few lines in our own words) lists the styles
after a sentence naming STYLE, and the held modes in MODE's row of the key legend. On a read
belief (``outside`` given) the word is kept for that setting as said, with a note; a verb, a
word listed beside a key's name, a lower-case list or a true model change nothing.
"""

from __future__ import annotations

from apbot.read.goal import parse_instruction
from tests.helpers import model_from

MAKER = model_from(
    """
    controls: [{id: style}, {id: mode}, {id: lid}, {id: start}]
    variables:
      style: {type: discrete, values: ["off", "on"], label: STYLE}
      mode: {type: discrete, values: [warm, cool], label: MODE}
      lid: {type: discrete, values: ["off", "on"], label: LID}
      running: {type: discrete, values: ["off", "on"]}
    actions:
      press_style: {control: style}
      press_mode: {control: mode}
      press_lid: {control: lid}
      press_start: {control: start}
    features:
      style:
        - {actions: [press_style], variable: style, effect: toggle}
      mode:
        - {actions: [press_mode], variable: mode, effect: next}
      lid:
        - {actions: [press_lid], variable: lid, effect: toggle}
      start:
        - {actions: [press_start], variable: running, effect: {to: "on"}}
    """
)

MANUAL = """
Choosing a style
   Each press of STYLE moves on to the next style, in this order:

      GOUDA → BRIE → FETA → GOUDA …

Keys
   MODE      warm or cool; hold 3 s for the others (SOAK, STORE)
   LID       CLOSED / OPEN
   START     START/STOP
   Tip: whey, milk, salt can be stored in the fridge.
"""


def _parse(sentence: str, manual: str = MANUAL) -> tuple[dict[str, object], list[str]]:
    notes: list[str] = []
    return parse_instruction(MAKER, sentence, manual, outside=notes), notes


def test_a_word_listed_below_a_sentence_naming_the_setting_is_kept_as_said() -> None:
    goal, notes = _parse("Brie, then start it.")
    assert goal["style"] == "brie", goal
    assert any("brie" in note and "lists it" in note for note in notes), notes


def test_a_word_listed_in_the_settings_legend_row_is_kept_as_said() -> None:
    goal, notes = _parse("Soak for a while please.")
    assert goal.get("mode") == "soak", goal
    assert notes


def test_a_verb_or_a_list_of_keys_gives_no_setting() -> None:
    goal, _ = _parse("Open the lid and stop.")
    assert goal.get("lid") != "open" and "style" not in goal and "mode" not in goal, goal


def test_a_lower_case_list_gives_no_setting() -> None:
    goal, _ = _parse("Add some salt.")
    assert set(goal) <= {"running"}, goal


def test_the_true_model_or_no_manual_changes_nothing() -> None:
    assert "style" not in parse_instruction(MAKER, "Brie, then start it.", MANUAL)
    goal, notes = _parse("Brie, then start it.", manual="")
    assert "style" not in goal and not notes, goal


def test_a_word_listed_for_two_settings_is_left_alone() -> None:
    manual = MANUAL + "\n   MODE      keeps the last style (GOUDA or BRIE)\n"
    goal, _ = _parse("Brie please.", manual)
    assert "style" not in goal and "mode" not in goal, goal


def test_a_safety_legend_below_a_line_naming_the_setting_lists_no_choices() -> None:
    manual = MANUAL + "\n   Read this page before you press STYLE.\n   DANGER / WARNING / CAUTION\n"
    goal, notes = _parse("Caution, then start it.", manual)
    assert "style" not in goal and not notes, goal


def test_a_row_with_a_label_of_its_own_takes_no_setting_from_above() -> None:
    manual = MANUAL + "\n   STYLE     see above\n   Model     PRO / MAX / ULTRA\n"
    goal, notes = _parse("Max, then start it.", manual)
    assert "style" not in goal and not notes, goal


def test_a_list_in_another_column_flattened_onto_a_keys_row_is_not_its_choices() -> None:
    manual = MANUAL + "\n   STYLE     picks a cheese          Model     PRO / MAX / ULTRA\n"
    goal, notes = _parse("Pro, then start it.", manual)
    assert "style" not in goal and not notes, goal


def test_a_list_of_what_the_lamps_show_gives_no_setting() -> None:
    """A run under a sentence saying what the lamps show is the states they light, not the
    choices of the key the sentence names."""
    manual = "After you press MODE, the lamps show:\n\n   HEATING / READY / DONE\n"
    goal, notes = _parse("Get it ready for tonight.", manual)
    assert "mode" not in goal and not notes, goal
