"""Where a misfiled or missing key is looked for: the panel's keys the belief gives no clear role.

The repairers probe these candidates one by one: keys no procedure uses, keys named like the
setting in trouble, keys filed beside another with the same effect. Also what a key did to a
step's setting as the display showed it, in the belief's vocabulary of effects.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from apbot.agent.perception import MISSING
from apbot.model.schema import GoTo
from apbot.read.actions import action_info

if TYPE_CHECKING:
    from apbot.agent.session import Session

__all__ = [
    "RUN_WORDS",
    "doubled_keys",
    "effect_shown",
    "keys_like",
    "locks_panel",
    "orphans",
    "run_states",
]

RUN_WORDS = ("running", "heating", "dispensing", "status", "brewing", "cooking")


def run_states(session: Session) -> dict[str, Any]:
    """The belief's run states (running, heating…) as they are now."""
    belief = session.belief
    return {n: belief.value(n) for n in belief.model.variables if any(w in n for w in RUN_WORDS)}


def effect_shown(session: Session, feature: str, index: int, before: Any, shown: Any) -> Any:
    """What the key did to the step's setting, as the display showed it: set it (the step's
    other keys set values too), stepped it one way or the other, or only showed it."""
    model = session.belief.model
    step = model.features[feature][index]
    effects = [session.effect((feature, index), a) for a in step.actions]
    if shown == before or shown is MISSING or shown is None:
        return "none"
    if any(isinstance(e, GoTo) for e in effects):
        return {"to": shown}
    values = session.domain_values(step.variable or "")
    if before in values and shown in values:
        i, j = values.index(before), values.index(shown)
        if (i + 1) % len(values) == j:
            return "next"
        if (j + 1) % len(values) == i:
            return "prev"
    return "next"


def doubled_keys(session: Session) -> list[str]:
    """Keys the belief files beside another key of the same step with the same effect: a
    second key doing exactly what the first does is more likely one misfiled there."""
    found = []
    for feature, steps in session.belief.model.features.items():
        for index, step in enumerate(steps):
            effects = [(a, session.effect((feature, index), a)) for a in step.actions]
            for i, (action, effect) in enumerate(effects):
                if any(effect == other for _, other in effects[:i]):
                    found.append(action)
    return [a for a in found if a in session.offered]


def keys_like(session: Session, name: str, exclude: set[str]) -> list[str]:
    """Keys of the panel whose names share a word with ``name`` (``press_timer`` for
    ``timer``, ``set_timer``): an entry key filed under another procedure."""
    words = {w for w in name.split("_") if len(w) >= 3 and w not in ("set", "press")}
    found = []
    for action in session.belief.model.actions:
        if action in exclude or action not in session.offered:
            continue
        if locks_panel(session, action):
            continue  # a lock hold named like the setting (hold TIMER ▲) would lock out
        parts = set(action_info(action).token.split("_"))  # its control's words, not its verb's
        if words & parts or any(
            w.startswith(p) or p.startswith(w) for w in words for p in parts if len(p) >= 3
        ):
            found.append(action)
    return found[:4]


def locks_panel(session: Session, action: str) -> bool:
    """Whether the belief says ``action`` puts the panel under a guard (locks it, switches
    it off) from where it is now."""
    compiled = session.belief.compiled
    index = compiled.action_index.get(action)
    if index is None:
        return False
    state = session.belief.state
    after = compiled.apply(state, index, compiled.hold_seconds[index] or None)
    if after is None:
        return False

    def holding(values: tuple[int, ...]) -> int:
        return sum(all(values[v] in ok for v, ok in guard.conditions) for guard in compiled.guards)

    return holding(after.values) > holding(state.values)


def orphans(session: Session) -> list[str]:
    """Keys the appliance offers that no feature of the belief uses, nor its keys that
    act from anywhere, nor a wait (at most eight)."""
    model = session.belief.model
    used = {a for steps in model.features.values() for s in steps for a in s.actions}
    used |= {a for entry in model.anywhere for a in entry.actions}
    used |= {a for a, spec in model.actions.items() if spec.skill == "wait"}
    return [a for a in session.belief.model.actions if a not in used and a in session.offered][:8]
