"""Whether a key's role in a model can be the one a user's value is for.

A reader can attach a key to the wrong setting (DEFROST read as an on/off switch where the
panel steps a weight with it). When the user names the key and says a value that none of the
settings the key adjusts could hold — a weight for a switch, a number for a list of words, a
word that is none of its values, a quantity of another kind — the role is likely the reader's
mistake: the goal parser keeps the value as an open entry, and the agent's variable finder
walks the key (``apbot.read.goal_open``, ``apbot.agent.discovery``).
"""

from __future__ import annotations

from typing import Any

from apbot.model.domain import ValueProblem, all_values, normalise, parse_value
from apbot.model.schema import ApplianceModel, DiscreteVariable


def adjusted_by(model: ApplianceModel, key: str) -> set[str]:
    """The variables the steps with ``key`` adjust."""
    return {
        step.variable
        for steps in model.features.values()
        for step in steps
        if key in step.actions and step.variable is not None
    }


def takes(model: ApplianceModel, variable: str, value: Any) -> bool:
    """A value of the variable's kind: one of its words for a list, a number or a time of its
    unit for the others (whether or not its range reaches it)."""
    spec = model.variables.get(variable)
    if spec is None:
        return False
    try:
        if isinstance(spec, DiscreteVariable):
            normalise(spec, value)
        else:
            parse_value(spec, value)
    except (ValueProblem, ValueError, TypeError):
        return False
    return True


def misread_key(model: ApplianceModel, key: str, value: Any) -> bool:
    """The key adjusts settings, none of which could hold ``value``; False for a key that
    adjusts nothing (a plain step, no role: the finder tries those anyway)."""
    adjusted = adjusted_by(model, key)
    return bool(adjusted) and not any(takes(model, name, value) for name in adjusted)


def is_switch(model: ApplianceModel, variable: str) -> bool:
    """A list of ``off`` and ``on`` only: a switch, which a key is read to toggle."""
    spec = model.variables.get(variable)
    return isinstance(spec, DiscreteVariable) and {str(v) for v in all_values(spec)} <= {
        "off",
        "on",
    }
