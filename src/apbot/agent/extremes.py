"""An end of a range asked for in words ("the hottest setting", "as dark as it goes"): the
goal reader must have placed it as the first or last value of some setting, or it is unread.

A superlative says which value, without a figure: the user wants an end of a setting's range.
When no setting of the goal as read stands at an end of its range (a switch's on or off
aside: every switch stands at an end), that end was not placed, and a claim of success would
say the user's request was done when only the rest of it was (:mod:`apbot.agent.unread`).
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

from apbot.model.domain import ValueProblem, all_values, normalise
from apbot.model.key_roles import is_switch
from apbot.model.schema import ApplianceModel
from apbot.read.number_tokens import tokenize
from apbot.read.numbers import find_mentions

# a superlative after "the" or a possessive ("the hottest", "its quietest"), or "as X as it
# goes / can / will go"; "-est" words of six letters or more (not "best", "rest", "least")
_EXTREME = re.compile(
    r"\b(?:the|its|their|your|my)\s+(?P<word>[a-z]{3,}est)\b"
    r"|\bas\s+(?P<degree>[a-z]+)\s+as\s+(?:it|that|the\s+\w+|\w+)\s+(?:\w+\s+)?(?:goes|go|can)\b",
    re.IGNORECASE,
)
_FIGURE = re.compile(r"-?\d+(?:\.\d+)?")
_NOT_SUPERLATIVE = frozenset(
    {"interest", "request", "harvest", "forest", "honest", "modest", "digest", "contest"}
)


def unmet_extremes(belief: ApplianceModel, instruction: str, goal: Mapping[str, Any]) -> list[str]:
    """The superlatives of ``instruction`` that no goal setting at an end of its range
    answers (empty when one does, or when the user asked for none)."""
    asked = [
        m.group(0)
        for m in _EXTREME.finditer(instruction)
        if (m.group("word") or "").casefold() not in _NOT_SUPERLATIVE
        and not _beside_a_figure(instruction[: m.start()])
    ]
    if not asked or any(_at_an_end(belief, name, value) for name, value in goal.items()):
        return []
    return asked


def _beside_a_figure(before: str) -> bool:
    """The superlative stands after a comma that ends a figure's clause ("an hour, the longest
    it allows"): it describes the figure said, which the number check answers for."""
    head, comma, _ = before.rstrip().rpartition(",")
    if not comma or before[len(head) + 1 :].strip():
        return False
    clause = re.split(r"[,.;:!?]", head)[-1]
    return bool(find_mentions(tokenize(clause)))


def _at_an_end(belief: ApplianceModel, name: str, value: Any) -> bool:
    """``value`` is the first or the last value of ``name``'s list (a switch has none). A
    menu's first or last choice counts too: read ranges are often wider or narrower than the
    appliance's, so the check errs towards believing the goal reader placed the end."""
    spec = belief.variables.get(name)
    if spec is None or is_switch(belief, name):
        return False
    try:
        values = list(all_values(spec))
        wanted = normalise(spec, value)
    except (ValueProblem, ValueError, TypeError):
        return False
    figures = [v for v in values if _FIGURE.fullmatch(str(v).strip())]
    if len(figures) >= 2 and wanted in figures:
        values = figures  # "the driest numbered setting": 5 of off, 1-5, continuous
    return bool(values) and wanted in (values[0], values[-1])
