"""An admissible, consistent lower bound on the actions still needed to reach a goal.

Every action has at most one *main* variable: the one its step adjusts. For each goal variable
we compute, over a graph of its values, the fewest actions whose main variable it is that can
bring it to its goal value. Changes it undergoes as a side effect of another step (``set``,
``reset``, a programme change restoring a setting's default) cost nothing in its graph — they
are paid for by the other step's variable. Each action is therefore counted at most once across
variables, and the sum over goal variables never overestimates: A* with it is optimal.

Typing a value on a keypad costs its digit count from a fresh buffer. Only the search's start
node can continue a half-typed buffer (elsewhere a visit is maximal, so leaving the keypad step
discards the buffer); there, and only there, one digit may finish the job (``continuing``).

Presses that adjust no goal variable (TIME COOK before the digits) are counted too: when a
goal variable can only be adjusted in a step reached through such a press, any route that uses
one of its own steps makes that press, and presses landing on different steps are distinct
actions (the hour and the minute of a clock each have their own CLOCK press in front). A route
that never uses its own steps — a side effect, or a programme change that restores the goal
value as the new programme's default — needs no entry press, so a variable's term is
``min(own route + entry, cheapest such jump)``, never the sum of a jump and an entry.

A goal setting that a still-needed change of another goal variable resets (a programme key
that resets the delay) must be set after that change: its term is at least its distance from
where the reset leaves it (:func:`apbot.plan.terms.reset_landings`). This keeps the search
from wandering a plateau of states that set the delay first, each as promising as the
optimum by the plain sum.
"""

from __future__ import annotations

from typing import Any

from apbot.plan.distances import ABSENT, INF, distances, distances_apart, per_case_table
from apbot.plan.goals import CompiledGoal
from apbot.plan.terms import (
    MUST,
    assigning_steps,
    entry_requirements,
    gate_floor,
    reset_landings,
    return_cost,
)
from apbot.sim.compiled import DIGIT, CompiledModel, State

__all__ = ["INF", "LowerBound"]


class LowerBound:
    """``bound(state)``: an admissible estimate of the actions left to reach the goal."""

    def __init__(self, compiled: CompiledModel, goal: CompiledGoal) -> None:
        self.compiled = compiled
        self.goal = goal
        cache: dict[Any, Any] = compiled.cache.setdefault("bounds", {})
        # per goal variable: (v, bound per case and value index, bound when absent, jump)
        self.tables: list[tuple[int, tuple[tuple[float, ...], ...], float, float]] = []
        goal_vars = set(goal.variables)
        self.entries = [entry_requirements(compiled, v, goal_vars) for v in goal.variables]
        charged = self._charged_dependents()
        for name, v in zip(goal.names, goal.variables, strict=True):
            goal_case = self._goal_case(v)
            reset_costs = charged.get(v, ())
            key = (v, goal.canonical[name], goal_case, reset_costs)
            if key not in cache:
                cache[key] = self._table(v, goal.canonical[name], goal_case, reset_costs)
            self.tables.append(cache[key])
        self.returns = self._programme_returns(cache)
        # per goal variable: its least term after a press onto a step in front of its own
        # steps, when every such press sets it (0: no such floor) — see
        # :func:`apbot.plan.terms.gate_floor`
        self.gate_floors = [
            gate_floor(compiled, v, entry, goal.canonical[name])
            for name, v, entry in zip(goal.names, goal.variables, self.entries, strict=True)
        ]
        # programmes no goal names, with the goal settings that may need them to change:
        # [(setting, its bound per case and value with no programme change)]
        self.detectors: dict[int, list[tuple[int, tuple[tuple[float, ...], ...]]]] = {}
        for name, v in zip(goal.names, goal.variables, strict=True):
            parent = compiled.vars[v].parent
            if parent < 0 or parent in goal_vars:
                continue
            costs = charged.get(v, ())
            free_key = ("free", v, goal.canonical[name], costs)
            if free_key not in cache:
                cache[free_key] = per_case_table(compiled, v, goal.canonical[name], costs)[3]
            self.detectors.setdefault(parent, []).append((v, cache[free_key]))
        candidates = [(w, wanted[0]) for w, wanted in zip(goal.variables, goal.wanted, strict=True)]
        candidates += [(w, MUST) for w in self.detectors]
        # per goal variable: (a variable that must still change, its goal index or MUST,
        # this one's bound after the reset every change of it makes) — see
        # :func:`apbot.plan.terms.reset_landings`
        self.landings = [
            tuple(
                (w, wanted, self._landing_bound(table, landed))
                for w, wanted, landed in reset_landings(compiled, candidates, v)
            )
            for v, table in zip(goal.variables, self.tables, strict=True)
        ]
        # steps where a partly typed buffer may finish a goal variable with one digit
        self.typing_step = {
            s: step.variable
            for s, step in enumerate(compiled.steps)
            if step.variable in goal_vars and any(e[0] == DIGIT for e in step.effects.values())
        }

    def __call__(self, state: State, continuing: bool = False) -> float:
        values = state.values
        vars_ = self.compiled.vars
        total = 0.0
        typing = self.typing_step.get(state.step, -1) if continuing and state.buffer else -1
        claimed: set[int] = set()  # steps an entry press counted so far lands on
        found: list[float] = []  # each goal variable's term, when programme returns need them
        must = self._must_change(values) if self.detectors else ()
        for (v, per_case, absent, jump), entry, landings, floor in zip(
            self.tables, self.entries, self.landings, self.gate_floors, strict=True
        ):
            index = values[v]
            if index < 0:
                bound = absent
            else:
                parent = vars_[v].parent
                bound = per_case[values[parent] if parent >= 0 else 0][index]
                if v == typing and bound > 1:
                    bound = 1
            for w, wanted, after_reset in landings:
                if after_reset > bound and (w in must if wanted == MUST else values[w] != wanted):
                    bound = after_reset  # w must still change, and that resets v
            if bound >= 1 and entry is not None:
                needs, _, gates = entry
                if state.step not in needs and claimed.isdisjoint(gates):
                    # a route through v's own steps makes an entry press no goal variable
                    # pays for; a jump (side effect, programme change) makes none. When
                    # that press sets v, the own route goes on from where it left v
                    bound = max(bound, floor)
                    if bound + 1 <= jump:
                        bound += 1
                        claimed |= gates
                    else:
                        bound = jump
            total += bound
            if self.returns:
                found.append(bound)
        for p, wanted, back, members in self.returns:
            if values[p] != wanted or found[self._index[p]] != 0:
                continue
            gap = 0.0
            for k, unchosen in members:
                v = self.tables[k][0]
                index = values[v]
                if index < 0 or found[k] == INF:
                    continue
                without = unchosen[index]
                if v == typing and without > 1:
                    without = 1
                for w, wanted_w, after_reset in self.landings[k]:
                    if after_reset > without and (
                        w in must if wanted_w == MUST else values[w] != wanted_w
                    ):
                        without = after_reset
                gap += without - found[k]
            total += min(gap, back)
        return total

    def _must_change(self, values: tuple[int, ...]) -> set[int]:
        """Programmes no goal names that must change all the same: a goal setting of theirs is
        absent in the current programme, or no key but a programme change brings it to its
        goal from here."""
        must = set()
        for w, settings in self.detectors.items():
            for v, free in settings:
                index = values[v]
                if index < 0 or free[values[w]][index] == INF:
                    must.add(w)
                    break
        return must

    def _programme_returns(
        self, cache: dict[Any, Any]
    ) -> list[tuple[int, int, float, list[tuple[int, tuple[float, ...]]]]]:
        """Goal programmes whose settings may need the programme chosen again: per programme,
        (p, its goal index, the fewest presses that leave p and choose its goal value again,
        [(goal index of a setting of p, that setting's bound per value with no programme
        change)]).

        While p is at its goal its term is 0, yet a setting of p whose own keys cannot reach
        its goal value (a power level that only goes up) gets there only by p being chosen
        again, which restores its default: p's own presses, counted nowhere else. With no
        programme change, each setting needs its bound without programme-change routes; with
        one, p needs the presses of a return. The bound adds the smaller of the two extras.
        Only for a p that its own keys alone can change (no side effect assigns it, it selects
        no programme of its own), and settings with no entry press in their term.
        """
        compiled, goal = self.compiled, self.goal
        self._index = {v: k for k, v in enumerate(goal.variables)}
        found = []
        for p, name in zip(goal.variables, goal.names, strict=True):
            var = compiled.vars[p]
            if var.parent >= 0 or any(
                target == p for step in compiled.all_steps for target, _ in step.side
            ):
                continue
            members = []
            for k, v in enumerate(goal.variables):
                if compiled.vars[v].parent != p or self.entries[k] is not None:
                    continue
                key = ("unchosen", v, goal.canonical[goal.names[k]], self._goal_case(v))
                if key not in cache:
                    cache[key] = self._unchosen(v, goal.canonical[goal.names[k]])
                members.append((k, cache[key]))
            if not members:
                continue
            domain = var.domains[0]
            assert domain is not None
            wanted = domain.index[goal.canonical[name]]
            found.append((p, wanted, return_cost(compiled, p, wanted), members))
        return found

    def _unchosen(self, v: int, goal_value: Any) -> tuple[float, ...]:
        """Per value index in the goal programme's domain: the bound with no programme change."""
        goal_case = self._goal_case(v)
        assert goal_case is not None
        dist, _, _, unchosen = distances_apart(self.compiled, v, goal_value, goal_case, ())
        domain = self.compiled.vars[v].domains[goal_case]
        assert domain is not None
        return tuple(min(dist.get(value, INF), unchosen) for value in domain.values)

    @staticmethod
    def _landing_bound(
        table: tuple[int, tuple[tuple[float, ...], ...], float, float],
        landed: list[tuple[int, int]],
    ) -> float:
        """The least bound over the (case, value index) pairs a reset may leave a variable at
        (case -1: absent in the programme of the moment)."""
        _, per_case, absent, _ = table
        return min(
            (absent if case < 0 else per_case[case][index] for case, index in landed),
            default=0.0,
        )

    def _goal_case(self, v: int) -> int | None:
        """The programme a dependent goal setting must end in, when the goal names it."""
        parent = self.compiled.vars[v].parent
        if parent < 0 or parent not in self.goal.variables:
            return None
        domain = self.compiled.vars[parent].domains[0]
        assert domain is not None
        return domain.index[self.goal.canonical[self.compiled.vars[parent].name]]

    def _charged_dependents(self) -> dict[int, tuple[int, ...]]:
        """Goal settings that pay for their programme's presses: per setting, what a programme
        change to each programme value costs it (1 or 0).

        A programme that is not itself a goal variable changes only through presses no goal
        variable pays for — unless a goal variable's step assigns it as a side effect. Then the
        first goal setting depending on it is charged one press for reaching the default of a
        programme value by a programme change (the others of the same programme ride along
        for free). Charges are per programme value, by the steps that can assign it: a step
        that can assign two programmes' values at once (POWER resetting both zones) is charged
        to one of them only, and steps in a feature the entry term already charges for, or
        adjusting a goal variable, are never charged here.
        """
        compiled = self.compiled
        goal_vars = set(self.goal.variables)
        entry_features = {f for entry in self.entries if entry is not None for f in entry[1]}
        charged: dict[int, tuple[int, ...]] = {}
        used_steps: set[int] = set()
        seen_parents: set[int] = set()
        for v in self.goal.variables:
            parent = compiled.vars[v].parent
            if parent < 0 or parent in goal_vars or parent in seen_parents:
                continue
            seen_parents.add(parent)
            costs = []
            charging: set[int] = set()
            for steps in assigning_steps(compiled, parent):
                free = bool(steps & used_steps) or any(
                    compiled.all_steps[s].variable in goal_vars
                    or compiled.all_steps[s].feature in entry_features
                    for s in steps
                )
                costs.append(0 if free else 1)
                if not free:
                    charging |= steps
            used_steps |= charging
            if any(costs):
                charged[v] = tuple(costs)
        return charged

    def _table(
        self, v: int, goal_value: Any, goal_case: int | None, reset_costs: tuple[int, ...] = ()
    ) -> tuple[int, tuple[tuple[float, ...], ...], float, float]:
        if goal_case is None and self.compiled.vars[v].parent >= 0:
            apart = per_case_table(self.compiled, v, goal_value, reset_costs)
            return (v, apart[0], apart[1], apart[2])
        dist, anywhere, jump = distances(self.compiled, v, goal_value, goal_case, reset_costs)
        per_case: list[tuple[float, ...]] = []
        for case, d in enumerate(self.compiled.vars[v].domains):
            if d is None:
                per_case.append(())
            elif goal_case is not None and case != goal_case:
                # the programme must still change to the goal's, which restores its default
                per_case.append((anywhere,) * len(d))
            else:
                per_case.append(tuple(min(dist.get(value, INF), anywhere) for value in d.values))
        absent = anywhere if goal_case is not None else min(dist.get(ABSENT, INF), anywhere)
        return (v, tuple(per_case), absent, jump)

    def blocking(self, state: State) -> list[str]:
        """Goal variables whose goal value no action can ever reach from this state."""
        values = state.values
        names = []
        for name, (v, per_case, absent, _) in zip(self.goal.names, self.tables, strict=True):
            index = values[v]
            parent = self.compiled.vars[v].parent
            bound = absent if index < 0 else per_case[values[parent] if parent >= 0 else 0][index]
            if bound == INF:
                names.append(name)
        return names
