"""Image mode: touches resolved on the true panel, the agent run through photos."""

from __future__ import annotations

import numpy as np
import pytest

from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.bench.suite import load_suite
from apbot.vision.environment import ImageEnvironment, PanelEnvironment
from apbot.vision.ground import Grounded, Grounding


@pytest.fixture(scope="module")
def suite():  # type: ignore[no-untyped-def]
    return load_suite()


def _centre(panel: PanelEnvironment, control: str) -> tuple[float, float]:
    box = next(c.box for c in panel.scene.layout.controls if c.id == control)
    x0, y0, x1, y1 = panel.photo().photo_box(box)
    return ((x0 + x1) / 2, (y0 + y1) / 2)


def test_a_touch_on_a_control_acts_and_one_beside_it_does_not(suite) -> None:  # type: ignore[no-untyped-def]
    panel = PanelEnvironment(suite.get("microwave_1"))
    panel.reset()
    touch = panel.touch([_centre(panel, "power_level_pad")], "press")
    assert touch.action == "press_power_level" and touch.observation is not None
    nothing = panel.touch([(2.0, 2.0)], "press")  # the wall around the panel
    assert nothing.controls == () and nothing.action is None
    held = panel.touch([_centre(panel, "stop_pad")], "hold", 3.0)
    assert held.action == "hold_stop"


def test_turns_and_two_finger_holds(suite) -> None:  # type: ignore[no-untyped-def]
    panel = PanelEnvironment(suite.get("washing_machine_1"))
    panel.reset()
    assert panel.touch([_centre(panel, "programme_dial")], "turn_ccw").action == (
        "turn_programme_ccw"
    )
    two = [_centre(panel, "rinse_button"), _centre(panel, "end_time_button")]
    assert panel.touch(two, "hold", 3.0).action == "hold_rinse_and_end_time"


def _true_grounding(panel: PanelEnvironment) -> Grounding:
    """Grounding from the layout itself: only to test the environment's mechanics."""
    photo = panel.photo()
    boxes = {c.id: photo.photo_box(c.box) for c in panel.scene.layout.controls}
    found = {}
    for name, action in panel.appliance.model.actions.items():
        if action.skill == "wait":
            continue
        controls = [action.control] if action.control else list(action.controls or [])
        found[name] = Grounded(name, action.skill, [boxes[c] for c in controls], name, 1.0)
    ungrounded = {
        n: "a wait touches no control"
        for n, a in panel.appliance.model.actions.items()
        if a.skill == "wait"
    }
    return Grounding(found, ungrounded, [], None, photo.image.size)


def test_the_agent_reaches_a_goal_through_photos(suite) -> None:  # type: ignore[no-untyped-def]
    appliance = suite.get("kettle_1")
    task = appliance.tasks[0]
    panel = PanelEnvironment(appliance)
    env = ImageEnvironment(panel, list(appliance.model.actions), _true_grounding(panel))
    context = TaskContext(appliance.id, appliance.category, task.id, task.instruction,
                          dict(task.goal), appliance.model, appliance.manual,
                          tuple(env.actions))  # fmt: skip
    episode = get_method("apbot").run(context, env)
    assert episode.claimed_success
    assert all(env.simulator.value(k) is not None for k in task.goal)


def test_an_ungrounded_action_spends_a_step_and_changes_nothing(suite) -> None:  # type: ignore[no-untyped-def]
    appliance = suite.get("kettle_1")
    panel = PanelEnvironment(appliance)
    empty = Grounding({}, {a: "no label" for a in appliance.model.actions}, [], None, (0, 0))
    env = ImageEnvironment(panel, list(appliance.model.actions), empty)
    before = env.reset().text
    after = env.step(next(iter(appliance.model.actions)))
    assert env.steps == 1 and after.text == before
    assert np.asarray(after.image.photo).size > 0
