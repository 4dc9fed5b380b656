"""A quick proof that a goal is out of reach: search a small abstraction of the model.

The abstraction keeps the feature pointer and a few variables — those the guards read and the
goal's, as many as fit a small state space — and forgets the rest. An action is refused only
when a guard that reads kept variables alone refuses it; an effect that reads a forgotten
variable (a conditional's branch) or types a digit may end in any of its outcomes. Every run
of the model is then a run of the abstraction, so a goal the abstraction cannot reach is out
of reach of the model too: the search can stop at once instead of walking a space of
thousands of states that differ only in settings that do not matter (a lock that stops the
start key, a start that resets the setting the goal wants on, while running locks its key).

The converse does not hold: a goal the abstraction reaches may still be unreachable.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator, Sequence
from typing import Any

from apbot.plan.goals import CompiledGoal
from apbot.sim.compiled import CLEAR, COND, DIGIT, NONE, TABLE, CompiledModel, State, StepInfo

# abstract states (kept values × pointer positions) the abstraction may have
ABSTRACT_STATES = 5_000

Node = tuple[tuple[int, ...], int]  # kept value indices, pointer


def kept_variables(compiled: CompiledModel, goal: CompiledGoal) -> list[int]:
    """Variables the abstraction keeps: no programme setting (their domains change with the
    programme), guard variables first, then goal variables, smallest domains first, while
    the abstract space stays within :data:`ABSTRACT_STATES`."""
    guarded = {v for guard in compiled.guards for v, _ in guard.conditions}
    candidates = [v for v in sorted(guarded) if compiled.vars[v].parent < 0]
    candidates += sorted(
        (v for v in goal.variables if compiled.vars[v].parent < 0 and v not in guarded),
        key=lambda v: len(_domain(compiled, v)),
    )
    kept: list[int] = []
    size = len(compiled.steps) + 1
    for v in candidates:
        if size * len(_domain(compiled, v)) <= ABSTRACT_STATES:
            kept.append(v)
            size *= len(_domain(compiled, v))
    return kept


def _domain(compiled: CompiledModel, v: int) -> Sequence[Any]:
    domain = compiled.vars[v].domains[0]
    assert domain is not None  # a variable without a programme has one domain
    return domain.values


def out_of_reach(compiled: CompiledModel, goal: CompiledGoal, start: State) -> bool:
    """Whether the abstraction proves that no action sequence leads from ``start`` to
    ``goal`` (False: it cannot tell)."""
    kept = kept_variables(compiled, goal)
    position = {v: i for i, v in enumerate(kept)}
    wanted = [
        (position[v], want[0])
        for v, want in zip(goal.variables, goal.wanted, strict=True)
        if v in position
    ]
    if not wanted:
        return False  # the goal reads nothing the abstraction keeps
    abstraction = _Abstraction(compiled, kept)
    first: Node = (tuple(start.values[v] for v in kept), start.step)
    seen = {first}
    queue = deque([first])
    while queue:
        node = queue.popleft()
        if all(node[0][i] == index for i, index in wanted):
            return False
        for after in abstraction.successors(node):
            if after not in seen:
                seen.add(after)
                queue.append(after)
    return True


class _Abstraction:
    """The model's actions on (kept values, pointer); see the module docstring."""

    def __init__(self, compiled: CompiledModel, kept: list[int]) -> None:
        self.compiled = compiled
        self.position = {v: i for i, v in enumerate(kept)}
        self.sizes = [len(_domain(compiled, v)) for v in kept]
        # guards that read kept variables only: (conditions by position, allowed actions)
        self.guards = [
            (tuple((self.position[v], ok) for v, ok in guard.conditions), guard.allowed)
            for guard in compiled.guards
            if all(v in self.position for v, _ in guard.conditions)
        ]
        self.waits = frozenset(compiled.waits)  # waiting passes every guard
        self._moves: dict[int, list[tuple[int, int, StepInfo | None, tuple[Any, ...], int]]] = {}
        self._allowing: dict[tuple[int, ...], frozenset[int] | None] = {}

    def successors(self, node: Node) -> Iterator[Node]:
        values, step = node
        moves = self._moves.get(step)
        if moves is None:
            moves = self._moves[step] = self._moves_from(step)
        allowed = self._allowed(values)
        for action, target, info, effect, kind in moves:
            if allowed is not None and action not in allowed and action not in self.waits:
                continue
            if info is None:  # a wait: the pointer may time out, nothing else changes
                yield values, target
                continue
            for after in self._effects(values, info, effect, kind):
                yield after, target

    def _allowed(self, values: tuple[int, ...]) -> frozenset[int] | None:
        """The actions every guard holding on these kept values lets through (None: all)."""
        if values in self._allowing:
            return self._allowing[values]
        allowed: frozenset[int] | None = None
        for conditions, keys in self.guards:
            if all(values[i] in ok for i, ok in conditions):
                allowed = keys if allowed is None else allowed & keys
        self._allowing[values] = allowed
        return allowed

    def _moves_from(
        self, step: int
    ) -> list[tuple[int, int, StepInfo | None, tuple[Any, ...], int]]:
        """(action, pointer after, step whose effect applies or None for a wait, its effect,
        -1 or NONE when entering only shows) for every action the pointer accepts here."""
        compiled = self.compiled
        moves: list[tuple[int, int, StepInfo | None, tuple[Any, ...], int]] = []
        for action in range(len(compiled.action_names)):
            if action in compiled.waits:
                moves.append((action, self._waited(step, compiled.waits[action]), None, (), -1))
                continue
            anywhere = compiled.anywhere.get(action)
            if anywhere is not None:
                target = -1 if anywhere.leave else step
                moves.append((action, target, anywhere, anywhere.effects[action], -1))
                continue
            target = compiled.targets[step + 1][action]
            if target < 0:
                continue
            info = compiled.steps[target]
            kind = NONE if info.show_on_entry and target != step else -1
            moves.append((action, target, info, info.effects[action], kind))
        return moves

    def _waited(self, step: int, seconds: float) -> int:
        if step >= 0:
            timeout = self.compiled.steps[step].timeout
            if timeout is not None and seconds + 1e-9 >= timeout:
                return -1
        return step

    def _effects(
        self, values: tuple[int, ...], info: StepInfo, effect: tuple[Any, ...], kind: int
    ) -> list[tuple[int, ...]]:
        """Every kept-value outcome of one action's effect (``kind`` -1: the effect's own)."""
        outcomes = []
        for branch in self._branches(values, effect):
            new = list(values)
            main = self.position.get(info.variable)
            how = branch[0] if kind < 0 else kind
            choices: list[list[int]] = [new]
            if main is not None:
                if how in (TABLE, CLEAR) and branch[1][0] is not None:
                    new[main] = branch[1][0][new[main]]
                elif how == DIGIT:  # typing may leave any value
                    choices = [
                        [*new[:main], index, *new[main + 1 :]] for index in range(self.sizes[main])
                    ]
            for chosen in choices:
                for target, tables in info.side:
                    i = self.position.get(target)
                    if i is not None and tables[0] is not None:
                        chosen[i] = tables[0][chosen[i]]
                outcomes.append(tuple(chosen))
        return outcomes

    def _branches(self, values: tuple[int, ...], effect: tuple[Any, ...]) -> list[tuple[Any, ...]]:
        """A conditional's branch when it reads kept variables only, else both."""
        if effect[0] != COND:
            return [effect]
        conditions = effect[1]
        if all(v in self.position for v, _ in conditions):
            holds = all(values[self.position[v]] in ok for v, ok in conditions)
            return self._branches(values, effect[2] if holds else effect[3])
        return self._branches(values, effect[2]) + self._branches(values, effect[3])
