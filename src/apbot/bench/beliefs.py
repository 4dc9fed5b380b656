"""The model a method works from in a benchmark run: the truth, a seeded faulty copy, or a reading.

A run's belief is one string (stored in every record and in ``run.json``):

- ``"true"`` — the ground-truth model, no faults;
- ``"faulty:RATE"`` — the ground truth with faults injected at ``RATE`` (0 ≤ RATE ≤ 1), seeded by
  the run's seed and the appliance id, so every process builds the same faulty model;
- ``"read"`` — a model read from the manual (not available yet: the reader lands later).

The string is parsed once up front (:func:`parse_belief`) so a typo stops the run before any work.

>>> parse_belief("faulty:0.30")
BeliefSpec(kind='faulty', rate=0.3)
>>> str(parse_belief("faulty:0.30")), str(parse_belief("true"))
('faulty:0.3', 'true')
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from apbot.bench.suite import SuiteAppliance
from apbot.model.schema import ApplianceModel

ACCEPTED_FORMS = "'true' or 'faulty:RATE' with 0 ≤ RATE ≤ 1 (e.g. 'faulty:0.2')"


class BeliefError(ValueError):
    """A belief string that is malformed or names a belief that cannot be built (yet)."""


@dataclass(frozen=True)
class BeliefSpec:
    """A parsed belief string; ``str()`` gives its canonical spelling (used in record keys)."""

    kind: Literal["true", "faulty", "read"]
    rate: float = 0.0

    def __str__(self) -> str:
        return f"faulty:{self.rate:g}" if self.kind == "faulty" else self.kind


def parse_belief(spec: str) -> BeliefSpec:
    """Validate a belief string; raise :class:`BeliefError` naming the accepted forms.

    >>> parse_belief("faulty:2")
    Traceback (most recent call last):
    ...
    apbot.bench.beliefs.BeliefError: belief 'faulty:2': the rate must be between 0 and 1
    """
    text = spec.strip()
    if text == "true":
        return BeliefSpec("true")
    if text == "read":
        raise BeliefError(
            "belief 'read' (a model read from the manual) is not available yet: "
            "the manual reader lands with the reading issue; use 'true' or "
            "'faulty:RATE'"
        )
    kind, sep, rate_text = text.partition(":")
    if kind == "faulty" and sep:
        try:
            rate = float(rate_text)
        except ValueError:
            raise BeliefError(
                f"belief {spec!r}: {rate_text!r} is not a number; accepted: {ACCEPTED_FORMS}"
            ) from None
        if not math.isfinite(rate) or not 0.0 <= rate <= 1.0:
            raise BeliefError(f"belief {spec!r}: the rate must be between 0 and 1")
        return BeliefSpec("faulty", rate)
    raise BeliefError(f"unknown belief {spec!r}; accepted: {ACCEPTED_FORMS}")


def belief_model(
    appliance: SuiteAppliance, belief: str | BeliefSpec, seed: int
) -> tuple[ApplianceModel, list[str]]:
    """The model a method is given for ``appliance``, and the faults injected into it (readable).

    Faults are seeded by ``"{seed}/{appliance id}"``: the same run gives the same faults in
    any process, and different appliances get independent draws.
    """
    spec = belief if isinstance(belief, BeliefSpec) else parse_belief(belief)
    if spec.kind == "true":
        return appliance.model, []
    if spec.kind == "faulty":
        from apbot.bench.faults import inject_faults  # written alongside; imported on use

        model, faults = inject_faults(appliance.model, spec.rate, seed=f"{seed}/{appliance.id}")
        return model, [str(fault) for fault in faults]
    raise BeliefError(f"belief {str(spec)!r} cannot be built yet")
