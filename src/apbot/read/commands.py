"""Helpers behind ``apbot read`` and ``apbot eval-reader``: action lists in, tables out."""

from __future__ import annotations

from pathlib import Path

import yaml

from apbot.model.yaml_text import read_text
from apbot.read.errors import ReaderError
from apbot.read.evaluate import SuiteScore

COLUMNS = ("variables", "discrete_values", "numeric_ranges", "placements", "features")


def action_names(path: Path) -> list[str]:
    """Action names from a file: one a line, a YAML/JSON list, or a model's ``actions`` map."""
    text = read_text(path)
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError:
        data = None
    if isinstance(data, dict) and isinstance(data.get("actions"), dict | list):
        data = data["actions"]
    if isinstance(data, dict):
        return [str(k) for k in data]
    if isinstance(data, list):
        return [str(x) for x in data]
    names = [
        line.strip() for line in text.splitlines() if line.strip() and not line.startswith("#")
    ]
    if not names:
        raise ReaderError(f"{path}: no action names found")
    return names


def score_table(result: SuiteScore) -> str:
    """Plain-text P/R table: one row per category and one overall."""
    head = f"{'category':<18}" + "".join(f"{c:>18}" for c in COLUMNS)
    lines = [head, f"{'':<18}" + "".join(f"{'P    R':>18}" for _ in COLUMNS)]
    rows = [*sorted(result.per_category.items()), ("overall", result.overall)]
    for name, score in rows:
        table = score.table()
        cells = "".join(
            f"{table[c]['precision']:>12.2f}{table[c]['recall']:>6.2f}" for c in COLUMNS
        )
        lines.append(f"{name:<18}{cells}")
    lines.append(
        f"{result.appliances} manuals read in {result.seconds:.2f} s "
        f"({1000 * result.seconds / max(1, result.appliances):.0f} ms each)"
    )
    return "\n".join(lines)
