"""Where a programme starts a setting of its own, learnt from a look at it.

A setting that depends on the programme (a soup's cooking time, a cycle's spin) takes a
starting value when the programme is chosen. Manuals give the setting's range per programme
far more often than where each programme starts it: the reader then leaves the start unsaid,
and the model takes the first value of the range — a guess. When a look at the setting (no key
of its own pressed since the programme was chosen) shows another value of that programme's
range, the look is the evidence: the programme starts it there. Without this the belief keeps
its guess, and a planner that finds choosing the programme again cheaper than walking the
setting back goes round in a loop (choose, look, see the same value, choose again).
"""

from __future__ import annotations

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
    if observed in (MISSING, UNREADABLE, None) or predicted != before:
        return False  # not read, or the look itself moved the setting
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
    if not session.budget.once("start", f"{name}:{case}"):
        return False
    if not session.try_repair(
        lambda: set_start(model, name, case, observed),
        f"{name} starts at {observed!r} in {case}",
        session.belief.pointer(),
        refused=f"could not learn where {case} starts {name}",
    ):
        return False
    session.belief.set_value(name, observed)
    return True
