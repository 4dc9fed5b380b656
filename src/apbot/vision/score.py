"""Scoring grounding against a layout (the judge's side: it may use the true boxes).

A grounded action is right when the centre of each of its boxes, mapped back to layout
units, lies inside the true box of the control the action uses (both, in order, for a
two-control hold) and its skill is the action's skill. Precision counts over the actions
grounded, recall over all actions that touch a control (waits are not grounded).
"""

from __future__ import annotations

from dataclasses import dataclass

from apbot.model.schema import ApplianceModel
from apbot.vision.ground import Grounding
from apbot.vision.render import PanelLayout, Photo

SKILL_OF = {"press": "press", "hold": "hold", "turn_cw": "turn_cw", "turn_ccw": "turn_ccw"}


@dataclass
class Tally:
    """Counts behind precision and recall."""

    right: int = 0
    grounded: int = 0
    total: int = 0

    def add(self, other: Tally) -> None:
        self.right += other.right
        self.grounded += other.grounded
        self.total += other.total

    @property
    def precision(self) -> float:
        return self.right / self.grounded if self.grounded else 0.0

    @property
    def recall(self) -> float:
        return self.right / self.total if self.total else 0.0

    @property
    def f1(self) -> float:
        p, r = self.precision, self.recall
        return 2 * p * r / (p + r) if p + r else 0.0

    def as_dict(self) -> dict[str, float | int]:
        return {
            "precision": round(self.precision, 4),
            "recall": round(self.recall, 4),
            "f1": round(self.f1, 4),
            "right": self.right,
            "grounded": self.grounded,
            "total": self.total,
        }


def score_grounding(
    grounding: Grounding, model: ApplianceModel, layout: PanelLayout, photo: Photo
) -> tuple[Tally, list[str]]:
    """The tally of one panel and a line per wrong or missing action."""
    boxes = {c.id: c.box for c in layout.controls}
    tally = Tally()
    wrong: list[str] = []
    for name, action in model.actions.items():
        if action.skill == "wait":
            continue
        tally.total += 1
        found = grounding.actions.get(name)
        if found is None:
            wrong.append(f"{name}: not grounded ({grounding.ungrounded.get(name, '?')})")
            continue
        tally.grounded += 1
        controls = [action.control] if action.control else list(action.controls or [])
        ok = found.skill == SKILL_OF.get(action.skill, action.skill) and len(found.points) == len(
            controls
        )
        if ok:
            for point, control in zip(found.points, controls, strict=True):
                x, y = photo.layout_point(*point)
                x0, y0, x1, y1 = boxes[control]
                ok = ok and x0 <= x <= x1 and y0 <= y <= y1
        if ok:
            tally.right += 1
        else:
            wrong.append(f"{name}: {found.skill} at {found.label!r}")
    return tally, wrong
