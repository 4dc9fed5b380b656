"""Image mode: the appliance as a panel that is touched at points and answers with photos.

:class:`PanelEnvironment` is the world: it takes a point (or box) and a skill — press, hold
for some seconds, turn clockwise or anticlockwise, a two-finger hold — finds which control
(if any) is under each point, performs the matching action on the true simulator, and
returns a photo of the panel afterwards. A point on no control, or a skill the control does
not answer to, does nothing, as on a real panel.

:class:`ImageEnvironment` is the robot in front of it, behind the agent's
:class:`~apbot.agent.environment.Environment` protocol: it grounds the belief's action names
once on a first photo, presses at the grounded points, and reads the display from every
returned photo. The agent runs unchanged; grounding and reading mistakes cost what they
would cost on a real appliance (a wrong key pressed, a wrong text read).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from apbot.agent.environment import Feedback
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Observation, Simulator
from apbot.vision.ground import Grounding, ground
from apbot.vision.photo import Camera
from apbot.vision.reading import DisplayCamera, ImageReading
from apbot.vision.render import PanelScene, Photo, SuiteAppliance

SHORT_PRESS = 0.3
"""Seconds a plain press lasts (a press on a hold-only key is a too-short hold)."""


@dataclass
class Touch:
    """What one touch did: the controls under the points, the action performed (if any)."""

    controls: tuple[str, ...]
    action: str | None
    photo: Photo
    observation: Observation | None


class PanelEnvironment:
    """A rendered appliance panel that reacts to touches at image points."""

    def __init__(self, appliance: SuiteAppliance, camera: Camera | None = None,
                 scene: PanelScene | None = None) -> None:  # fmt: skip
        self.appliance = appliance
        self.scene = scene or PanelScene.of(appliance)
        self.camera = camera or Camera()
        self.simulator = Simulator(compiled_model(appliance.model))
        self.frame = 0
        self.touches = 0
        self._last: Observation = self.simulator.reset()
        self._reference: Photo = self.photo()
        self._by_touch: dict[tuple[frozenset[str], str], list[tuple[str, float]]] = {}
        self._waits: list[tuple[str, float]] = []
        for name, action in appliance.model.actions.items():
            if action.skill == "wait":
                self._waits.append((name, action.seconds or 0.0))
                continue
            controls = frozenset([action.control] if action.control else action.controls or [])
            key = (controls, action.skill)
            self._by_touch.setdefault(key, []).append((name, action.seconds or 0.0))

    def reset(self) -> Photo:
        self._last = self.simulator.reset()
        self.frame = 0
        self.touches = 0
        return self.photo()

    def photo(self) -> Photo:
        """A photo of the panel as it is now (each call a new frame: new sensor noise)."""
        self.frame += 1
        photo = self.scene.photograph(self._last.display, self._last.lamps, self.camera,
                                      self.frame)  # fmt: skip
        self._reference = photo
        return photo

    @property
    def latest(self) -> Photo:
        """The latest photo of the panel (the one touches are aimed at)."""
        return self._reference

    def control_at(self, x: float, y: float, photo: Photo) -> str | None:
        """The control under photo pixel (x, y), if any."""
        lx, ly = photo.layout_point(x, y)
        for control in self.scene.layout.controls:
            x0, y0, x1, y1 = control.box
            if x0 <= lx <= x1 and y0 <= ly <= y1:
                return control.id
        return None

    def touch(self, points: Sequence[tuple[float, float]], skill: str,
              seconds: float | None = None) -> Touch:  # fmt: skip
        """Touch the panel at ``points`` (pixels of the latest photo) with ``skill``:
        ``press``, ``hold`` (``seconds``), ``turn_cw``, ``turn_ccw``, or ``wait``."""
        self.touches += 1
        reference = self._reference
        if skill == "wait":
            action = _closest(self._waits, seconds)
            observation = self.simulator.step(action, seconds) if action else None
            if observation is not None:
                self._last = observation
            return Touch((), action, self.photo(), observation)
        controls = tuple(c for p in points if (c := self.control_at(*p, reference)) is not None)
        action, how_long = self._action_for(controls, skill, seconds)
        observation = None
        if action is not None and len(controls) == len(points):
            observation = self.simulator.step(action, how_long)
            self._last = observation
        return Touch(controls, action, self.photo(), observation)

    def _action_for(self, controls: tuple[str, ...], skill: str, seconds: float | None
                    ) -> tuple[str | None, float | None]:  # fmt: skip
        if not controls:
            return None, None
        key = frozenset(controls)
        if skill == "hold":
            holds = self._by_touch.get((key, "hold"), [])
            if holds:
                return _closest(holds, seconds), seconds
            presses = self._by_touch.get((key, "press"), [])  # a long press is still a press
            return (presses[0][0] if presses else None), None
        if skill == "press":
            presses = self._by_touch.get((key, "press"), [])
            if presses:
                return presses[0][0], None
            holds = self._by_touch.get((key, "hold"), [])  # too short a hold
            return (holds[0][0] if holds else None), SHORT_PRESS
        found = self._by_touch.get((key, skill), [])
        return (found[0][0] if found else None), None


def _closest(options: list[tuple[str, float]], seconds: float | None) -> str | None:
    """The action whose duration is the longest one not above ``seconds``."""
    if not options:
        return None
    if seconds is None:
        return options[0][0]
    fitting = [o for o in options if o[1] <= seconds + 1e-9]
    return max(fitting, key=lambda o: o[1])[0] if fitting else min(options, key=lambda o: o[1])[0]


class ImageEnvironment:
    """The agent's environment in image mode: actions by name, feedback read from photos.

    ``actions`` are the belief's action names; each is performed at the box grounding gave
    it on the first photo. An action that could not be grounded touches nothing (the step
    is spent, the panel is unchanged). ``simulator`` and ``steps`` are for the benchmark's
    judge, as with :class:`~apbot.agent.environment.SimulatorEnvironment`.
    """

    def __init__(self, panel: PanelEnvironment, actions: Sequence[str],
                 grounding: Grounding | None = None,
                 grounder: Callable[[np.ndarray, Sequence[str]], Grounding] = ground
                 ) -> None:  # fmt: skip
        self.panel = panel
        self._actions = tuple(actions)
        first = panel.reset()
        self.grounding = grounding or grounder(np.asarray(first.image), self._actions)
        self.display = DisplayCamera(self.grounding.window)
        self.steps = 0

    @property
    def simulator(self) -> Simulator:
        return self.panel.simulator

    @property
    def actions(self) -> Sequence[str]:
        return self._actions

    def reset(self) -> Feedback:
        self.steps = 0
        return self._feedback(Touch((), None, self.panel.reset(), None))

    def step(self, action: str, seconds: float | None = None) -> Feedback:
        if action not in self._actions:
            raise KeyError(f"unknown action {action!r}")
        self.steps += 1
        grounded = self.grounding.actions.get(action)
        if grounded is None:
            if action in self.grounding.ungrounded and "wait" in self.grounding.ungrounded[action]:
                return self._feedback(self.panel.touch([], "wait", seconds))
            self.panel.touches += 1
            return self._feedback(Touch((), None, self.panel.photo(), None))
        return self._feedback(self.panel.touch(grounded.points, grounded.skill, seconds))

    def touch(self, points: Sequence[tuple[float, float]], skill: str,
              seconds: float | None = None) -> Feedback:  # fmt: skip
        """One step that touches photo points directly (a method that picks boxes itself,
        not action names): the step is counted and the new photo read."""
        self.steps += 1
        return self._feedback(self.panel.touch(points, skill, seconds))

    def _feedback(self, touch: Touch) -> Feedback:
        reading = self.display.read(touch.photo.image)
        seen = touch.observation
        beep = seen is not None and not seen.accepted and seen.perceptible  # heard, not seen
        return Feedback(reading.text, {}, not beep, "beep" if beep else "", reading)


def reading_of(feedback: Feedback) -> ImageReading | None:
    """The display reading carried by an image-mode feedback, if any."""
    return feedback.image if isinstance(feedback.image, ImageReading) else None
