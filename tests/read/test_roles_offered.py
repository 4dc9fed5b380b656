"""Keys offered as alternatives for one named thing: each key picks one value of it."""

from __future__ import annotations

from apbot.read import read_manual

ACTIONS = ["press_still", "press_fizzy", "press_chilled", "press_size", "press_pour"]

# a drinks tap whose STILL / FIZZY / CHILLED keys each choose the drink; a chart row beside
# CHILLED's name gives a range that is no setting of that key's own
TAP = """DRINKS TAP DT-2 GUIDE

CONTROLS

STILL, FIZZY, CHILLED, SIZE and POUR are touch keys.

CHOOSING THE DRINK

Tap STILL, FIZZY or CHILLED. The screen shows the name of the drink selected.

SIZE gives the next glass size: 200 ml, 300 ml, 500 ml.

POUR starts and stops pouring.

| Use | Key | Temperature |
| Lemonade | CHILLED | 4 – 8 °C |
"""


def test_offered_keys_are_one_setting_named_by_the_chosen_thing() -> None:
    model = read_manual(TAP, ACTIONS).model
    drink = model.variables["drink"]
    assert drink.values == ["still", "fizzy", "chilled"]
    assert [getattr(s.effect, "to", None) for s in model.features["chilled"]] == ["chilled"]
    assert "chilled" not in model.variables


def test_keys_offered_without_a_chosen_thing_keep_their_roles() -> None:
    text = TAP.replace("The screen shows the name of the drink selected.", "")
    model = read_manual(text, ACTIONS).model
    assert "drink" not in model.variables
