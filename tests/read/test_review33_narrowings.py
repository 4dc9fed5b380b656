"""Narrowings of the previous session's goal-parser rules, each where it misfired on a sentence
of our own words: one end said of the settings joined by "and" taken for a setting that was
sent its own way before it ("the bass up and the treble all the way down"), the power read as
kept off from "without turning up the volume" (a setting's word after the particle), and
"stop <setting>" read where the sentence says not to stop it or to stop it later."""

from __future__ import annotations

from tests.read.test_goal_dropped33 import _brush, _parse
from tests.read.test_goal_parse33 import _detector


def test_a_setting_sent_its_own_way_before_a_joined_end_keeps_its_own() -> None:
    # the bass goes up (by how much is not said), only the treble to its end
    assert _parse("Turn the bass up and the treble all the way down.") == {"treble": 0}
    assert _parse("Bass up a little and the microphone right down.") == {"mic": 0}
    # settings only joined by "and" still share the end
    assert _parse("Turn the bass and the treble all the way up.") == {"bass": 8, "treble": 8}


def test_a_setting_turned_up_without_is_no_power_kept_off() -> None:
    assert "power" not in _brush("Without turning up the beep, pick the daily mode.")
    assert "power" not in _brush("Without switching on the beep, pick the deep mode.")
    # the appliance itself, with the particle first or last, is still kept off
    assert _brush("Without switching on the brush, pick the deep mode.")["power"] == "off"
    assert _brush("Without turning it on, pick the deep mode.")["power"] == "off"


def test_stop_said_not_to_or_for_later_is_no_off() -> None:
    assert "tracking" not in _detector("Keep tracking on, don't stop the tracking.")
    assert "tracking" not in _detector("Never stop tracking while I sweep.")
    assert "tracking" not in _detector("Stop tracking after ten minutes.")
    assert _detector("Stop tracking altogether.")["tracking"] == "off"
