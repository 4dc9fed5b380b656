"""Model faults: a ground-truth model mutated the way a reader gets a manual wrong.

The fault study asks whether the closed loop recovers from a wrong belief, so the faults are
the mistakes an LLM or an offline parser makes when reading a manual: a wrong step or range
end, a value missed or invented, a list in the wrong order, wrap and clamp confused, a key's
direction reversed, a step of a procedure skipped. Every faulty model is still a valid model
(the agent plans on it); goal values may fall outside a faulty domain, which is what the agent
must repair.

Rate semantics
--------------
The *sites* are the model's adjustable variables, in file order (those a feature steps, adds
to or types: not ``power``, locks, or variables only set as side effects such as ``running``),
then its features with two or more steps. Each site has its own generator, seeded by
``(seed, appliance id, site)``; it draws one uniform number and is faulted when that number is
below ``rate``, with a kind chosen uniformly among those that apply and keep the model valid
(the kinds are tried in a random order; the first that gives a valid model is kept). A site's
draws depend neither on the rate nor on the other sites, so the faults at a lower rate are a
subset of those at a higher rate with the same seed (validity is judged with the earlier
faults in place, so an earlier fault could in principle rule a later choice out; on the
bundled suite it never does, which the tests check). Rate 0 returns the model unchanged and
rate 1 faults every site that can be faulted.

The package: :mod:`~apbot.bench.faults.common` (the :class:`Fault` record, model data helpers),
:mod:`~apbot.bench.faults.values` (faults in a variable's values),
:mod:`~apbot.bench.faults.procedures` (faults in features) and
:mod:`~apbot.bench.faults.injection` (sites, kind tables, :func:`inject_faults`).
"""

from apbot.bench.faults.common import Fault, describe, fault_kind
from apbot.bench.faults.injection import (
    FAULT_KINDS,
    FEATURE_KINDS,
    MAX_TRIES_PER_KIND,
    VARIABLE_KINDS,
    Kind,
    fault_sites,
    first_valid,
    inject_faults,
)
from apbot.bench.faults.procedures import missing_step
from apbot.bench.faults.values import (
    effect_direction,
    extra_value,
    missing_value,
    range_end,
    step_size,
    value_order,
    wrap,
)

__all__ = [
    "FAULT_KINDS",
    "FEATURE_KINDS",
    "MAX_TRIES_PER_KIND",
    "VARIABLE_KINDS",
    "Fault",
    "Kind",
    "describe",
    "effect_direction",
    "extra_value",
    "fault_kind",
    "fault_sites",
    "first_valid",
    "inject_faults",
    "missing_step",
    "missing_value",
    "range_end",
    "step_size",
    "value_order",
    "wrap",
]
