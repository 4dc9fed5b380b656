"""Belief strings that name fault kinds: parsed, canonical, checked, and obeyed."""

from __future__ import annotations

import pytest

from apbot.bench.beliefs import BeliefError, belief_model, parse_belief
from apbot.bench.faults import fault_kind
from apbot.bench.suite import load_suite


def test_a_belief_can_name_fault_kinds_in_a_canonical_order() -> None:
    spec = parse_belief("faulty:0.30:guard, display")
    assert spec.kinds == ("display", "guard")
    assert str(spec) == "faulty:0.3:display,guard"
    assert parse_belief(str(spec)) == spec
    assert parse_belief("faulty:0.3").kinds == ()


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("faulty:0.3:gaurd", "unknown fault kind.*gaurd.*known: step_size"),
        ("faulty:0.3:", "name at least one fault kind"),
        ("faulty:0.3: , ", "name at least one fault kind"),
    ],
)
def test_bad_fault_kinds_are_refused_naming_them(text: str, message: str) -> None:
    with pytest.raises(BeliefError, match=message):
        parse_belief(text)


def test_the_faulty_model_has_only_the_named_kinds() -> None:
    appliance = load_suite().get("washing_machine_2")
    _, everything = belief_model(appliance, "faulty:1", 3)
    _, guards = belief_model(appliance, "faulty:1:guard", 3)
    assert guards and {fault_kind(f) for f in guards} == {"guard"}
    assert {fault_kind(f) for f in everything} > {"guard"}
