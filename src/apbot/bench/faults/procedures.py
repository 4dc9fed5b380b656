"""Faults in procedures (features): a step skipped, and what a step's keys are believed to do.

A reader skips "press TIMER before ▲/▼", misses that the first press only shows the setting,
gets a side effect wrong, files a key under the wrong procedure, or reads two procedures as one.
"""

from __future__ import annotations

import random

from apbot.bench.faults.common import Candidates, Fault, actions_text, dump, plain
from apbot.model.schema import ApplianceModel
from apbot.sim.compiled import default_effect


def missing_step(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A feature with two or more steps loses one (e.g. "press TIMER before ▲/▼").

    Steps that only press a key (entry, confirm) are tried first: that is what a reader skips.
    When the step's actions are used nowhere else they stay in the model (so it remains valid)
    as no-op actions of the neighbouring step: the belief then thinks ▲ works without TIMER,
    and that TIMER does nothing.
    """
    steps = model.features.get(name, [])
    if len(steps) < 2:
        return
    keys = [i for i, s in enumerate(steps) if s.variable is None]  # entry or confirm steps
    others = [i for i, s in enumerate(steps) if s.variable is not None]
    for i in rng.sample(keys, len(keys)) + rng.sample(others, len(others)):
        step = steps[i]
        data = dump(model)
        del data["features"][name][i]
        used = {a for feature in data["features"].values() for s in feature for a in s["actions"]}
        orphans = [a for a in step.actions if a not in used]
        label = f"step {i + 1} of {len(steps)} ({actions_text(step.actions)}) is missing"
        if not orphans:
            yield data, Fault("missing_step", name, label)
            continue
        if step.variable is not None or step.set or step.reset:
            continue  # a step that changes values cannot become a no-op
        j = i if i < len(steps) - 1 else i - 1  # the neighbour, indexed after the removal
        neighbour = steps[j + 1 if j >= i else j]
        target = data["features"][name][j]
        target["actions"] = [*orphans, *target["actions"]]
        if neighbour.variable is not None or neighbour.effect is not None:
            target["effect"] = {
                **{a: "none" for a in orphans},
                **{a: plain(default_effect(neighbour, a, model)) for a in neighbour.actions},
            }
        side = "next" if j >= i else "previous"
        yield (
            data,
            Fault(
                "missing_step",
                name,
                f"{label}; {', '.join(orphans)} kept as a no-op of the {side} step",
            ),
        )
