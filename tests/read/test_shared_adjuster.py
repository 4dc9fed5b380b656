"""A function key that chooses which setting a shared adjuster changes (roles_shared), each
rule on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual

# a contact grill: one pair of arrow keys, a SET key that hands them the other setting
GRILL = """# Contact grill

## Keys

| Key | Use |
|---|---|
| ON/OFF | Power. |
| SET | Toggles the arrow keys between the grilling time and the temperature. |
| UP / DOWN | Raise or lower the value on the display. |
| GO | Starts grilling. |

## Grilling

The arrow keys normally change the grilling time (1 to 30 minutes).
To change the heat, press SET: the temperature blinks. Use UP and DOWN to pick 160 to 230 °C.
Press SET once more to return to the time.
"""
GRILL_ACTIONS = ["press_on_off", "press_set", "press_up", "press_down", "press_go"]


def _steps(model: object, var: str) -> list[list[tuple[str, ...]]]:
    feats = model.features  # type: ignore[attr-defined]
    return [
        [tuple(s.actions) for s in steps]
        for steps in feats.values()
        if any(s.variable == var for s in steps)
    ]


def test_a_key_that_switches_the_pair_gives_it_both_settings() -> None:
    model = read_manual(GRILL, GRILL_ACTIONS).model
    temps = [v for v in model.variables if v.startswith("temp")]
    times = [v for v in model.variables if "time" in v]
    assert temps and times, list(model.variables)
    pair = ("press_up", "press_down")
    # after SET the arrows set the temperature, after SET again the time
    assert [("press_set",), pair, ("press_set",), pair] in _steps(model, temps[0])
    # alone they set the time (their own sentence says so)
    assert [pair] in _steps(model, times[0])
