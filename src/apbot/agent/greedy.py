"""The ablation without a button policy: presses chosen one at a time from the feedback.

The macro-action order still comes from the model, and every step is entered with the
planned key; but instead of the computed number of "+" presses, the agent looks at the display,
picks the step key whose believed effect lands closest to the target, presses it, and looks
again — one decision, one reasoning step, per press. This is what the paper's "w/o button
policy" measures (an LLM choosing every press), and why it runs out of steps on long ranges.
"""

from __future__ import annotations

from collections import Counter
from typing import Any

from apbot.agent.session import MISSING, Executed, Session
from apbot.plan.plan import MacroAction, PlannedAction


class GreedyExecutor:
    """Execute a macro action press by press from the feedback."""

    def __init__(self, session: Session) -> None:
        self.session = session

    def execute_greedily(self, macro: MacroAction) -> list[Executed]:
        executed: list[Executed] = []
        actions = list(macro.actions)
        i = 0
        while i < len(actions):
            done = self.session.press(actions[i])
            executed.append(done)
            i += 1
            end = i
            while end < len(actions) and self._same_step(done, actions[end]):
                end += 1
            if (
                end == i
                or done.pointer is None
                or done.variable is None
                or not self.session.stepping(done.pointer, done.action.name)
            ):
                continue
            target = self._value_after(actions[i:end])
            executed.extend(self._towards(done, target))
            i = end
        return executed

    def _same_step(self, done: Executed, action: PlannedAction) -> bool:
        if done.pointer is None:
            return False
        feature, index = done.pointer
        return action.name in self.session.belief.model.features[feature][
            index
        ].actions and self.session.effect(done.pointer, action.name) not in ("digit", "none")

    def _value_after(self, actions: list[PlannedAction]) -> Any:
        """What the belief says the step's variable will be after these planned presses."""
        saved = self.session.belief.state
        name = self.session.step_variable(self.session.belief.pointer())
        for action in actions:
            self.session.belief.advance(action.name, action.seconds)
        value = self.session.belief.value(name) if name else None
        self.session.belief.state = saved
        return value

    def _towards(self, entered: Executed, target: Any) -> list[Executed]:
        """Press the key the belief says lands closest to ``target``, look, repeat."""
        assert entered.pointer is not None and entered.variable is not None
        name = entered.variable
        feature, index = entered.pointer
        keys = [
            a
            for a in self.session.belief.model.features[feature][index].actions
            if self.session.effect(entered.pointer, a) not in ("digit", "none")
        ]
        executed: list[Executed] = []
        seen: Counter[Any] = Counter()
        while True:
            observed = self.session.shown(name)
            if observed is MISSING or observed == target:
                return executed
            seen[observed] += 1
            if seen[observed] > 2:  # going round in circles
                return executed
            best = min(keys, key=lambda a: self._distance_after(name, a, target))
            self.session.count_reasoning_step()
            executed.append(self.session.press(self.session.planned(best)))

    def _distance_after(self, name: str, action: str, target: Any) -> float:
        saved = self.session.belief.state
        self.session.belief.advance(action)
        values = self.session.domain_values(name)
        after = self.session.belief.value(name)
        self.session.belief.state = saved
        if after not in values or target not in values:
            return float("inf")
        return abs(values.index(after) - values.index(target))
