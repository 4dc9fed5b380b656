"""Benchmark suites: appliances with a manual, a ground-truth model, a panel layout and tasks.

A suite is a directory with one sub-directory per appliance::

    <suite>/<appliance-id>/manual.md     (or manual.txt: text extracted from a PDF)
    <suite>/<appliance-id>/model.yaml    the ground truth, in the model format
    <suite>/<appliance-id>/panel.yaml    controls and display on a panel canvas
    <suite>/<appliance-id>/tasks.yaml    instructions, goals, optimal action counts

The bundled suite ships inside the package (``apbot/data/suite``) so ``pip install`` brings it.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from apbot.model.load import parse_model, read_yaml, schema_problems
from apbot.model.problems import ModelError, Problem
from apbot.model.schema import IDENT, ApplianceModel, Box, Scalar

# Goal variables per task, by category: the paper's six, then our three.
GOAL_VARIABLES: dict[str, int] = {
    "dehumidifier": 1,
    "bottle_washer": 2,
    "rice_cooker": 3,
    "microwave": 4,
    "bread_maker": 5,
    "washing_machine": 6,
    "kettle": 2,
    "induction_cooker": 3,
    "air_fryer": 4,
}
CATEGORIES = tuple(GOAL_VARIABLES)


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class PanelControl(_Strict):
    """A control as drawn on the panel: its printed label and where it is."""

    id: str = Field(pattern=IDENT)
    label: str
    box: Box
    shape: Literal["rect", "round", "key", "knob", "slider", "icon"] = "rect"


class PanelLayout(_Strict):
    """The panel canvas (pixels), its display region, and every control."""

    canvas: tuple[int, int]
    display: Box
    controls: list[PanelControl] = Field(min_length=1)
    colour: str = "#d9d9d9"


class Task(_Strict):
    """One instruction and the goal (variables and values) that defines success."""

    id: str = Field(pattern=r"^[a-z0-9_]+$")
    instruction: str = Field(min_length=8)
    goal: dict[str, Scalar] = Field(min_length=1)
    optimal_steps: int | None = Field(default=None, ge=0)
    allow: dict[str, str] = Field(default_factory=dict)
    """Findings of ``apbot.bench.goal_checks`` this task accepts, each with the reason."""


class TaskFile(_Strict):
    appliance: str
    tasks: list[Task] = Field(min_length=1)


@dataclass
class SuiteAppliance:
    """Everything the benchmark knows about one appliance."""

    id: str
    category: str
    directory: Path
    manual: str
    model: ApplianceModel
    layout: PanelLayout
    tasks: list[Task]
    manual_file: str = "manual.md"

    @property
    def manual_words(self) -> int:
        return len(self.manual.split())


@dataclass
class Suite:
    name: str
    directory: Path
    appliances: list[SuiteAppliance] = field(default_factory=list)
    seconds: float = 0.0

    def get(self, appliance_id: str) -> SuiteAppliance:
        for appliance in self.appliances:
            if appliance.id == appliance_id:
                return appliance
        from apbot.model.values import closest_matches

        close = closest_matches(appliance_id, [a.id for a in self.appliances], limit=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        raise KeyError(f"no appliance {appliance_id!r} in suite {self.name!r}{hint}")

    @property
    def tasks(self) -> list[tuple[SuiteAppliance, Task]]:
        return [(a, t) for a in self.appliances for t in a.tasks]


def bundled_suite_dir() -> Path:
    """Where the bundled suite lives inside the installed package."""
    return Path(str(resources.files("apbot") / "data" / "suite"))


def _load_yaml_model(path: Path, schema: type[BaseModel], source: str) -> BaseModel:
    text = path.read_text(encoding="utf-8")
    try:
        return schema.model_validate(read_yaml(text, source))
    except ValidationError as exc:
        raise ModelError(schema_problems(exc, text), source) from None


def load_appliance(directory: Path, check: bool = False) -> SuiteAppliance:
    """Load one appliance directory; ``check`` also runs the model's semantic checks."""
    manual_path = next(
        (directory / name for name in ("manual.md", "manual.txt") if (directory / name).exists()),
        None,
    )
    missing = [
        name
        for name in ("model.yaml", "panel.yaml", "tasks.yaml")
        if not (directory / name).exists()
    ]
    if manual_path is None:
        missing.insert(0, "manual.md (or manual.txt)")
    if missing:
        raise ModelError(
            [Problem((), f"missing {name}", "suite") for name in missing], str(directory)
        )
    model_path = directory / "model.yaml"
    text = model_path.read_text(encoding="utf-8")
    model = parse_model(read_yaml(text, str(model_path)), str(model_path), text, check=check)
    layout = _load_yaml_model(directory / "panel.yaml", PanelLayout, str(directory / "panel.yaml"))
    task_file = _load_yaml_model(directory / "tasks.yaml", TaskFile, str(directory / "tasks.yaml"))
    assert isinstance(layout, PanelLayout) and isinstance(task_file, TaskFile)
    return SuiteAppliance(
        model.appliance.id,
        model.appliance.category,
        directory,
        manual_path.read_text(encoding="utf-8"),
        model,
        layout,
        list(task_file.tasks),
        manual_path.name,
    )


def load_suite(name: str | Path = "bundled", check: bool = False) -> Suite:
    """Load a suite: ``"bundled"`` (shipped with apbot) or a directory in the suite format.

    The bundled suite's models are checked by the test suite, so they load unchecked by
    default; pass ``check=True`` to run every semantic check anyway.
    """
    started = time.perf_counter()
    directory = bundled_suite_dir() if str(name) == "bundled" else Path(name)
    if not directory.is_dir():
        raise FileNotFoundError(f"suite directory {directory} does not exist")
    suite = Suite(str(name), directory)
    for child in sorted(p for p in directory.iterdir() if (p / "model.yaml").exists()):
        suite.appliances.append(load_appliance(child, check=check))
    suite.seconds = time.perf_counter() - started
    return suite
