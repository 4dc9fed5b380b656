"""Image mode for the benchmark: one rendered panel per appliance, grounded once per process.

The camera of an appliance is drawn from its id and the run's seed (``mild`` variations), so
a run is reproducible; the grounding of a set of action names on that camera's first photo
is computed once and reused for every task of the appliance in the same process, and kept
on disk (:mod:`apbot.vision.cache`) for the next process and the next run.
"""

from __future__ import annotations

import zlib
from collections.abc import Sequence

from apbot.vision.cache import cached_ground
from apbot.vision.environment import ImageEnvironment, PanelEnvironment
from apbot.vision.ground import Grounding
from apbot.vision.photo import Camera
from apbot.vision.render import PanelScene, SuiteAppliance

LEVEL = "mild"
_SCENES: dict[str, PanelScene] = {}
_GROUNDINGS: dict[tuple[str, tuple[str, ...], int], Grounding] = {}


def camera_for(appliance_id: str, seed: int = 0, level: str = LEVEL) -> Camera:
    """The (reproducible) camera in front of one appliance in a run with ``seed``."""
    return Camera.sample(zlib.crc32(f"{appliance_id}/{seed}".encode()), level)


def image_environment(appliance: SuiteAppliance, actions: Sequence[str], seed: int = 0
                      ) -> ImageEnvironment:  # fmt: skip
    """An :class:`ImageEnvironment` for ``appliance`` whose ``actions`` are grounded (cached)."""
    scene = _SCENES.get(appliance.id)
    if scene is None:
        scene = _SCENES[appliance.id] = PanelScene.of(appliance)
    panel = PanelEnvironment(appliance, camera_for(appliance.id, seed), scene)
    key = (appliance.id, tuple(actions), seed)
    env = ImageEnvironment(panel, actions, _GROUNDINGS.get(key), cached_ground)
    _GROUNDINGS[key] = env.grounding
    return env
