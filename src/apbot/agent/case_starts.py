"""Where a programme starts a setting of its own, learnt from a look at it.

A setting that depends on the programme (a soup's cooking time, a cycle's spin) takes a
starting value when the programme is chosen; so does one the programme's choice resets (a
cake's baking time reset by the menu dial). Manuals give the setting's range per programme far
more often than where each programme starts it: the reader then leaves the start unsaid, and
the model takes the first value of the range — a guess. When a look at the setting (no key of
its own pressed since the programme was chosen, or only the one press of its own key the look
needed) shows another value of its range, the look is the evidence: the programme starts it
there — or, where the look's press moved it a step, a step before what it showed. Without this
the belief keeps its guess, and a planner that finds choosing the programme again cheaper than
walking the setting back goes round in a loop (choose, look, see the same value, choose again).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from apbot.agent.perception import MISSING, UNREADABLE
from apbot.agent.repair import set_start

if TYPE_CHECKING:
    from apbot.agent.executed import Executed
    from apbot.agent.session import Session


def learn_start(session: Session, name: str, before: Any, done: Executed | None) -> bool:
    """After a look at ``name`` (``before``: the belief's value ahead of it; ``done``: the
    look's last press): when the belief held its guessed start (the programme's, or the one a
    reset brings it back to) and the display showed another value, the start is where the
    belief's own press would show that value from (once per setting and programme). True when
    the belief changed."""
    if done is None or name not in done.surprises:
        return False
    predicted, observed = done.surprises[name]
    if observed in (MISSING, UNREADABLE, None):
        return False
    model = session.belief.model
    spec = model.variables[name]
    case = session.case(name)
    if spec.depends_on is not None:
        if case is None or not spec.cases or case not in spec.cases:
            return False
        own: Any = spec.cases[case]
    elif any(name in step.reset for steps in model.features.values() for step in steps):
        own = spec  # reset by a programme's choice (or another step) to a start read nowhere
    else:
        return False
    if getattr(own, "initial", None) is not None:
        return False  # the manual says where it starts: a look that disagrees is another story
    if before != session.belief.initial_value(name):
        return False  # the belief did not hold the guess
    start = _start(session.domain_values(name), before, predicted, observed, bool(spec.wrap))
    if start is None:
        return False
    if not session.budget.once("start", f"{name}:{case}"):
        return False
    where = f"in {case}" if case is not None else "when reset"
    if not session.try_repair(
        lambda: set_start(model, name, case, start),
        f"{name} starts at {start!r} {where}",
        session.belief.pointer(),
        refused=f"could not learn where {name} starts {where}",
    ):
        return False
    session.belief.set_value(name, observed)
    return True


def _start(values: list[Any], before: Any, predicted: Any, observed: Any, wrap: bool) -> Any:
    """The value the look started from, had the belief's press moved the setting from it
    as it was predicted to move it from ``before``; None if there is none.

    >>> _start([20, 25, 30, 35, 40], 20, 20, 40, False)
    40
    >>> _start([20, 25, 30, 35, 40], 20, 25, 40, False)
    35
    >>> _start([0, 20, 40, 60], 0, 20, 0, True)
    60
    >>> _start([0, 20, 40, 60], 0, 20, 0, False) is None
    True
    """
    if observed not in values or before not in values or predicted not in values:
        return None
    index = values.index(observed) - (values.index(predicted) - values.index(before))
    if wrap:
        index %= len(values)
    elif not 0 <= index < len(values):
        return None
    start = values[index]
    return None if start == before else start
