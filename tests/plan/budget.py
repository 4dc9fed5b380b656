"""How hard the planner's property tests try: a CI-sized budget by default (a few seconds each),
a long one on request, run once before a release or after touching ``apbot.plan``::

    APBOT_PROPERTY_BUDGET=long pytest tests/plan -q -p no:randomly --hypothesis-show-statistics
"""

from __future__ import annotations

import os

LONG = os.environ.get("APBOT_PROPERTY_BUDGET", "ci") == "long"

# (hypothesis examples, most states a generated model may have)
OPTIMALITY = (1_500, 30_000) if LONG else (100, 5_000)
BOUND = (1_500, 30_000) if LONG else (150, 3_000)


def states_bucket(count: int) -> str:
    """A hypothesis event naming the size class of a case, so statistics show the spread."""
    for limit in (10, 100, 1_000, 10_000):
        if count < limit:
            return f"reachable states < {limit:,}"
    return "reachable states >= 10,000"
