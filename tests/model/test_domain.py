from __future__ import annotations

import math
import time

import pytest

from apbot.model.domain import DomainError, ValueProblem, build_domain, normalise
from apbot.model.limits import MAX_VALUES
from apbot.model.schema import DiscreteVariable, NumericVariable, TimeVariable
from apbot.model.values import expand_ranges


def numeric(**kw: object) -> NumericVariable:
    return NumericVariable.model_validate({"type": "numeric", **kw})


def test_numeric_goal_values_in_any_unit() -> None:
    delay = numeric(ranges=[[0, 60, 10], [60, 720, 30]], unit="min")
    assert normalise(delay, "2 h") == 120
    assert normalise(delay, "half an hour") == 30
    assert normalise(delay, 90) == 90
    with pytest.raises(ValueProblem, match="not one of its values"):
        normalise(delay, "75 min")
    with pytest.raises(ValueProblem, match="not a quantity in min"):
        normalise(delay, "40 %")


def test_time_goal_values() -> None:
    cook = TimeVariable.model_validate(
        {"type": "time", "format": "mm:ss", "ranges": [["00:00:00", "01:00:00", 30]]}
    )
    assert normalise(cook, "1:30") == "00:01:30"  # mm:ss display: minutes and seconds
    assert normalise(cook, "90 seconds") == "00:01:30"
    assert normalise(cook, "00:45:00") == "00:45:00"
    with pytest.raises(ValueProblem, match="ambiguous"):
        normalise(cook, 30)
    clock = TimeVariable.model_validate(
        {"type": "time", "format": "h:mm", "ranges": [["01:00:00", "12:59:00", 60]]}
    )
    assert normalise(clock, "9:45") == "09:45:00"  # h:mm display: hours and minutes


def test_discrete_values_tolerate_case_punctuation_and_units() -> None:
    programme = DiscreteVariable.model_validate(
        {"type": "discrete", "values": ["Quick Wash", "cotton", "20", "40"]}
    )
    assert normalise(programme, "quick-wash") == "Quick Wash"
    assert normalise(programme, "40 °C") == "40"
    with pytest.raises(ValueProblem, match="did you mean 'cotton'"):
        normalise(programme, "coton")


def test_switch_values_from_yaml_booleans() -> None:
    power = DiscreteVariable.model_validate({"type": "discrete", "values": [False, True]})
    assert power.values == ["false", "true"]
    on_off = DiscreteVariable.model_validate({"type": "discrete", "values": ["off", "on"]})
    assert normalise(on_off, "ON") == "on"


def test_domain_errors_say_what_is_wrong() -> None:
    with pytest.raises(DomainError, match="inside range 1"):
        build_domain(numeric(ranges=[[0, 60, 10], [50, 100, 10]]))
    with pytest.raises(DomainError, match="not reached from 0 in steps of 10"):
        build_domain(numeric(ranges=[[0, 55, 10]]))
    with pytest.raises(DomainError, match="initial value 7"):
        build_domain(numeric(ranges=[[0, 10, 5]], initial=7))


def test_wrap_and_clamp() -> None:
    domain = build_domain(numeric(ranges=[[0, 20, 10]]))
    assert [domain.next_index(2), domain.prev_index(0)] == [2, 0]
    wrapping = build_domain(numeric(ranges=[[0, 20, 10]], wrap=True))
    assert [wrapping.next_index(2), wrapping.prev_index(0)] == [0, 2]


def test_adding_to_a_wrapping_clock_counts_round() -> None:
    from apbot.model.schema import TimeVariable

    clock = build_domain(
        TimeVariable.model_validate(
            {"type": "time", "wrap": True, "ranges": [["00:00:00", "23:59:00", 60]]}
        )
    )
    assert clock.values[clock.snap_index(23.5 * 3600 + 3600)] == "00:30:00"
    assert clock.values[clock.snap_index(-60)] == "23:59:00"
    uneven = build_domain(numeric(ranges=[[0, 10, 5], [10, 30, 10]], wrap=True))
    assert uneven.values[uneven.snap_index(35)] == 0
    clamped = build_domain(numeric(ranges=[[0, 10, 5]]))
    assert clamped.values[clamped.snap_index(15)] == 10


def test_values_in_the_variables_own_unit() -> None:
    loaf = numeric(ranges=[[1.5, 2.5, 0.5]], unit="lb")
    assert normalise(loaf, "2.5 lb") == 2.5
    assert normalise(loaf, "2.5 pounds") == 2.5
    cups = numeric(ranges=[[1, 10, 1]], unit="cups")
    assert normalise(cups, "3 cups") == 3
    fahrenheit = numeric(ranges=[[150, 450, 25]], unit="°F")
    assert normalise(fahrenheit, "350 °F") == 350
    with pytest.raises(ValueProblem):
        normalise(fahrenheit, "180 °C")  # never silently converted


def test_subtracting_snaps_down() -> None:
    coarse = build_domain(numeric(ranges=[[0, 10, 1], [10, 60, 10]]))
    assert coarse.values[coarse.snap_index(20 - 1, down=True)] == 10
    assert coarse.values[coarse.snap_index(20 - 1)] == 20  # adding snaps up


# --- large domains: linear checks, bounded messages, an enforced limit ---------------------------


def discrete(values: list[str], **kw: object) -> DiscreteVariable:
    return DiscreteVariable.model_validate({"type": "discrete", "values": values, **kw})


def test_a_30000_value_domain_with_a_repeat_is_checked_in_linear_time() -> None:
    values = [f"v{i}" for i in range(30_000)]
    started = time.perf_counter()
    assert len(build_domain(discrete(values))) == 30_000
    with pytest.raises(DomainError, match=r"'v7' is listed twice \(as value 8 and 30000\)"):
        build_domain(discrete([*values[:-1], "v7"]))
    assert time.perf_counter() - started < 2.0  # 44 s with a list.count per value


def test_messages_about_a_huge_domain_stay_short() -> None:
    values = [f"v{i}" for i in range(10_000)]
    with pytest.raises(DomainError) as caught:
        build_domain(discrete(values, initial="nosuch"))
    message = str(caught.value)
    assert message.endswith("'v9999'] (10,000 in all)") and len(message) < 200
    with pytest.raises(ValueProblem) as goal:
        normalise(discrete(values), "nosuch")
    assert "(10,000 in all)" in str(goal.value) and len(str(goal.value)) < 200


def test_a_domain_past_the_limit_is_refused_without_listing_it() -> None:
    assert len(build_domain(numeric(ranges=[[1, MAX_VALUES, 1]]))) == MAX_VALUES
    started = time.perf_counter()
    with pytest.raises(DomainError, match=f"at most {MAX_VALUES:,}"):
        build_domain(numeric(ranges=[[0, 3_000_000, 1]]))
    with pytest.raises(DomainError, match=f"at most {MAX_VALUES:,}"):
        build_domain(discrete([f"v{i}" for i in range(MAX_VALUES + 1)]))
    assert time.perf_counter() - started < 2.0


def test_whole_number_ranges_expand_like_decimal_ones() -> None:
    assert expand_ranges([[0, 60, 10], [60.0, 120.0, 30.0]]) == [0, 10, 20, 30, 40, 50, 60, 90, 120]
    assert expand_ranges([[0, 1, 0.25], [1, 3, 1]]) == [0, 0.25, 0.5, 0.75, 1, 2, 3]
    assert all(type(v) is int for v in expand_ranges([[0.0, 4.0, 2.0]]))
    with pytest.raises(ValueError, match="step must be positive"):
        expand_ranges([[0, 10, 0]])  # looped for ever


@pytest.mark.parametrize("raw", [math.inf, math.nan, 10**400, "9" * 400, "9" * 400 + " h"])
def test_infinite_or_enormous_goal_numbers_are_value_problems(raw: object) -> None:
    """Found by the goal fuzzer: int(inf) raised an OverflowError from inside normalise."""
    minutes = numeric(ranges=[[0, 120, 30]], unit="min")
    timer = TimeVariable.model_validate({"type": "time", "ranges": [["00:00:00", "01:00:00", 60]]})
    for var in (minutes, timer):
        with pytest.raises(ValueProblem) as caught:
            normalise(var, raw)
        assert len(str(caught.value)) < 150
