"""Whatever the text, the reader returns a checked model or raises ReaderError — nothing else."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from apbot.bench.suite import load_suite
from apbot.model.validate import check_model
from apbot.read import ReaderError, read_manual

SUITE = load_suite("bundled")
MANUALS = [a.manual for a in SUITE.appliances]
ACTIONS = [list(a.model.actions) for a in SUITE.appliances]
FUZZ = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _passes(text: str, actions: list[str]) -> None:
    try:
        reading = read_manual(text, actions)
    except ReaderError as error:
        assert str(error).strip()  # a clear error says what is wrong
        return
    assert not [p for p in check_model(reading.model) if p.severity == "error"]
    assert set(reading.model.actions) == set(actions)  # exactly the appliance's action names


@FUZZ
@given(st.text(max_size=2000), st.sampled_from(ACTIONS))
def test_random_text(text, actions):
    _passes(text, actions)


@FUZZ
@given(st.binary(max_size=3000), st.sampled_from(ACTIONS))
def test_binary_garbage(data, actions):
    _passes(data.decode("latin-1"), actions)


@FUZZ
@given(st.integers(0, len(MANUALS) - 1), st.floats(0, 1), st.integers(0, len(MANUALS) - 1))
def test_truncated_manual_or_another_appliances_manual(i, cut, j):
    text = MANUALS[i][: int(len(MANUALS[i]) * cut)]
    _passes(text, ACTIONS[i])
    _passes(MANUALS[i], ACTIONS[j])  # the manual of another appliance


@FUZZ
@given(
    st.lists(
        st.from_regex(
            r"(press|hold|turn)_[a-z]{1,6}(_(cw|ccw|up|down|and_[a-z]{1,4}))?", fullmatch=True
        ),
        min_size=1,
        max_size=12,
        unique=True,
    ),
    st.sampled_from(MANUALS),
)
def test_random_action_names(actions, manual):
    _passes(manual, actions)


@FUZZ
@given(
    st.integers(0, len(MANUALS) - 1),
    st.lists(st.integers(0, 10**6), min_size=1, max_size=40),
    st.binary(min_size=1, max_size=200),
)
def test_a_manual_with_garbage_and_shuffled_lines(i, picks, junk):
    """A vision model's text: lines out of order, repeated, with binary junk spliced in."""
    lines = MANUALS[i].splitlines() or [""]
    mixed = [lines[p % len(lines)] for p in picks]
    mixed.insert(picks[0] % len(mixed), junk.decode("utf-8", errors="replace"))
    _passes("\n".join(mixed), ACTIONS[i])


@FUZZ
@given(st.sampled_from(MANUALS), st.sampled_from(MANUALS), st.sampled_from(ACTIONS))
def test_two_manuals_run_together(first, second, actions):
    """Two appliances' manuals in one file (another appliance's names everywhere)."""
    _passes(first + "\n\n" + second, actions)


def test_input_that_is_not_a_manual_raises_reader_error():
    for bad in (b"bytes", 42, None):
        with pytest.raises(ReaderError, match="text"):
            read_manual(bad, ["press_power"])  # type: ignore[arg-type]
    with pytest.raises(ReaderError, match="characters"):
        read_manual("x" * 500_000, ["press_power"])
    for names in ([], ["press power"], [""], ["press_power", "press_power"]):
        with pytest.raises(ReaderError):
            read_manual(MANUALS[0], names)
