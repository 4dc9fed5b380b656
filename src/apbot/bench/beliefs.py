"""The model a method works from in a benchmark run: the truth, a seeded faulty copy, or a reading.

A run's belief is one string (stored in every record and in ``run.json``):

- ``"true"`` — the ground-truth model, no faults;
- ``"faulty:RATE"`` — the ground truth with faults injected at ``RATE`` (0 ≤ RATE ≤ 1), seeded by
  the run's seed and the appliance id, so every process builds the same faulty model;
  ``"faulty:RATE:KIND,KIND"`` injects only those fault kinds (``apbot.bench.faults.FAULT_KINDS``);
- ``"read"`` — the default: a model read from the manual and the action names, by the configured
  LLM (``--llm``, seeded by the offline reading) or else by the offline reader
  (:mod:`apbot.bench.reading`: read once per appliance, cached on disk).

The string is parsed once up front (:func:`parse_belief`) so a typo stops the run before any work.

>>> parse_belief("faulty:0.30")
BeliefSpec(kind='faulty', rate=0.3, kinds=())
>>> str(parse_belief("faulty:0.30")), str(parse_belief("true"))
('faulty:0.3', 'true')
>>> str(parse_belief("faulty:0.3:guard, entry_format"))
'faulty:0.3:entry_format,guard'
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from apbot.bench.suite import SuiteAppliance
from apbot.model.schema import ApplianceModel

ACCEPTED_FORMS = (
    "'read', 'true', 'faulty:RATE' with 0 ≤ RATE ≤ 1 (e.g. 'faulty:0.2') or "
    "'faulty:RATE:KIND,...' (e.g. 'faulty:0.3:guard')"
)


class BeliefError(ValueError):
    """A belief string that is malformed or names a belief that cannot be built (yet)."""


@dataclass(frozen=True)
class BeliefSpec:
    """A parsed belief string; ``str()`` gives its canonical spelling (used in record keys)."""

    kind: Literal["true", "faulty", "read"]
    rate: float = 0.0
    kinds: tuple[str, ...] = ()  # fault kinds to inject (empty: every kind)

    def __str__(self) -> str:
        if self.kind != "faulty":
            return self.kind
        return f"faulty:{self.rate:g}" + (f":{','.join(self.kinds)}" if self.kinds else "")


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
        return BeliefSpec("read")
    kind, sep, rest = text.partition(":")
    rate_text, _, kinds_text = rest.partition(":")
    if kind == "faulty" and sep:
        try:
            rate = float(rate_text)
        except ValueError:
            raise BeliefError(
                f"belief {spec!r}: {rate_text!r} is not a number; accepted: {ACCEPTED_FORMS}"
            ) from None
        if not math.isfinite(rate) or not 0.0 <= rate <= 1.0:
            raise BeliefError(f"belief {spec!r}: the rate must be between 0 and 1")
        return BeliefSpec("faulty", rate, _fault_kinds(spec, kinds_text))
    raise BeliefError(f"unknown belief {spec!r}; accepted: {ACCEPTED_FORMS}")


def _fault_kinds(spec: str, text: str) -> tuple[str, ...]:
    """The kinds named after the rate, in the canonical order (``FAULT_KINDS``)."""
    named = [part.strip() for part in text.split(",") if part.strip()]
    if not named:
        if text.strip() or spec.strip().endswith(":"):
            raise BeliefError(f"belief {spec!r}: name at least one fault kind after the rate")
        return ()
    from apbot.bench.faults import FAULT_KINDS

    unknown = [k for k in named if k not in FAULT_KINDS]
    if unknown:
        raise BeliefError(
            f"belief {spec!r}: unknown fault kind(s) {', '.join(unknown)}; "
            f"known: {', '.join(FAULT_KINDS)}"
        )
    return tuple(k for k in FAULT_KINDS if k in named)


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

        model, faults = inject_faults(
            appliance.model, spec.rate, seed=f"{seed}/{appliance.id}", kinds=spec.kinds or None
        )
        return model, [str(fault) for fault in faults]
    from apbot.bench.reading import read_belief

    actions = list(appliance.model.actions)  # the names grounding gives, nothing more
    reading = read_belief(appliance.manual, actions, appliance.id, appliance.category)
    return reading.model, []
