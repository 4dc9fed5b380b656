"""The order a compiled model numbers its actions in: the model's own, not the caller's listing.

Where a search meets equally good choices it takes the one it generated first, and that follows
the actions' numbers. A robot's grounding lists the controls in whatever order it finds them, so
that listing must not decide: actions are numbered by the first procedure that uses them (a
feature's steps, then the steps reachable from anywhere: the order the model — a read model the
manual — describes them in), then by name.
"""

from __future__ import annotations

from apbot.model.schema import ApplianceModel


def action_order(model: ApplianceModel) -> list[str]:
    """The model's action names: by the first procedure that uses them, then by name."""
    first: dict[str, int] = {}
    procedures = [step.actions for feature in model.features.values() for step in feature]
    procedures += [anywhere.actions for anywhere in model.anywhere]
    for place, actions in enumerate(procedures):
        for name in actions:
            first.setdefault(name, place)
    last = len(procedures)
    return sorted(model.actions, key=lambda name: (first.get(name, last), name))
