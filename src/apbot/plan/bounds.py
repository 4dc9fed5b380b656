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
where the reset leaves it (:func:`_reset_landings`). This keeps the search from wandering a
plateau of states that set the delay first, each as promising as the optimum by the plain sum.
"""

from __future__ import annotations

from collections import deque
from typing import Any

from apbot.model.effects import entry_digits
from apbot.plan.goals import CompiledGoal
from apbot.sim.compiled import CLEAR, DIGIT, TABLE, CompiledModel, State, leaves

INF = float("inf")
_ABSENT = ("absent",)  # a dependent setting that does not exist in the current programme


def _value_graph(
    compiled: CompiledModel, v: int, only_case: int | None = None, reset_costs: tuple[int, ...] = ()
) -> tuple[
    dict[Any, list[tuple[Any, int]]],
    list[tuple[Any, int]],
    list[tuple[Any, int]],
    list[tuple[Any, int]],
]:
    """Reverse edges ``to -> [(from, cost)]`` over canonical values, and two kinds of "from
    anywhere" edges: typing on the variable's own keypad step, and *jumps* made from outside
    its steps (side effects, programme changes) that need no press entering them. The last
    list holds the jumps that are programme changes (also among the jumps).

    ``only_case`` keeps a programme-dependent setting inside one programme's domain (the goal's).
    ``reset_costs`` is what a programme change to each programme value, restoring the setting's
    default there, costs it (1 where this setting is the one charged for its programme's
    presses, see :class:`LowerBound`; empty: 0 everywhere).
    """
    var = compiled.vars[v]

    def cases() -> list[tuple[int, Any]]:
        return [
            (c, d)
            for c, d in enumerate(var.domains)
            if d is not None and (only_case is None or c == only_case)
        ]

    reverse: dict[Any, list[tuple[Any, int]]] = {}
    typed_anywhere: list[tuple[Any, int]] = []
    jumps: list[tuple[Any, int]] = []
    entry = getattr(var.spec, "entry", None)

    def edge(a: Any, b: Any, cost: int) -> None:
        if a != b:
            reverse.setdefault(b, []).append((a, cost))

    for step in compiled.all_steps:  # features' steps and anywhere keys alike
        if step.variable == v:
            typed = False
            for effect in leaves(step.effects.values()):
                if effect[0] in (TABLE, CLEAR):
                    for case, domain in cases():
                        table = effect[1][case]
                        if table is None:
                            continue
                        for i, j in enumerate(table):
                            edge(domain.values[i], domain.values[j], 1)
                elif effect[0] == DIGIT and entry is not None and not typed:
                    typed = True  # every digit key of the step offers the same values
                    allowed = {value for _, d in cases() for value in d.values}
                    typed_anywhere.extend(
                        item for item in typeable_values(compiled, v) if item[0] in allowed
                    )
        for target, tables in step.side:
            if target == v:
                for case, domain in cases():
                    table = tables[case]
                    if table is not None:
                        jumps.append((domain.values[table[0]], 0))
    programme: list[tuple[Any, int]] = []
    if var.parent >= 0:  # a programme change restores the new programme's default
        # ... or, for a ``remember`` setting, the value kept for it: any of its values
        remembered = v in compiled.memory_slots

        def landing(d: Any) -> list[Any]:
            return list(d.values) if remembered else [d.values[d.initial]]

        if only_case is None:
            for case, d in enumerate(var.domains):
                cost = reset_costs[case] if reset_costs else 0
                if d is None:
                    programme.append((_ABSENT, cost))
                else:
                    programme.extend((value, cost) for value in landing(d))
        else:
            programme.extend((value, 0) for _, d in cases() for value in landing(d))
    return reverse, typed_anywhere, jumps + programme, programme


def typeable_values(compiled: CompiledModel, v: int) -> list[tuple[Any, int]]:
    """(value, digits needed from a fresh buffer) for every value a keypad can type."""
    cache = compiled.cache.setdefault("typeable", {})
    if v not in cache:
        var = compiled.vars[v]
        entry = getattr(var.spec, "entry", None)
        found: dict[Any, int] = {}
        for domain in var.domains:
            if entry is None or domain is None or domain.magnitudes is None:
                continue
            for value, magnitude in zip(domain.values, domain.magnitudes, strict=True):
                digits = entry_digits(magnitude, entry)
                if digits is not None:
                    found[value] = len(digits)
        cache[v] = list(found.items())
    return cache[v]


def distances_to(
    compiled: CompiledModel,
    v: int,
    goal_value: Any,
    only_case: int | None = None,
    reset_costs: tuple[int, ...] = (),
) -> tuple[dict[Any, float], float]:
    """Fewest main actions from each value to ``goal_value``, and the cost from anywhere."""
    dist, from_anywhere, _ = _distances(compiled, v, goal_value, only_case, reset_costs)
    return dist, from_anywhere


def _distances(
    compiled: CompiledModel,
    v: int,
    goal_value: Any,
    only_case: int | None,
    reset_costs: tuple[int, ...],
) -> tuple[dict[Any, float], float, float]:
    """:func:`distances_to`, plus the cheapest jump landing on the goal value: the only way
    there that uses none of the variable's own steps."""
    dist, from_anywhere, jump, _ = _distances_apart(compiled, v, goal_value, only_case, reset_costs)
    return dist, from_anywhere, jump


def _distances_apart(
    compiled: CompiledModel,
    v: int,
    goal_value: Any,
    only_case: int | None,
    reset_costs: tuple[int, ...],
) -> tuple[dict[Any, float], float, float, float]:
    """:func:`_distances`, plus the cost from anywhere by routes with no programme change."""
    reverse, typed_anywhere, jumps, programme = _value_graph(compiled, v, only_case, reset_costs)
    dist = _backwards(reverse, goal_value)
    anywhere = typed_anywhere + jumps
    from_anywhere = min((cost + dist.get(target, INF) for target, cost in anywhere), default=INF)
    jump = min((cost for target, cost in jumps if target == goal_value), default=INF)
    side = jumps[: len(jumps) - len(programme)]  # the programme changes come last
    unchosen = min(
        (cost + dist.get(target, INF) for target, cost in typed_anywhere + side), default=INF
    )
    return dist, from_anywhere, jump, unchosen


def _per_case_table(
    compiled: CompiledModel, v: int, goal_value: Any, reset_costs: tuple[int, ...]
) -> tuple[tuple[tuple[float, ...], ...], float, float, tuple[tuple[float, ...], ...]]:
    """The bound per case and value, the bound when absent, the cheapest jump, and the bound
    per case and value with no programme change (typing and side effects only), for a
    setting of a programme the goal does not name: distances within each programme's own
    domain (with its own keys' tables), since every programme change puts the setting back to
    the new programme's default (or what it kept there). Mixing the programmes' tables in one
    graph would let a setting land on a programme's default and walk on with another's keys.
    """
    var = compiled.vars[v]
    _, typed, jumps, programme = _value_graph(compiled, v, None, reset_costs)
    side = jumps[: len(jumps) - len(programme)]  # the programme changes come last
    dists: list[dict[Any, float]] = []
    for case, domain in enumerate(var.domains):
        if domain is None or goal_value not in domain.index:
            dists.append({})  # the goal cannot hold in this programme
        else:
            dists.append(_backwards(_value_graph(compiled, v, case)[0], goal_value))

    def from_any_case(value: Any) -> float:
        return min((dist.get(value, INF) for dist in dists), default=INF)

    anywhere = min((cost + from_any_case(target) for target, cost in typed + side), default=INF)
    remembered = v in compiled.memory_slots
    for case, domain in enumerate(var.domains):
        if domain is None:
            continue
        cost = reset_costs[case] if reset_costs else 0
        landing = domain.values if remembered else [domain.values[domain.initial]]
        anywhere = min(anywhere, cost + min(dists[case].get(value, INF) for value in landing))
    jump: float = min((cost for target, cost in jumps if target == goal_value), default=INF)
    per_case = tuple(
        ()
        if domain is None
        else tuple(min(dists[case].get(value, INF), anywhere) for value in domain.values)
        for case, domain in enumerate(var.domains)
    )
    # with no programme change: own keys within the programme, side effects, typing
    unchosen = min((cost + from_any_case(target) for target, cost in typed + side), default=INF)
    free = tuple(
        ()
        if domain is None
        else tuple(min(dists[case].get(value, INF), unchosen) for value in domain.values)
        for case, domain in enumerate(var.domains)
    )
    return per_case, anywhere, jump, free


def _backwards(reverse: dict[Any, list[tuple[Any, int]]], goal_value: Any) -> dict[Any, float]:
    """Fewest counted edges from every value to ``goal_value`` (0-1 BFS backwards)."""
    dist: dict[Any, float] = {goal_value: 0}
    queue: deque[Any] = deque([goal_value])
    while queue:
        node = queue.popleft()
        for source, cost in reverse.get(node, []):
            candidate = dist[node] + cost
            if candidate < dist.get(source, INF):
                dist[source] = candidate
                (queue.appendleft if cost == 0 else queue.append)(source)
    return dist


class LowerBound:
    """``bound(state)``: an admissible estimate of the actions left to reach the goal."""

    def __init__(self, compiled: CompiledModel, goal: CompiledGoal) -> None:
        self.compiled = compiled
        self.goal = goal
        cache: dict[Any, Any] = compiled.cache.setdefault("bounds", {})
        # per goal variable: (v, bound per case and value index, bound when absent, jump)
        self.tables: list[tuple[int, tuple[tuple[float, ...], ...], float, float]] = []
        goal_vars = set(goal.variables)
        self.entries = [_entry_requirements(compiled, v, goal_vars) for v in goal.variables]
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
        # steps, when every such press sets it (0: no such floor) — :func:`_gate_floor`
        self.gate_floors = [
            _gate_floor(compiled, v, entry, goal.canonical[name])
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
                cache[free_key] = _per_case_table(compiled, v, goal.canonical[name], costs)[3]
            self.detectors.setdefault(parent, []).append((v, cache[free_key]))
        candidates = [(w, wanted[0]) for w, wanted in zip(goal.variables, goal.wanted, strict=True)]
        candidates += [(w, MUST) for w in self.detectors]
        # per goal variable: (a variable that must still change, its goal index or MUST,
        # this one's bound after the reset every change of it makes) — :func:`_reset_landings`
        self.landings = [
            tuple(
                (w, wanted, self._landing_bound(table, landed))
                for w, wanted, landed in _reset_landings(compiled, candidates, v)
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
            found.append((p, wanted, _return_cost(compiled, p, wanted), members))
        return found

    def _unchosen(self, v: int, goal_value: Any) -> tuple[float, ...]:
        """Per value index in the goal programme's domain: the bound with no programme change."""
        goal_case = self._goal_case(v)
        assert goal_case is not None
        dist, _, _, unchosen = _distances_apart(self.compiled, v, goal_value, goal_case, ())
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
            for steps in _assigning_steps(compiled, parent):
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
            apart = _per_case_table(self.compiled, v, goal_value, reset_costs)
            return (v, apart[0], apart[1], apart[2])
        dist, anywhere, jump = _distances(self.compiled, v, goal_value, goal_case, reset_costs)
        per_case: list[tuple[float, ...]] = []
        for case, d in enumerate(self.compiled.vars[v].domains):
            if d is None:
                per_case.append(())
            elif goal_case is not None and case != goal_case:
                # the programme must still change to the goal's, which restores its default
                per_case.append((anywhere,) * len(d))
            else:
                per_case.append(tuple(min(dist.get(value, INF), anywhere) for value in d.values))
        absent = anywhere if goal_case is not None else min(dist.get(_ABSENT, INF), anywhere)
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


def _entry_requirements(
    compiled: CompiledModel, v: int, goal_vars: set[int]
) -> tuple[frozenset[int], frozenset[str], frozenset[int]] | None:
    """When every step adjusting ``v`` sits behind a step that adjusts no goal variable:
    the pointer positions from which no such entry press is needed, the features involved,
    and the steps in front (an entry press lands on one of them: presses landing on disjoint
    sets of steps are distinct presses). None when some step adjusting ``v`` can be entered
    directly."""
    if any(step.variable == v for step in compiled.anywhere_steps):
        return None  # an anywhere key adjusts it without entering anything
    free: set[int] = set()
    features: set[str] = set()
    gates: set[int] = set()
    for sid, step in enumerate(compiled.steps):
        if step.variable != v:
            continue
        if step.index == 0:
            return None
        # the steps from which one of its actions moves the pointer straight there: the one
        # before it, and those before optional steps in between
        before = [
            p
            for p in range(len(compiled.steps))
            if p != sid and any(compiled.targets[p + 1][a] == sid for a in step.actions)
        ]
        if any(compiled.steps[p].variable in goal_vars for p in before):
            return None
        free.add(sid)
        free.update(before)
        gates.update(before)
        features.add(step.feature)
    if not features:
        return None
    return frozenset(free), frozenset(features), frozenset(gates)


def _gate_floor(
    compiled: CompiledModel,
    v: int,
    entry: tuple[frozenset[int], frozenset[str], frozenset[int]] | None,
    goal_value: Any,
) -> float:
    """The fewest presses of v's own steps that bring ``v`` to ``goal_value`` from where a
    press onto one of the steps in front of them (``entry``'s gates) leaves it, when every
    such press sets ``v`` to a constant (a TIME key that shows 7:00 before the dial turns).
    A route that ends in v's own steps makes such a press last before them, and between it
    and the goal the pointer stays in v's steps, where nothing but v's own keys moves v or its
    programme: it goes on from the constant, not from v's value now. 0 (no floor) when
    some gate leaves ``v`` as it is, when an anywhere key or a cycle's end may change ``v``
    or its programme between that press and v's steps, or when a key enters v's steps
    from no feature."""
    if entry is None:
        return 0.0
    _, _, gates = entry
    var = compiled.vars[v]
    watched = {v, var.parent} if var.parent >= 0 else {v}
    if any(
        step.variable in watched or any(t in watched for t, _ in step.side)
        for step in compiled.anywhere_steps
    ) or any(any(t in watched for t, _ in cycle.side) for cycle in compiled.cycles):
        return 0.0
    own = [s for s, step in enumerate(compiled.steps) if step.variable == v]
    if any(compiled.targets[0][a] in own for s in own for a in compiled.steps[s].actions):
        return 0.0
    if any(t == var.parent for s in own for t, _ in compiled.steps[s].side):
        return 0.0  # its own steps change its programme
    floor = INF
    for gate in gates:
        step = compiled.steps[gate]
        if step.variable == var.parent and var.parent >= 0:
            return 0.0
        tables = [tables for t, tables in step.side if t == v]
        if not tables:
            return 0.0  # this press leaves v as it was
        for case, domain in enumerate(var.domains):
            table = tables[-1][case]
            if domain is None or table is None:
                continue
            if len(set(table)) != 1:
                return 0.0  # not a constant: where it lands depends on v
            reverse, typed, _, _ = _value_graph(compiled, v, case)
            dist = _backwards(reverse, goal_value) if goal_value in domain.index else {}
            typing = min((cost + dist.get(to, INF) for to, cost in typed), default=INF)
            floor = min(floor, dist.get(domain.values[table[0]], INF), typing)
    return 0.0 if floor == INF else floor


def _return_cost(compiled: CompiledModel, p: int, wanted: int) -> float:
    """Fewest presses of p's own keys that choose p again and leave it at value ``wanted``
    (from ``wanted``): a way round its values, or one press that assigns without changing
    (a go-to key, a clear, a digit)."""
    domain = compiled.vars[p].domains[0]
    assert domain is not None
    reverse, _, _, _ = _value_graph(compiled, p)
    dist = _backwards(reverse, domain.values[wanted])
    best = INF
    for step in compiled.all_steps:
        if step.variable != p:
            continue
        for effect in leaves(step.effects.values()):
            if effect[0] in (CLEAR, DIGIT):
                return 1.0
            if effect[0] != TABLE or effect[1][0] is None:
                continue
            after = effect[1][0][wanted]
            if after == wanted:
                if effect[2]:
                    return 1.0
                continue
            best = min(best, 1 + dist.get(domain.values[after], INF))
    return best


MUST = -3  # in place of a goal index: the variable is no goal, but must change (see below)


def _reset_landings(
    compiled: CompiledModel, candidates: list[tuple[int, int]], v: int
) -> list[tuple[int, int, list[tuple[int, int]]]]:
    """Variables every change of which resets goal variable ``v``: (w, w's goal index or
    :data:`MUST`, the (case, value index) pairs the reset can leave ``v`` at).

    ``candidates`` are (w, goal index) for goal variables, (w, MUST) for programmes of goal
    settings that are no goal themselves. While a goal w is off its goal — or a MUST w has a
    setting that cannot reach its goal without w changing — w must still change, and whatever
    changes it resets v in the same press; after the last such press v still has to go from
    where the reset left it to its goal, by presses counted in v's term only. Resets are
    ``reset``/``set`` side effects of every step that can change w (w selecting no programme of
    its own, else a programme change could move it without them), or, for a setting of w,
    the programme's default every change of w restores (not for a ``remember`` setting).
    """
    found = []
    parent = compiled.vars[v].parent
    for w, wanted in candidates:
        if w == v:
            continue
        changing = [
            step
            for step in compiled.all_steps
            if step.variable == w or any(target == w for target, _ in step.side)
        ]
        landed: set[tuple[int, int]] = set()
        if parent == w:
            if wanted != MUST or v in compiled.memory_slots:
                continue  # a goal programme: the goal's case says it already
            for case, domain in enumerate(compiled.vars[v].domains):
                landed.add((-1, 0) if domain is None else (case, domain.initial))
            for step in changing:  # a side effect of the same press may move it on
                for target, assigned in step.side:
                    if target == v:
                        landed.update(_side_landings(assigned))
            found.append((w, wanted, sorted(landed)))
            continue
        if compiled.vars[w].parent >= 0:
            continue
        for step in changing:
            tables = [assigned for target, assigned in step.side if target == v]
            if not tables or (
                parent >= 0  # the same press choosing v's programme restores its default
                and (step.variable == parent or any(t == parent for t, _ in step.side))
            ):
                break
            landed.update(_side_landings(tables[-1]))  # the last assignment wins
        else:
            if changing and landed:
                if parent >= 0:
                    landed.add((-1, 0))  # a programme change may also leave it absent
                found.append((w, wanted, sorted(landed)))
    return found


def _side_landings(tables: tuple[tuple[int, ...] | None, ...]) -> set[tuple[int, int]]:
    """The (case, value index) pairs a side effect's per-case tables can assign."""
    landed: set[tuple[int, int]] = set()
    for case, table in enumerate(tables):
        if table is None:
            landed.add((-1, 0))
        else:
            landed.update((case, index) for index in set(table))
    return landed


def _assigning_steps(compiled: CompiledModel, programme: int) -> list[set[int]]:
    """Per value of a programme, the steps whose actions can assign it that value (by their
    main effect or a side effect) — a superset is safe, a missing step is not."""
    var = compiled.vars[programme]
    domain = var.domains[0]
    assert domain is not None
    steps: list[set[int]] = [set() for _ in domain.values]
    for sid, step in enumerate(compiled.all_steps):  # ids past the features' are anywhere keys
        if step.variable == programme:
            for effect in leaves(step.effects.values()):
                if effect[0] in (TABLE, CLEAR) and effect[1][0] is not None:
                    for value in set(effect[1][0]):
                        steps[value].add(sid)
                elif effect[0] == DIGIT:
                    for chosen in steps:
                        chosen.add(sid)
        for target, tables in step.side:
            if target == programme and tables[0] is not None:
                steps[tables[0][0]].add(sid)
    return steps
