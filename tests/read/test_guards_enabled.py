"""Keys that work only while a switch is on ("+ and - only work while warming is on"), on a
small manual written in our own words: a guard refuses them while the switch is off."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

WARMER = """PLATO W-2 PLATE WARMER
Instructions

  Key      What it does
  -------  -----------------------------------------------------------
  ON/OFF   Switches the warmer on or off.
  WARM     Warming on / off.
  +        Raises the plate temperature by 5 degrees.
  -        Lowers the plate temperature by 5 degrees.

Setting the temperature

  1. Press WARM. The WARM lamp lights.
  2. Press + or - to set the plate temperature, 40 to 80 °C.
{rule}
"""
ACTIONS = ["press_on_off", "press_warm", "press_plus", "press_minus"]


def _warm_guard(text: str) -> list[str] | None:
    model = read_manual(text, ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    for guard in model.guards:
        if list(guard.when) == ["warm"]:
            return list(guard.only)
    return None


def test_keys_that_only_work_while_a_switch_is_on_are_refused_while_it_is_off() -> None:
    only = _warm_guard(WARMER.format(rule="+ and - only work while warming is on."))
    assert only is not None
    assert "press_plus" not in only and "press_minus" not in only
    assert "press_warm" in only and "press_on_off" in only


def test_a_legend_saying_the_keys_need_the_switch_on() -> None:
    text = WARMER.format(rule="").replace("by 5 degrees.", "by 5 degrees (warming on only).")
    only = _warm_guard(text)
    assert only is not None and "press_plus" not in only


def test_keys_with_no_effect_while_the_switch_is_off() -> None:
    only = _warm_guard(WARMER.format(rule="With warming off + and - have no effect."))
    assert only is not None and "press_minus" not in only


def test_no_such_sentence_gives_no_guard() -> None:
    assert _warm_guard(WARMER.format(rule="The temperature is kept when switched off.")) is None


TIMED = WARMER.replace(
    "  -        Lowers the plate temperature by 5 degrees.\n",
    "  -        Lowers the plate temperature by 5 degrees.\n"
    "  TIMER    Sets the switch-off time, 1 to 8 hours.\n",
)


def _refused(rule: str) -> set[str]:
    actions = [*ACTIONS, "press_timer"]
    model = read_manual(TIMED.format(rule=rule), actions).model
    only = next((g.only for g in model.guards if list(g.when) == ["warm"]), None)
    return set() if only is None else set(actions) - set(only)


def test_a_key_named_in_the_next_clause_is_not_refused() -> None:
    rule = "+ and - only work while warming is on; TIMER works at any time."
    assert _refused(rule) == {"press_plus", "press_minus"}


def test_no_effect_said_of_something_else_after_but_refuses_no_key() -> None:
    rule = "With warming off, TIMER still counts down but the plate does not change its heat."
    assert "press_timer" not in _refused(rule)
