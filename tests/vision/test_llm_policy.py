"""llm-policy-image against the scripted OpenAI-compatible server: box k → a touch at k's centre."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from apbot.agent.episode import TaskContext
from apbot.agent.registry import default_methods, methods
from apbot.bench.suite import SuiteAppliance, bundled_suite_dir, load_appliance
from apbot.vision.environment import ImageEnvironment, PanelEnvironment
from apbot.vision.ground import Grounding
from apbot.vision.llm_policy import NoVision, centre, panel_boxes, run_llm_policy_image
from apbot.vision.render import PanelScene
from tests.llm.conftest import SECRET
from tests.llm.scripted import Reply, Script, serving


@pytest.fixture(scope="module")
def kettle() -> SuiteAppliance:
    return load_appliance(bundled_suite_dir() / "kettle_1")


@pytest.fixture
def script() -> Script:
    return Script()


@pytest.fixture
def llm_env(script: Script, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[str]:
    with serving(script) as url:
        monkeypatch.setenv("APBOT_LLM", f"{url}:scripted-model")
        monkeypatch.setenv("APBOT_LLM_KEY_ENV", "APBOT_TEST_KEY")
        monkeypatch.setenv("APBOT_TEST_KEY", SECRET)
        monkeypatch.setenv("APBOT_LLM_CACHE_DIR", str(tmp_path / "cache"))
        monkeypatch.setenv("APBOT_LLM_BACKOFF", "0.01")
        monkeypatch.setenv("APBOT_LLM_RETRIES", "0")
        yield url


def _env(appliance: SuiteAppliance) -> ImageEnvironment:
    panel = PanelEnvironment(appliance, scene=PanelScene.of(appliance))
    nothing = Grounding({}, {}, [], None, (0, 0))  # this method grounds nothing by name
    return ImageEnvironment(panel, list(appliance.model.actions), nothing)


def _context(appliance: SuiteAppliance) -> TaskContext:
    task = appliance.tasks[0]
    return TaskContext(
        appliance.id,
        appliance.category,
        task.id,
        task.instruction,
        dict(task.goal),
        appliance.model,
        manual=appliance.manual,
        actions=tuple(appliance.model.actions),
        max_reasoning_steps=5,
    )


def _box_on(env: ImageEnvironment, control: str) -> int:
    """The 1-based number of a box whose centre lies on ``control`` (as the method numbers)."""
    boxes = panel_boxes(np.asarray(env.panel.latest.image))
    for k, box in enumerate(boxes, 1):
        if env.panel.control_at(*centre(box), env.panel.latest) == control:
            return k
    raise AssertionError(f"no box on {control}")


def test_registered_only_when_named() -> None:
    assert "llm-policy-image" in methods()
    assert "llm-policy-image" not in default_methods()


def test_the_chosen_box_is_touched_at_its_centre(
    script: Script, llm_env: str, kettle: SuiteAppliance
) -> None:
    env = _env(kettle)
    env.reset()
    start = _box_on(env, "start_button")
    answers = [{"action": "press", "box": start}, {"action": "done"}]
    script.router = lambda body: Reply(json.dumps(answers[min(script.count, 2) - 1]))
    episode = run_llm_policy_image(_context(kettle), env)
    assert episode.claimed_success and episode.execution_steps == 1
    assert env.panel.touches == 1
    assert env.simulator.value("heating") == "on"  # the start key was pressed
    assert env.simulator.observe().display == "HEATING 100°C"
    first = script.requests[0]["messages"]
    assert first[1]["content"].startswith("User manual:")
    image = first[2]["content"][1]["image_url"]["url"]
    assert image.startswith("data:image/jpeg;base64,")
    assert "What you did so far:\n(nothing yet)" in first[3]["content"]
    second = script.requests[1]["messages"][3]["content"]
    assert f"1. press box {start}" in second
    assert SECRET not in json.dumps(script.requests)


def test_a_box_on_no_control_does_nothing(
    script: Script, llm_env: str, kettle: SuiteAppliance
) -> None:
    env = _env(kettle)
    env.reset()
    boxes = panel_boxes(np.asarray(env.panel.latest.image))
    assert boxes
    script.router = lambda body: Reply(json.dumps({"action": "press", "box": len(boxes) + 5}))
    episode = run_llm_policy_image(_context(kettle), env)  # out of range: never touched
    assert not episode.claimed_success and env.panel.touches == 0
    assert "no valid choice" in (episode.failure or "")


def test_every_control_has_a_box(kettle: SuiteAppliance) -> None:
    env = _env(kettle)
    env.reset()
    temp = _box_on(env, "temp_button")
    boxes = panel_boxes(np.asarray(env.panel.latest.image))
    feedback = env.touch([centre(boxes[temp - 1])], "press")
    assert env.steps == 1 and env.panel.touches == 1
    assert feedback.text == env.simulator.observe().display
    for control in ("warm_button", "start_button"):
        _box_on(env, control)


def test_a_text_only_server_is_refused_clearly(
    script: Script, llm_env: str, kettle: SuiteAppliance
) -> None:
    script.router = lambda body: Reply(status=400, error="this model does not support image input")
    env = _env(kettle)
    with pytest.raises(NoVision, match="reads images"):
        run_llm_policy_image(_context(kettle), env)


def test_the_local_model_is_refused_before_asking(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, kettle: SuiteAppliance
) -> None:
    monkeypatch.setenv("APBOT_LLM", "local")
    monkeypatch.setenv("APBOT_LLM_CACHE_DIR", str(tmp_path / "cache"))
    with pytest.raises(NoVision, match="text-only"):
        run_llm_policy_image(_context(kettle), _env(kettle))


def test_display_mode_is_refused(kettle: SuiteAppliance) -> None:
    from apbot.agent.environment import SimulatorEnvironment

    with pytest.raises(NoVision, match="--feedback image"):
        run_llm_policy_image(_context(kettle), SimulatorEnvironment(kettle.model, "display"))
