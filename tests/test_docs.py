"""The examples in docs/model-format.md run as written (they are doctests)."""

from __future__ import annotations

import doctest
from pathlib import Path

DOCS = Path(__file__).resolve().parents[1] / "docs"


def test_the_model_format_examples_run() -> None:
    result = doctest.testfile(
        str(DOCS / "model-format.md"),
        module_relative=False,
        verbose=False,
        optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE,
    )
    assert result.attempted >= 10 and result.failed == 0
