"""Where a programme starts a setting of its own, learnt from a look at it.

A setting that depends on the programme (a soup's cooking time, a cycle's spin) takes a
starting value when the programme is chosen. Manuals give the setting's range per programme
far more often than where each programme starts it: the reader then leaves the start unsaid,
and the model takes the first value of the range — a guess. When a look at the setting (no key
of its own pressed since the programme was chosen) shows another value of that programme's
range, the look is the evidence: the programme starts it there (or, when the belief says the
look itself steps the value — an entry press that applies its step — where that step
would have come from). Without this the belief keeps
its guess, and a planner that finds choosing the programme again cheaper than walking the
setting back goes round in a loop (choose, look, see the same value, choose again).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from apbot.agent.perception import MISSING, UNREADABLE
from apbot.agent.repair import set_start
from apbot.model.domain import build_domain

if TYPE_CHECKING:
    from apbot.agent.executed import Executed
    from apbot.agent.session import Session


def learn_start(session: Session, name: str, before: Any, done: Executed | None) -> bool:
    """After a look at ``name`` (``before``: the belief's value ahead of it; ``done``: the
    look's last press): when the belief held its programme's guessed start and the display
    showed another value of that programme's range, the programme starts it there (once per
    setting and programme). True when the belief changed."""
    if done is None or name not in done.surprises:
        return False
    predicted, observed = done.surprises[name]
    if observed in (MISSING, UNREADABLE, None):
        return False  # not read
    model = session.belief.model
    spec = model.variables[name]
    case = session.case(name)
    if spec.depends_on is None or case is None or not spec.cases or case not in spec.cases:
        return False
    own = spec.cases[case]
    if getattr(own, "initial", None) is not None:
        return False  # the manual says where it starts: a look that disagrees is another story
    domain = build_domain(spec, own)
    if not domain.values or before != domain.values[0] or observed not in domain.index:
        return False  # the belief did not hold the guess, or the value is no start it can hold
    start = _start_before(domain.values, before, predicted, observed, bool(spec.wrap))
    if start is None:
        return False
    if not session.budget.once("start", f"{name}:{case}"):
        return False
    if not session.try_repair(
        lambda: set_start(model, name, case, start),
        f"{name} starts at {start!r} in {case}",
        session.belief.pointer(),
        refused=f"could not learn where {case} starts {name}",
    ):
        return False
    session.belief.set_value(name, observed)
    return True


def _start_before(
    values: Sequence[Any], before: Any, predicted: Any, observed: Any, wrap: bool = False
) -> Any:
    """The start that, moved as the belief says the look moves it (from ``before`` to
    ``predicted``: an entry press that steps the value once), gives what was shown — the
    value shown itself when the look was to leave it alone. None when that start would lie
    outside the range (the belief's look cannot have given what was shown), unless the values
    wrap round (``wrap``).

    >>> _start_before([20, 25, 30, 35, 40], 20, 20, 40), _start_before([20, 25, 30, 35], 20, 25, 35)
    (40, 30)
    >>> _start_before([20, 25, 30], 20, 25, 20) is None
    True
    >>> _start_before([20, 25, 30], 20, 30, 25, wrap=True)
    30
    """
    if predicted not in values:
        return None
    index = values.index(observed) - (values.index(predicted) - values.index(before))
    if wrap:
        index %= len(values)
    return values[index] if 0 <= index < len(values) else None
