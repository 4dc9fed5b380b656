"""The hand-written example models shipped with the package."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from apbot.model.load import load_model
from apbot.model.schema import ApplianceModel


def example_dir() -> Path:
    """Where the example model files live inside the installed package."""
    return Path(str(resources.files("apbot") / "data" / "examples"))


def example_names() -> list[str]:
    """Names of the bundled example models."""
    return sorted(p.stem for p in example_dir().glob("*.yaml"))


def load_example(name: str) -> ApplianceModel:
    """Load a bundled example model by name (see :func:`example_names`)."""
    path = example_dir() / f"{name}.yaml"
    if not path.exists():
        raise FileNotFoundError(f"no example {name!r}; choose from {example_names()}")
    return load_model(path)
