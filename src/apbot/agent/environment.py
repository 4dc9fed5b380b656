"""What an agent can touch: an appliance behind a small protocol.

The agent never sees the ground truth. It may press actions by name and read the feedback the
appliance gives back: the display text and, when the environment reports them, the values it
shows under the environment's own variable names (state estimation maps those onto the belief
model's names). Anything with ``actions``, ``reset`` and ``step`` is an environment; see
``apbot.agent.wrappers`` for wrapping a third-party simulator in a few lines.

>>> from apbot.examples import load_example
>>> env = SimulatorEnvironment(load_example("washing_machine"))
>>> env.step("press_power").text
'HELLO'
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

from apbot.model.schema import ApplianceModel
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Simulator


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


class SimulatorEnvironment:
    """A ground-truth simulator seen only through feedback: the benchmark's environment.

    The benchmark keeps ``simulator`` to judge the final state; agents get this object and
    must use only :class:`Environment`'s methods.
    """

    def __init__(self, model: ApplianceModel | Simulator) -> None:
        self.simulator = model if isinstance(model, Simulator) else Simulator(compiled_model(model))
        self.steps = 0

    @property
    def actions(self) -> Sequence[str]:
        return self.simulator.actions

    def reset(self) -> Feedback:
        self.steps = 0
        return _feedback(self.simulator.reset())

    def step(self, action: str, seconds: float | None = None) -> Feedback:
        self.steps += 1
        return _feedback(self.simulator.step(action, seconds))


def _feedback(observation: Any) -> Feedback:
    # the simulator's reason for a refusal names true values ("child_lock is on"): an agent
    # must learn that from the display, so only the fact of the refusal is passed on
    return Feedback(
        observation.display,
        dict(observation.values),
        observation.accepted,
        "" if observation.accepted else "refused",
    )
