"""What an agent can touch: an appliance behind a small protocol.

The agent never sees the ground truth. It may press actions by name and read the feedback the
appliance gives back: the display text and, when the environment reports them, the values it
shows under the environment's own variable names (state estimation maps those onto the belief
model's names). Anything with ``actions``, ``reset`` and ``step`` is an environment; see
``apbot.agent.wrappers`` for wrapping a third-party simulator in a few lines.

>>> from apbot.examples import load_example
>>> env = SimulatorEnvironment(load_example("washing_machine"))
>>> env.step("press_power").text  # the main display, then the lit lamps
'HELLO  PAUSED'
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Literal, Protocol, runtime_checkable

from apbot.model.schema import ApplianceModel
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Observation, Simulator


@dataclass(slots=True)
class Feedback:
    """What the appliance shows after an action.

    ``values`` maps the environment's own variable names to the values it reports (raw: they
    are normalised against the belief model by state estimation). ``accepted`` is False when
    the appliance visibly refused the action (a beep, "LOCKED"); ``reason`` says why when the
    environment knows. ``image`` is reserved for a photo of the display.
    """

    text: str = ""
    values: dict[str, Any] = field(default_factory=dict)
    accepted: bool = True
    reason: str = ""
    image: Any = None


@runtime_checkable
class Environment(Protocol):
    """An appliance an agent can operate: the protocol every method runs against."""

    @property
    def actions(self) -> Sequence[str]:
        """The names of the actions the agent may perform."""
        ...

    def reset(self) -> Feedback:
        """Back to the start of an episode; what the appliance shows then."""
        ...

    def step(self, action: str, seconds: float | None = None) -> Feedback:
        """Perform one physical action (``seconds``: how long a hold lasts)."""
        ...


FeedbackMode = Literal["display", "values", "image"]
FEEDBACK_MODES: tuple[FeedbackMode, ...] = ("display", "values", "image")
"""``image`` is served by ``apbot.vision.environment.ImageEnvironment`` (a panel photo per
action), not by :class:`SimulatorEnvironment`."""


class SimulatorEnvironment:
    """A ground-truth simulator seen only through feedback: the benchmark's environment.

    ``feedback`` says what the agent gets after each action (:func:`panel_feedback`):
    ``display`` (the default) is what a robot in front of the panel has; ``values`` adds what
    the paper's simulator reports. The benchmark keeps ``simulator`` to judge the final state;
    agents get this object and must use only :class:`Environment`'s methods.
    """

    def __init__(
        self, model: ApplianceModel | Simulator, feedback: FeedbackMode = "display"
    ) -> None:
        if feedback not in FEEDBACK_MODES:
            raise ValueError(
                f"unknown feedback mode {feedback!r}; choose one of {', '.join(FEEDBACK_MODES)}"
            )
        if feedback == "image":
            raise ValueError(
                "image feedback needs a panel: use apbot.vision.environment.ImageEnvironment"
            )
        self.simulator = model if isinstance(model, Simulator) else Simulator(compiled_model(model))
        self.feedback = feedback
        self.steps = 0

    @property
    def actions(self) -> Sequence[str]:
        return self.simulator.actions

    def reset(self) -> Feedback:
        self.steps = 0
        return panel_feedback(self.simulator.reset(), self.feedback)

    def step(self, action: str, seconds: float | None = None) -> Feedback:
        self.steps += 1
        return panel_feedback(self.simulator.step(action, seconds), self.feedback)


def panel_feedback(observation: Observation, mode: FeedbackMode = "display") -> Feedback:
    """What a simulated appliance may reveal to an agent: the one rule every adapter follows.

    * ``display``: the panel's text (main display and lit lamps), and a refusal only where the
      appliance makes one perceptible (a beep, a message: ``Guard.signal``,
      ``Display.ignored``). A key ignored without a sign is indistinguishable from one that
      changed nothing.
    * ``values``: as the paper's simulator — also the shown variables by name, and every
      refusal, silent or not.

    Never the simulator's reason for a refusal: it names true values ("child_lock is on"),
    which an agent must learn from the display.
    """
    if mode == "values":
        return Feedback(
            observation.text,
            dict(observation.values),
            observation.accepted,
            "" if observation.accepted else "refused",
        )
    refused = not observation.accepted and observation.perceptible
    return Feedback(observation.text, {}, not refused, "beep" if refused else "")
