from __future__ import annotations

import pytest

from apbot.model.domain import DomainError, ValueProblem, build_domain, normalise
from apbot.model.schema import DiscreteVariable, NumericVariable, TimeVariable


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
