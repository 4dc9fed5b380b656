"""The end check learns an on/off lamp's word only from the latest press that showed the
setting other than predicted, and only while the display still shows what that press left:
an older press's predicted value is no longer the setting's value (review7b finding 4)."""

from __future__ import annotations

from apbot.agent.checking import _latest_switch
from apbot.agent.environment import Feedback
from apbot.agent.executed import Executed
from apbot.plan.plan import PlannedAction


def _press(text: str, surprised: bool) -> Executed:
    action = PlannedAction("press_mist", "press", ("mist",))
    surprises = {"mist": ("on", "off")} if surprised else {}
    return Executed(action, None, "mist", Feedback(text), True, surprises=surprises)


def test_an_older_press_whose_screen_has_since_changed_is_not_learnt_from() -> None:
    switched, later = _press("WARM  MIST 3", True), _press("MIST 3", False)
    assert _latest_switch("mist", [switched, later]) is None


def test_the_latest_switching_press_is_learnt_from_while_its_screen_stays() -> None:
    first, second = _press("WARM  MIST 3", True), _press("MIST 3", True)
    assert _latest_switch("mist", [first, second]) is second
    looked = _press("MIST 3", False)
    assert _latest_switch("mist", [first, second, looked]) is second
