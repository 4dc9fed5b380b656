"""Lifting guards: bring the appliance out of the guards the belief thinks hold (switch it
on, unlock it) so that a probe or an unknown key can tell something. Apart from guards.py (which
explains, learns and relaxes guards, changing the belief) because lifting changes the appliance:
it only presses keys along planned routes.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.session import Session
from apbot.plan.plan import Unreachable, plan


class GuardLifter:
    """Press the appliance out of the guards the belief thinks hold."""

    session: Session

    def lift_all(self) -> None:
        """Bring the appliance out of every guard the belief thinks holds (switch it on,
        unlock it): a key the belief does not know can then tell something."""
        compiled = self.session.belief.compiled
        for guard in compiled.guards:
            holds = all(self.session.belief.state.values[v] in ok for v, ok in guard.conditions)
            blocked = [a for i, a in enumerate(compiled.action_names) if i not in guard.allowed]
            # a guard that getting out of puts the panel under another ("unit on": switching
            # off lands in "unit off") is no blocker to lift
            if holds and blocked and not self._swaps(guard):
                self.lift(blocked[0])

    def _swaps(self, guard: Any) -> bool:
        """Whether leaving ``guard`` (its first condition changed) makes another guard hold."""
        compiled = self.session.belief.compiled
        values = list(self.session.belief.state.values)
        for v, ok in guard.conditions:
            domain = compiled.vars[v].domain(self.session.belief.state.values)
            others = [i for i in range(len(domain.values) if domain else 0) if i not in ok]
            if not others:
                continue
            values[v] = others[0]
            return any(
                other is not guard and all(values[u] in allowed for u, allowed in other.conditions)
                for other in compiled.guards
            )
        return False

    def lift(self, action: str) -> None:
        """Bring the appliance out of any guard that would refuse ``action`` (switch it on,
        unlock it), so that a probe with ``action`` can tell something."""
        compiled = self.session.belief.compiled
        index = compiled.action_index[action]
        for guard in compiled.guards:
            holds = all(self.session.belief.state.values[v] in ok for v, ok in guard.conditions)
            if index in guard.allowed or not holds:
                continue
            for v, ok in guard.conditions:
                domain = compiled.vars[v].domain(self.session.belief.state.values)
                others = [
                    value for i, value in enumerate(domain.values if domain else ()) if i not in ok
                ]
                if not others:
                    continue
                try:
                    found = plan(
                        compiled,
                        self.session.belief.state,
                        {compiled.vars[v].name: others[0]},
                        self.session.config.plan_budget,
                        self.session.config.plan_work,
                    )
                except Unreachable:
                    continue
                before = self.session.last.text
                for planned in found.actions:
                    self.session.press(planned, exploring=True)
                name = compiled.vars[v].name
                after = self.session.last
                if (
                    self.session.belief.value(name) != others[0]
                    and after.accepted
                    and after.text.strip()
                    and after.text != before
                ):
                    # the panel answered (lit up, left the guard's message) with a screen the
                    # belief cannot read: it did come out of the guard
                    self.session.belief.set_value(name, others[0])
                break
