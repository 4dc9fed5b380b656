"""Keys printed as a name and a sign ("A- / A+", "POSITION < / >") whose actions are named
for what they do: found by their key table's row, then read as one stepping pair; and a hold
written as a sentence of the key's row. Each rule on a small manual of our own words."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.labels_legend import _said

# a sign maker: a letter key with two signs, actions named for the way they change the size
SIGN_MAKER = """
LetterJet LJ-2 sign maker

| No. | Key | Function |
|---|---|---|
| (1) | A- | Smaller letters |
| (2) | A+ | Larger letters |
| (3) | MODE | Letter mode. Hold 2 seconds: mirror writing on / off |

Letter height (A- / A+)
Each press of A+ makes the letters one size larger, each press of A- one size smaller.
The heights are: 10, 20, 30, 40 and 50 mm.

MODE steps through NORMAL → BOLD → NORMAL.
"""
SIGN_ACTIONS = ["press_smaller", "press_larger", "press_mode", "hold_mode"]

# a shower arm: a name with < and > for back and forward
SHOWER = """
Aqua SA-1 shower arm

| Key | Name | Touch briefly |
|---|---|---|
| (A) | ANGLE < | arm further back |
| (B) | ANGLE > | arm further forward |
| (C) | FLOW | next flow |

The arm angle goes from 1 to 5.
FLOW steps through LOW → HIGH → LOW.
"""
SHOWER_ACTIONS = ["press_angle_back", "press_angle_fwd", "press_flow"]


def _step_of(model, action: str):  # type: ignore[no-untyped-def]
    return next(s for steps in model.features.values() for s in steps if action in s.actions)


def test_an_action_word_is_found_in_a_row_by_itself_its_start_or_its_letters() -> None:
    assert _said("smaller", ["smaller", "letters"])
    assert _said("pos", ["position"])
    assert _said("fwd", ["arm", "further", "forward"])
    assert not _said("fwd", ["arm", "further", "back"])
    assert not _said("set", ["sweet"])  # letters with vowels abbreviate only as a word's start


def test_a_key_printed_as_a_sign_is_named_by_its_row_and_paired_with_its_opposite() -> None:
    model = read_manual(SIGN_MAKER, SIGN_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    step = _step_of(model, "press_larger")
    assert step.variable == "letter_height"  # named by "Letter height (A- / A+)"
    assert step.effect == {"press_larger": "next", "press_smaller": "prev"}
    assert model.variables["letter_height"].unit == "mm"


def test_a_name_with_less_than_and_greater_than_signs_is_one_pair() -> None:
    model = read_manual(SHOWER, SHOWER_ACTIONS).model
    step = _step_of(model, "press_angle_fwd")
    assert step.effect == {"press_angle_fwd": "next", "press_angle_back": "prev"}
    assert _step_of(model, "press_angle_back").variable == step.variable


def test_a_hold_written_as_a_sentence_of_the_keys_row_switches_its_own_setting() -> None:
    model = read_manual(SIGN_MAKER, SIGN_ACTIONS).model
    step = _step_of(model, "hold_mode")
    assert step.variable == "mirror_writing" and step.effect == "toggle"


def test_a_hold_sentence_that_switches_on_and_off_by_a_verb_is_no_setting() -> None:
    manual = SIGN_MAKER.replace("mirror writing on / off", "switch on / off")
    step = _step_of(read_manual(manual, SIGN_ACTIONS).model, "hold_mode")
    assert step.variable != "switch"


# a steamer whose parts list (not a key table) says "steam" in the lid's row
STEAMER = """
Vapora V-1 food steamer

| No. | Part | Description |
|---|---|---|
| 1 | Lid | lets the steam out through its vent |
| 2 | Basket | holds the food |

Keys: ⏻ switches the steamer on and off. ♨ starts steaming.
Open the lid before you fill the tank.
"""


def test_a_parts_list_names_no_key() -> None:
    from apbot.read.labels import find_labels
    from apbot.read.text import parse_manual

    labels = find_labels(parse_manual(STEAMER), ["power", "steam"])
    assert labels["steam"].text != "Lid"
