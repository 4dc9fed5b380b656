"""A key that closes the procedure typed last, where the belief has it start something else.

Manuals end many entries with a key of another job: the clock, a kitchen timer or a delay is
typed and then confirmed with START, which starts the cooking only from the home screen. A
reader that missed the closing sentence has the entry end at its digits, so the plan sets the
timer and then presses START to cook: the appliance takes that START as the timer's confirmation
and shows the home screen again, not the cooking. The press that was to change a setting (running)
from no procedure of the one just typed in, right after that procedure's last step, did not
show it at all (or as text the belief cannot read) while the display did move: the key is that
procedure's last step. The belief learns the step — a key that does nothing more — and plans
again from there, so the next plan leaves the procedure before it presses the key for its own
job (on the appliance, the key pressed again at the confirmed entry does nothing): the agent
leaves it at once by the procedure's own entry key, which the plan has just pressed and seen
change nothing else — another key may clear what was set. Only for a procedure of an entry key
and what it sets, and a press that brought back the home screen (the belief's idle screen, or
the text the display showed before any press: a countdown that merely looks unreadable is the
key doing its job), changed no setting the display shows and lit no word the belief does not
know (that is the key's own sign: :mod:`apbot.agent.relit`); once per key.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from apbot.agent.executed import Executed
from apbot.agent.model_edits import RepairError
from apbot.agent.perception import MISSING, UNREADABLE
from apbot.agent.relit import new_word, printed_words
from apbot.agent.repair import insert_step

if TYPE_CHECKING:
    from apbot.agent.session import Session

__all__ = ["learn_closing"]


def learn_closing(session: Session, done: Executed) -> bool:
    """``done``'s key, pressed just after the last (adjusting) step of the procedure the belief
    was in, and believed to start another procedure, did not do that procedure's job (its
    setting not shown, or shown unreadably) though the display changed: learn it
    as the first procedure's closing step, its believed effects undone. True when the belief
    changed."""
    if done.refused or done.unchanged or done.before is None or done.pointer is None:
        return False
    if done.state_before is None or done.variable not in done.surprises:
        return False
    feature, index = done.before
    model = session.belief.model
    steps = model.features.get(feature, [])
    key = done.action.name
    if (
        index != len(steps) - 1
        or len(steps) < 2
        or steps[0].variable is not None  # an entry key, then what it sets
        or steps[index].variable is None
        or done.pointer[0] == feature
        or any(key in step.actions for step in steps)
    ):
        return False
    compiled = session.belief.compiled
    name = done.variable
    assert name is not None
    if done.surprises[name][1] not in (UNREADABLE, None):
        # its setting shown, if at its old value: the key came to it (and only showed it)
        return False
    text = done.feedback.text
    home = (done.seen is not None and done.seen.screen_kind == "idle") or (
        bool(text.strip()) and text == session.first_text
    )
    if not home:
        return False  # not back at the home screen: the key may have done its job unread
    seen = done.seen.values if done.seen is not None else {}
    if any(value != compiled.value(done.state_before, n) for n, value in seen.items()):
        return False  # it changed another setting the display shows: a key filed wrongly
    if new_word(done.text_before, done.feedback.text, printed_words(model)) is not None:
        return False  # a word the belief does not know lit up: the key's own sign (relit)
    if not session.budget.once("entry", f"closes:{key}"):
        return False
    try:
        new = insert_step(model, feature, len(steps), [key])
    except RepairError as exc:
        session.episode.log("repair", f"could not close {feature} with {key}: {exc}")
        return False
    undo = {
        n: compiled.value(done.state_before, n)
        for n in model.variables
        if done.observed(n) is MISSING
        and compiled.value(done.state_before, n) != session.belief.value(n)
    }
    session.adopt(
        new, f"{key} closes {feature} (it did not set {name} from there)", (feature, len(steps))
    )
    for n, value in undo.items():
        session.belief.set_value(n, value)
    entry = steps[0]
    if entry.variable is None and entry.actions[0] in session.offered:
        # leave the closed entry by its own first key, seen to change nothing else when the
        # plan typed it (any other key may reset what was set: a popcorn key clears the cook
        # time); the display shows the entry's setting kept
        session.press(session.planned(entry.actions[0]), exploring=True)
    return True
