"""What kind of mismatch a press was: the first questions the loop's check asks of it.

Pure readings of one :class:`Executed` against the belief, no presses: whether the press
brought up another setting than the belief's step adjusts, and whether the belief's display
rules for its own setting may be what is wrong.
"""

from __future__ import annotations

from apbot.agent.perception import Seen
from apbot.agent.session import Executed, Session
from apbot.model.display import display_value

__all__ = ["shown_otherwise", "wrong_setting"]


def shown_otherwise(session: Session, done: Executed) -> bool:
    """The press of the belief's setting's own key brought up the screen of another setting
    whose steps do not have that key (or that shows the very value predicted), and the
    display changed: the belief's display rules for its setting may be wrong (once)."""
    seen = done.seen
    name = done.variable
    if seen is None or name is None or done.pointer is None or done.unchanged:
        return False
    others = {v for kind, v in seen.screens if kind == "focus"}
    if not others or seen.showing(name):
        return False
    effect = session.effect(done.pointer, done.action.name)
    if not session.stepping(done.pointer, done.action.name) and effect != "digit":
        return False
    model = session.belief.model
    printed = display_value(model.variables[name], done.predicted)
    if not (len(printed) >= 2 and printed in seen.text) and any(
        done.action.name in step.actions
        for steps in model.features.values()
        for step in steps
        if step.variable in others
    ):
        return False  # the other setting's own key, and not the value predicted either
    return session.budget.once("template", f"suspect:{name}")


def wrong_setting(session: Session, done: Executed) -> bool:
    """The press brought up another setting than the belief's step adjusts (or left the
    display as it was: a key ignored without a sign)."""
    if done.variable is None:
        return False
    seen = done.seen or Seen()
    if not seen.showing(done.variable) and not seen.unknown:
        return True
    if done.surprises.get(done.variable, (None, 0))[1] is not None:
        return False
    if done.unchanged:
        return True
    shown = seen.shown()
    return bool(shown - set(session.belief.model.display.indicators) - {done.variable})
