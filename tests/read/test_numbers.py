"""Numbers in words, durations, clock times and units, as the goal parser reads them."""

from __future__ import annotations

import pytest

from apbot.read.number_tokens import read_number, tokenize
from apbot.read.numbers import find_mentions


def mentions(text: str) -> list[tuple[str, float]]:
    return [(m.kind, m.value) for m in find_mentions(tokenize(text))]


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("seventy", 70),
        ("twenty-five", 25),
        ("two hundred fifty", 250),
        ("three hundred and twenty-five", 325),
        ("one thousand two hundred", 1200),
        ("two and a half", 2.5),
        ("four and a quarter", 4.25),
        ("three quarters", 0.75),
        ("1.5", 1.5),
        ("a single", 1),
        ("twice", 2),
    ],
)
def test_numbers_in_words(text: str, value: float) -> None:
    number = read_number(tokenize(text), 0)
    assert number is not None and number.value == value
    assert number.end == len(tokenize(text))


def test_words_that_are_not_numbers() -> None:
    assert read_number(tokenize("blue"), 0) is None
    # "twenty" then "thirty" is two numbers, not fifty
    assert read_number(tokenize("twenty thirty"), 0).value == 20  # type: ignore[union-attr]


@pytest.mark.parametrize(
    ("text", "seconds"),
    [
        ("half an hour", 1800),
        ("an hour and a half", 5400),
        ("two and a half hours", 9000),
        ("a quarter of an hour", 900),
        ("three quarters of an hour", 2700),
        ("2 hrs 30 mins", 9000),
        ("1 hr 20", 4800),
        ("8 min 30 sec", 510),
        ("6 min 45 s", 405),
        ("two hours and fifteen minutes", 8100),
        ("a 12-minute timer", 720),
        ("a full hour", 3600),
        ("4.5 hours", 16200),
        ("a day", 86400),
    ],
)
def test_durations(text: str, seconds: int) -> None:
    assert mentions(text)[0] == ("duration", seconds)


@pytest.mark.parametrize(
    ("text", "clock"),
    [
        ("ready by 7:30", "07:30"),
        ("at 7:30 pm", "19:30"),
        ("10:15 p.m.", "22:15"),
        ("9 pm", "21:00"),
        ("12 am", "00:00"),
        ("8 o'clock", "08:00"),
        ("nine o'clock tonight", "21:00"),
        ("half past six", "06:30"),
        ("a quarter to eight", "07:45"),
        ("4:30 in the afternoon", "16:30"),
        ("7 in the evening", "19:00"),
        ("6:30 tomorrow morning", "06:30"),
        ("21:00", "21:00"),
    ],
)
def test_clock_times(text: str, clock: str) -> None:
    found = [m for m in find_mentions(tokenize(text)) if m.kind == "clock"]
    assert found, text
    hours, minutes = divmod(int(found[0].value) // 60, 60)
    assert f"{hours:02d}:{minutes:02d}" == clock


@pytest.mark.parametrize(
    ("text", "kind", "value", "dimension"),
    [
        ("fifty percent", "quantity", 50, "ratio"),
        ("35 per cent", "quantity", 35, "ratio"),
        ("1.5 kW", "quantity", 1500, "power"),
        ("1.5 kg", "quantity", 1500, "mass"),
        ("a half-kilo loaf", "quantity", 500, "mass"),
        ("600 millilitres", "quantity", 600, "volume"),
        ("350°F", "fahrenheit", 350, "fahrenheit"),
        ("390 degrees Fahrenheit", "fahrenheit", 390, "fahrenheit"),
        ("40 °C", "quantity", 40, "temperature"),
        ("one hundred seventy degrees", "quantity", 170, "temperature"),
        ("spin at 800", "number", 800, None),
    ],
)
def test_quantities_and_units(text: str, kind: str, value: float, dimension: str | None) -> None:
    found = find_mentions(tokenize(text))
    assert len(found) == 1, found
    assert (found[0].kind, found[0].value, found[0].dimension) == (kind, value, dimension)


def test_tokens_split_units_and_clauses() -> None:
    assert [t.text for t in tokenize("12min, 350°F")] == ["12", "min", ",", "350", "°f"]
    assert ";" in [t.text for t in tokenize("water — heat it")]
    assert [t.text for t in tokenize("steam-and-dry")] == ["steam", "-", "and", "-", "dry"]


def test_a_range_is_not_a_clock_or_a_sum() -> None:
    assert mentions("eco 40-60") == [("number", 40), ("number", 60)]


def test_british_and_named_clock_times() -> None:
    assert mentions("ready by 7.30") == [("clock", 7 * 3600 + 30 * 60)]
    assert mentions("at midnight") == [("clock", 0)]
    assert mentions("bake for 2.5 hours") == [("duration", 9000)]
    assert mentions("a 1.75 oz bag")[0][0] == "quantity"


def test_minutes_past_and_to_an_hour() -> None:
    """A clock face's words: "twenty past one", "ten to eight"; "5 to 8" and "from five to
    eight minutes" stay a range."""
    assert mentions("it's twenty past one") == [("clock", 3600 + 20 * 60)]
    assert mentions("at ten to eight") == [("clock", 7 * 3600 + 50 * 60)]
    assert mentions("twenty-five past six in the evening") == [("clock", 18 * 3600 + 25 * 60)]
    assert mentions("from five to eight minutes") == [("number", 5), ("duration", 480)]
    assert mentions("ten to twelve minutes") == [("number", 10), ("duration", 720)]


def test_minutes_to_one_are_before_one_not_after_midnight() -> None:
    """ "ten to one" is 12:50 (noon or, said so, midnight), never 00:50 on a 12-hour clock."""
    assert mentions("set the clock to ten to one") == [("clock", 12 * 3600 + 50 * 60)]
    assert mentions("at ten to one in the morning") == [("clock", 50 * 60)]
    assert mentions("at ten to one in the afternoon") == [("clock", 12 * 3600 + 50 * 60)]


def test_a_dotted_time_with_its_half_of_the_day_and_a_bare_hour_with_a_day_part() -> None:
    assert mentions("from 7 am to 9.30 pm") == [("clock", 7 * 3600), ("clock", 21 * 3600 + 1800)]
    assert mentions("water at eight tonight") == [("clock", 20 * 3600)]
    assert mentions("from 10 in the morning to 10 at night") == [
        ("clock", 10 * 3600),
        ("clock", 22 * 3600),
    ]
    assert mentions("cook 2.50 kg") == [("quantity", 2500)]


def test_a_thickness_in_micrometres_is_no_duration() -> None:
    """The micro sign is no word letter: "150 µm" once read as 150 minutes (its bare "m")."""
    assert [t.text for t in tokenize("150 µm pouches")] == ["150", "micron", "pouches"]
    assert [t.text for t in tokenize("175μm")] == ["175", "micron"]  # Greek mu, no space
    assert not [m for m in find_mentions(tokenize("150 µm pouches")) if m.kind == "duration"]
