"""The core of every belief repair: a model as editable data, and back to a validated model.

Split from :mod:`apbot.agent.repair` so that the modules of repairs (that one,
:mod:`apbot.agent.added_settings`) share it without importing each other; the repair module
re-exports :class:`RepairError`, so ``from apbot.agent.repair import RepairError`` keeps working.
"""

from __future__ import annotations

from typing import Any

from pydantic import ValidationError

from apbot.model.schema import ApplianceModel
from apbot.model.validate import check_model


class RepairError(ValueError):
    """The repaired model would not be valid; the message says why."""


def _rebuild(data: dict[str, Any], checked: bool = True) -> ApplianceModel:
    """The model of ``data``; ``checked=False``: the schema only, not the model's checks."""
    try:
        model = ApplianceModel.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        raise RepairError(f"{'.'.join(str(p) for p in first['loc'])}: {first['msg']}") from None
    if not checked:
        return model
    errors = [p for p in check_model(model) if p.severity == "error"]
    if errors:
        raise RepairError(str(errors[0]))
    return model


def _dump(model: ApplianceModel) -> dict[str, Any]:
    return model.model_dump(mode="json", exclude_none=True)
