from __future__ import annotations

import pytest

from apbot.model.values import (
    expand_ranges,
    format_hms,
    format_time,
    parse_hms,
    parse_quantity,
    words_to_number,
)


def test_piecewise_ranges_share_their_boundary_once() -> None:
    assert expand_ranges([[0, 60, 10], [60, 720, 30]])[:9] == [0, 10, 20, 30, 40, 50, 60, 90, 120]
    assert expand_ranges([[0, 1, 0.1]])[-1] == 1  # decimal steps do not drift


def test_time_round_trip() -> None:
    assert parse_hms(format_hms(3725)) == 3725
    assert format_hms(100 * 3600) == "100:00:00"
    with pytest.raises(ValueError):
        parse_hms("1:30")


@pytest.mark.parametrize(
    ("seconds", "style", "shown"),
    [
        (90, "mm:ss", "01:30"),
        (5400, "h:mm", "1:30"),
        (5400, "hh:mm", "01:30"),
        (5400, "min", "90 min"),
        (5400, "h", "1.5 h"),
        (5400, "hh:mm:ss", "01:30:00"),
    ],
)
def test_display_styles(seconds: int, style: str, shown: str) -> None:
    assert format_time(seconds, style) == shown


@pytest.mark.parametrize(
    ("text", "number"),
    [
        ("forty five", 45),
        ("one and a half", 1.5),
        ("half", 0.5),
        ("two hundred", 200),
        ("twenty-five", 25),
        ("a dozen", 12),
    ],
)
def test_number_words(text: str, number: float) -> None:
    assert words_to_number(text) == number


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("half an hour", (1800, "time")),
        ("2 hrs", (7200, "time")),
        ("1 h 30 min", (5400, "time")),
        ("fifty percent", (50, "ratio")),
        ("2kg", (2000, "mass")),
        ("1.5 L", (1500, "volume")),
        ("40 °C", (40, "temperature")),
        ("1200 rpm", (1200, "speed")),
        ("45", (45, None)),
    ],
)
def test_quantities_with_units(text: str, expected: tuple[float, str | None]) -> None:
    value, dimension, _ = parse_quantity(text)  # type: ignore[misc]
    assert (value, dimension) == expected


def test_mixed_dimensions_are_not_a_quantity() -> None:
    assert parse_quantity("2 h 30 g") is None
    assert parse_quantity("quickly") is None


@pytest.mark.parametrize(
    ("text", "number"),
    [
        ("-5", -5),
        ("−0.5", -0.5),
        ("+3", 3),
        ("1-2", None),
        ("twenty-five", 25),
    ],
)
def test_signs_and_ranges(text: str, number: float | None) -> None:
    assert words_to_number(text) == number


def test_negative_quantities_keep_their_sign() -> None:
    assert parse_quantity("-5 °C") == (-5, "temperature", 1.0)
    assert parse_quantity("-18") == (-18, None, 1.0)


def test_micrometres_are_a_length() -> None:
    """Pouches and films are sold by the micron ("80 mic", "150 µm"): a length, never minutes."""
    assert parse_quantity("150 µm") == (0.15, "length", 1.0)
    assert parse_quantity("80 mic") == parse_quantity("80 microns") == (0.08, "length", 1.0)
    assert parse_quantity("150µm") == (0.15, "length", 1.0)
