"""Defects a code review found in the reader, each on a small manual of its own."""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from apbot.model.validate import check_model
from apbot.read import ReaderError, read_manual

KNOB = ["turn_mode_knob_clockwise", "press_start_button"]


def _checked(text: str, actions: list[str]) -> None:
    try:
        reading = read_manual(text, actions)
    except ReaderError as error:
        assert str(error).strip()
        return
    assert not [p for p in check_model(reading.model) if p.severity == "error"]


def test_a_knob_with_zero_positions_is_read_without_a_list() -> None:
    text = "# T\n\nThe MODE knob has zero positions.\n\nTurn the MODE knob to select.\n"
    model = read_manual(text, KNOB).model  # (raised ValueError: int('zero'))
    assert not [p for p in check_model(model) if p.severity == "error"]


def test_a_counted_knob_in_words_takes_the_row_of_that_many_names() -> None:
    text = "# T\n\nThe MODE knob has three positions.\n\nDRY · STEAM · GRILL\n"
    model = read_manual(text, KNOB).model
    assert model.variables["mode_knob"].values == ["dry", "steam", "grill"]


_COUNT = st.sampled_from(["zero", "0", "00", "one", "nineteen", "12", "99", "no", "a"])
_AMOUNT = st.sampled_from(["0", "0.5", "1,5", "zero", "half", "ten", "24", "1000", "00"])
_UNIT = st.sampled_from(["min", "hours", "s", "°C", "%", "kg", "g", "W", ""])


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_COUNT, _AMOUNT, _AMOUNT, _AMOUNT, _UNIT)
def test_counted_ranged_and_stepped_phrases_with_odd_numbers_read_or_refuse(
    count: str, low: str, high: str, step: str, unit: str
) -> None:
    text = (
        f"# T\n\nThe MODE knob has {count} positions.\n\n{low} {unit} · {high} {unit}\n\n"
        f"Set the time from {low} to {high} {unit} in steps of {step} {unit}.\n\n"
        f"Each press of TIMER adds {step} {unit}, up to {high} {unit}.\n\n"
        f"| Programme | Time ({unit}) |\n|---|---|\n| BAKE | {low}–{high} |\n| GRILL | {high} |\n"
    )
    _checked(text, [*KNOB, "press_timer_button"])
