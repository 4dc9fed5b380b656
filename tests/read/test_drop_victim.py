"""When the checker refuses one of two features that share a first key, the reader gives up the
one whose amount is a pure guess, not the one whose range the manual states."""

from __future__ import annotations

from typing import Any

from apbot.read.drop_victim import feature_to_drop
from apbot.read.report import Note

_WHY = (
    "feature 'set_extra' can never start: every action of its first step already starts "
    "['set_extra_seconds']; give it a distinct first action or merge the features"
)


def _data() -> dict[str, Any]:
    return {
        "variables": {
            "extra": {"type": "time", "ranges": [["00:00:00", "00:01:00", 1]]},
            "extra_seconds": {"type": "time", "ranges": [["00:01:00", "01:00:00", 60]]},
        },
        "features": {
            "set_extra_seconds": [
                {"actions": ["hold_set"]},
                {"actions": ["press_plus"], "variable": "extra_seconds"},
            ],
            "set_extra": [
                {"actions": ["hold_set"]},
                {"actions": ["press_plus"], "variable": "extra"},
            ],
        },
    }


def test_the_guessed_owner_goes_when_the_refused_feature_has_a_stated_range() -> None:
    notes = [
        Note("variables.extra", "range 0–60 s", line=12, quote="The range is 0 to 60 seconds."),
        Note("variables.extra_seconds", "range 1–60 min (the manual gives none)", guess=True),
    ]
    assert feature_to_drop(_data(), "set_extra", _WHY, notes) == "set_extra_seconds"


def test_the_refused_feature_goes_when_the_owner_has_evidence_too() -> None:
    notes = [
        Note("variables.extra", "range 0–60 s", line=12, quote="The range is 0 to 60 seconds."),
        Note("variables.extra_seconds", "range 1–60 min", line=3, quote="1 to 60 minutes"),
    ]
    assert feature_to_drop(_data(), "set_extra", _WHY, notes) == "set_extra"


def test_the_refused_feature_goes_when_its_own_range_is_a_guess() -> None:
    notes = [
        Note("variables.extra", "range 0–10 (the manual gives none)", guess=True),
        Note("variables.extra_seconds", "range 1–60 min (the manual gives none)", guess=True),
    ]
    assert feature_to_drop(_data(), "set_extra", _WHY, notes) == "set_extra"


def test_another_complaint_drops_the_feature_it_names() -> None:
    notes = [Note("variables.extra_seconds", "range 1–60 min (the manual gives none)", guess=True)]
    assert feature_to_drop(_data(), "set_extra", "step 2 names no action", notes) == "set_extra"
