"""Model faults: a ground-truth model mutated the way a reader gets a manual wrong.

The fault study asks whether the closed loop recovers from a wrong belief, so the faults are
the mistakes an LLM or an offline parser makes when reading a manual (each kind's docstring
has an example):

- in a variable's values (:mod:`~apbot.bench.faults.values`): ``step_size``, ``range_end``,
  ``missing_value``, ``extra_value``, ``value_order``, ``wrap``, ``effect_direction``,
  ``missing_case`` (a programme-dependent setting missing one programme's case);
- in how it is shown and typed (:mod:`~apbot.bench.faults.display`): ``display`` (a template,
  label or per-value word copied wrong), ``entry_format`` (``minutes`` for ``mm:ss``);
- in procedures (:mod:`~apbot.bench.faults.procedures`): ``missing_step``, ``on_entry``
  (``show`` for ``apply`` and back), ``side_effect``, ``misplaced_action``, ``merged_features``;
- in what the model holds (:mod:`~apbot.bench.faults.structure`): ``missing_variable``,
  ``spurious_variable``, ``guard``.

Every faulty model is still a valid model (the agent plans on it: each candidate must pass
:func:`apbot.model.validate.check_model`); goal values may fall outside a faulty domain,
which is what the agent must repair. Kinds skip mutations that could never show (a clamped
range written differently with the same values, two values of a cycle swapped…);
:func:`apbot.bench.faults.evidence.first_difference` finds the presses that reveal a fault.

Rate semantics
--------------
The *sites* (:func:`fault_sites`) are the settings a step adjusts, in file order (not
``power``, locks or the run state), then the procedures (features with two or more steps, one
that adjusts a setting or one with side effects), then the guards. Each site has its own
generator, seeded by ``(seed, appliance id, site)``; it draws one uniform number and is faulted
when that number is below ``rate``, with a kind of its section (variable, feature or guard
kinds) chosen uniformly among those that apply and keep the model valid (the kinds are tried
in a random order; the first that gives a valid model is kept). ``kinds`` restricts the choice
to some kinds, keeping each site's order of kinds. Faulted sites are mutated in the order of
their draws, smallest first, so the sites faulted at a lower rate are a prefix of those at a
higher rate: the faults at a lower rate are a subset of those at a higher rate with the same
seed, by construction, even where faults interact (a feature merged away, a variable
removed: a later site whose target is gone is skipped). Rate 0 returns the model unchanged
and rate 1 faults every site that can be faulted. Faults are listed in site order.
"""

from apbot.bench.faults.common import Fault, describe, fault_kind
from apbot.bench.faults.display import display, entry_format
from apbot.bench.faults.injection import (
    FAULT_KINDS,
    FEATURE_KINDS,
    GUARD_KINDS,
    MAX_TRIES_PER_KIND,
    ORIGINAL_KINDS,
    SITE_KINDS,
    VARIABLE_KINDS,
    Kind,
    candidate_sites,
    fault_sites,
    first_valid,
    inject_faults,
)
from apbot.bench.faults.procedures import (
    merged_features,
    misplaced_action,
    missing_step,
    on_entry,
    side_effect,
)
from apbot.bench.faults.structure import guard, missing_variable, spurious_variable
from apbot.bench.faults.values import (
    effect_direction,
    extra_value,
    missing_case,
    missing_value,
    range_end,
    step_size,
    value_order,
    wrap,
)

__all__ = [
    "FAULT_KINDS",
    "FEATURE_KINDS",
    "GUARD_KINDS",
    "MAX_TRIES_PER_KIND",
    "ORIGINAL_KINDS",
    "SITE_KINDS",
    "VARIABLE_KINDS",
    "Fault",
    "Kind",
    "candidate_sites",
    "describe",
    "display",
    "effect_direction",
    "entry_format",
    "extra_value",
    "fault_kind",
    "fault_sites",
    "first_valid",
    "guard",
    "inject_faults",
    "merged_features",
    "misplaced_action",
    "missing_case",
    "missing_step",
    "missing_value",
    "missing_variable",
    "on_entry",
    "range_end",
    "side_effect",
    "spurious_variable",
    "step_size",
    "value_order",
    "wrap",
]
