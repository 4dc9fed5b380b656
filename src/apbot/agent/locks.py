"""Locks and lit panels: what a refused key's screen says about the guards that hold.

Two beliefs a refusal's screen can correct, both as settings of the belief (no model edit):

* a key refused while the display prints a lock word (LOCK, LOC, KEYLOCK, a padlock) that
  the belief's own lock guard would explain, had the belief not thought the lock off: the
  reader copied the lock's message wrong ('UNLOCK' for the lamp of the lifted lock) or
  guessed its starting value wrong. The lock is on: the planner then lifts it with the
  lock's key.
* a guard whose screen is dark (switched off: the panel shows nothing) that the belief
  thinks holds while the display is lit: its setting is at another value. Left alone, a
  lock the belief also believes on leaves no key it allows (the off guard lets only the
  power key through, the lock only its own key): nothing can be planned.
"""

from __future__ import annotations

import re

from apbot.agent.repair import RepairError, set_display
from apbot.agent.session import Executed, Session
from apbot.model.display import OFF_WORDS

_WORD = re.compile(r"\S+")
_LOCK_WORDS = frozenset({"lock", "locked", "loc"})


def is_lock_setting(name: str) -> bool:
    """A setting that locks the panel (a child lock): its name has the word lock."""
    return "lock" in name.split("_")


def blocking_words(name: str, dark: bool, words: frozenset[str]) -> frozenset[str]:
    """The values at which setting ``name`` plausibly blocks keys: behind a refusal, a lock's
    release (a setting named for unlocking, "unlock", "hot_unlock") blocks when it is off."""
    if not dark and "unlock" in name.casefold().replace("-", "_").split("_"):
        return OFF_WORDS
    return words


def shows_lock(text: str) -> bool:
    """Whether a display text prints a lock word: LOCK, LOC, LOCKED, a compound ending in
    lock (KEYLOCK, C-LOCK) or a padlock — not UNLOCK (the lock lifted), CLOCK nor BLOCKED."""
    for match in _WORD.finditer(text):
        word = match.group(0).strip(".,:;!?()[]").casefold()
        if "🔒" in word or word in _LOCK_WORDS:
            return True
        stem = word.removesuffix("ed")
        if (
            stem.endswith("lock")
            and not stem.startswith("un")
            and not stem.endswith(("clock", "block"))
        ):
            return True  # (FILTER BLOCKED is a fault, not a lock)
    return False


def believe_lock_shown(session: Session, refused: Executed) -> bool:
    """A key refused under a lock word, which a lock guard of the belief would refuse but
    the belief thinks lifted: believe the lock on (True), so that the plan lifts it first."""
    if not shows_lock(refused.feedback.text):
        return False
    compiled = session.belief.compiled
    action = compiled.action_index.get(refused.action.name)
    state = session.belief.state
    for guard in compiled.guards:
        if action in guard.allowed or not guard.conditions:
            continue
        if not all(is_lock_setting(compiled.vars[v].name) for v, _ in guard.conditions):
            continue
        if all(state.values[v] in ok for v, ok in guard.conditions):
            return False  # the belief knew it locked: something else is wrong
        if not session.budget.once("guard", f"lock shown:{guard.name or guard.display}"):
            return False
        for v, ok in guard.conditions:
            domain = compiled.vars[v].domain(state.values)
            if domain is not None:
                session.belief.set_value(compiled.vars[v].name, domain.values[min(ok)])
        session.episode.log(
            "repair",
            f"refused with {refused.feedback.text.strip()!r}: the panel is locked "
            f"('{guard.name or guard.display}')",
        )
        for v, _ in guard.conditions:
            _unlock_lamp(session, compiled.vars[v].name)
        return True
    return False


def _unlock_lamp(session: Session, name: str) -> None:
    """A lock the belief lights as UNLOCK (or another un-word of locking) while on: that
    lamp is the lifted lock's, lit when it is off — swap the two values' words."""
    spec = session.belief.model.variables[name]
    show = getattr(spec, "show", None)
    on = session.belief.value(name)
    if not isinstance(show, dict) or len(show) != 2 or str(on) not in show:
        return
    word = show[str(on)]
    if not (word.casefold().startswith("un") and shows_lock(word[2:])):
        return
    off = next(k for k in show if k != str(on))
    if show[off]:
        return
    try:
        model = set_display(session.belief.model, name, {str(on): "", off: word})
    except RepairError:
        return
    session.adopt(model, f"{name}: {word} is lit while it is {off}", session.belief.pointer())


def lit_not_dark(session: Session) -> bool:
    """A guard that hides the display (the appliance off) believed to hold while the
    display is lit with other text: its setting is not at that value (True: believed
    changed)."""
    text = session.last.text.strip()
    if not text:
        return False
    compiled = session.belief.compiled
    guard = compiled.hiding_guard(session.belief.state)
    if guard is None or len(guard.conditions) != 1 or (guard.display and guard.display in text):
        return False
    ((v, ok),) = guard.conditions
    domain = compiled.vars[v].domain(session.belief.state.values)
    others = [value for i, value in enumerate(domain.values if domain else ()) if i not in ok]
    name = compiled.vars[v].name
    if len(others) != 1 or not session.budget.once("guard", f"lit:{name}"):
        return False
    if not session.belief.set_value(name, others[0]):
        return False
    session.episode.log(
        "repair", f"the display is lit ({text!r}): {name} is {others[0]}, not '{guard.name}'"
    )
    return True
