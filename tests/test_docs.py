"""Every ``>>>`` example in docs/*.md runs as written (doctest), like the README's blocks.

The model-format reference shows each construct with a small model and what the simulator
and the planner do with it; a doc example that drifted from the code fails here.
"""

from __future__ import annotations

import doctest
from pathlib import Path

import pytest

DOCS = sorted((Path(__file__).resolve().parents[1] / "docs").glob("*.md"))


@pytest.mark.parametrize("path", DOCS, ids=[p.name for p in DOCS])
def test_doc_examples_run(path: Path) -> None:
    result = doctest.testfile(
        str(path),
        module_relative=False,
        optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE,
        verbose=False,
        report=True,
    )
    assert result.failed == 0, f"{path.name}: {result.failed} of {result.attempted} examples fail"


def test_the_format_reference_has_examples() -> None:
    text = (Path(__file__).resolve().parents[1] / "docs" / "model-format.md").read_text()
    assert text.count(">>> ") >= 25
