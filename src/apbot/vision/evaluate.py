"""``apbot ground``: grounding precision/recall/F1 and display-reading accuracy on a suite.

Grounding: every appliance's panel is rendered with seeded camera variations and grounded
from the photo and the true model's action names only; the layout's boxes judge the result
(:mod:`apbot.vision.score`). Display reading: states are reached by random presses, the
panel is photographed (seeded variations; dot matrix, and seven segments for the states
whose main text seven segments can show), the display read from the photo, and the reading
counts as right when
the belief's display reader gives the same values as for the true text (``5``/``S``-style
look-alikes are settled by the display rules, as the agent does); a text the reader cannot
parse counts as right only when it is the true text exactly.
"""

from __future__ import annotations

import random
import time
import zlib
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from apbot.agent.environment import Feedback
from apbot.agent.perception import Perceiver
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Observation, Simulator
from apbot.vision.display_art import visible
from apbot.vision.glyphs import seven_segment_ok
from apbot.vision.ground import ground
from apbot.vision.photo import Camera
from apbot.vision.reading import DisplayCamera
from apbot.vision.render import PanelScene, SuiteAppliance
from apbot.vision.score import Tally, score_grounding


@dataclass
class GroundReport:
    """Figures of one evaluation, with what went wrong."""

    overall: Tally = field(default_factory=Tally)
    categories: dict[str, Tally] = field(default_factory=dict)
    display_right: int = 0
    display_n: int = 0
    display_styles: dict[str, list[int]] = field(default_factory=dict)
    mistakes: list[str] = field(default_factory=list)
    ground_seconds: list[float] = field(default_factory=list)
    read_seconds: list[float] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        return {
            "grounding": {
                "overall": self.overall.as_dict(),
                "categories": {k: v.as_dict() for k, v in sorted(self.categories.items())},
            },
            "display": {
                "accuracy": round(self.display_right / self.display_n, 4)
                if self.display_n
                else 0.0,
                "n": self.display_n,
                "styles": {
                    k: {"accuracy": round(v[0] / v[1], 4) if v[1] else 0.0, "n": v[1]}
                    for k, v in sorted(self.display_styles.items())
                },
            },
            "timing": {
                "ground_seconds_mean": _mean(self.ground_seconds),
                "read_seconds_mean": _mean(self.read_seconds),
            },
        }


def _mean(values: list[float]) -> float:
    return round(float(np.mean(values)), 4) if values else 0.0


SEG_TRIES = 12
"""Random walks tried for a state a seven-segment display can show before giving up on it."""


def evaluate_grounding(
    appliances: Sequence[SuiteAppliance],
    variations: int = 2,
    level: str = "mild",
    report: GroundReport | None = None,
) -> GroundReport:
    """Ground each appliance on ``variations`` seeded photos and score it."""
    report = report or GroundReport()
    for appliance in appliances:
        scene = PanelScene.of(appliance)
        start = Simulator(compiled_model(appliance.model)).reset()
        for v in range(variations):
            seed = zlib.crc32(f"ground/{appliance.id}/{v}".encode())
            photo = scene.photograph(start.display, start.lamps, Camera.sample(seed, level))
            found = ground(np.asarray(photo.image), list(appliance.model.actions))
            report.ground_seconds.append(found.seconds)
            tally, wrong = score_grounding(found, appliance.model, appliance.layout, photo)
            report.overall.add(tally)
            report.categories.setdefault(appliance.model.appliance.category, Tally()).add(tally)
            report.mistakes += [f"{appliance.id} (camera {v}): {w}" for w in wrong]
    return report


def evaluate_display(
    appliances: Sequence[SuiteAppliance],
    per_appliance: int = 14,
    level: str = "mild",
    report: GroundReport | None = None,
) -> GroundReport:
    """Read ``per_appliance`` dot-matrix displays of each appliance from photos, and half as
    many seven-segment ones (states whose main text fits seven segments), one camera per
    appliance and style, as a robot would."""
    report = report or GroundReport()
    for appliance in appliances:
        perceiver = Perceiver(appliance.model)
        fresh = Simulator(compiled_model(appliance.model))
        fresh.reset()
        initial = {name: fresh.value(name) for name in appliance.model.variables}
        rng = random.Random(f"display/{appliance.id}")
        seg = PanelScene.of(appliance, style="seg", force=True)
        for style in ("dot", "seg"):
            scene = seg if style == "seg" else PanelScene.of(appliance, style="dot")
            camera = Camera.sample(zlib.crc32(f"display/{appliance.id}/{style}".encode()), level)
            reader = DisplayCamera()
            sim = Simulator(compiled_model(appliance.model))
            sim.reset()
            actions = list(sim.actions)
            count = per_appliance if style == "dot" else max(4, per_appliance // 2)
            for i in range(count):
                seen = _walk(sim, rng, actions, appliance)
                if style == "seg":  # only states a seven-segment display can show
                    for _ in range(SEG_TRIES):
                        if seven_segment_ok(visible(seen.display)):
                            break
                        seen = _walk(sim, rng, actions, appliance)
                    else:
                        continue
                photo = scene.photograph(seen.display, seen.lamps, camera, frame=i + 1)
                started = time.perf_counter()
                reading = reader.read(photo.image)
                report.read_seconds.append(time.perf_counter() - started)
                truth = visible(seen.text)
                ok = _same_reading(perceiver, truth, reading.text, reading.alternatives, initial)
                report.display_n += 1
                report.display_right += ok
                tally = report.display_styles.setdefault(style, [0, 0])
                tally[0] += ok
                tally[1] += 1
                if not ok:
                    report.mistakes.append(
                        f"{appliance.id} ({style}): {truth!r} read as {reading.text!r}"
                    )
    return report


def _walk(sim: Simulator, rng: random.Random, actions: list[str], appliance: SuiteAppliance
          ) -> Observation:  # fmt: skip
    """A few random actions on ``sim``; what the appliance shows after them."""
    for _ in range(rng.randint(1, 4)):
        name = rng.choice(actions)
        sim.step(name, appliance.model.actions[name].seconds)
    return sim.observe()


def _same_reading(
    perceiver: Perceiver,
    truth: str,
    text: str,
    alternatives: list[tuple[str, float]],
    context: dict[str, Any],
) -> bool:
    """Whether the photo's reading means what the true text means to the display reader
    (``context``: the appliance's initial values, a neutral prediction for both)."""
    if text == truth:
        return True
    true_seen = perceiver.perceive(Feedback(truth), context)
    if true_seen.unknown:
        return False
    seen = perceiver.perceive(Feedback(text, image=_Alternatives(alternatives)), context)
    return (
        not seen.unknown
        and seen.values == true_seen.values
        and seen.outside == true_seen.outside
        and seen.blank == true_seen.blank
    )


@dataclass
class _Alternatives:
    alternatives: list[tuple[str, float]]
