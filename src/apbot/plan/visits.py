"""The button policy: the cheapest ways to spend one *visit* in a step.

A visit is a maximal run of actions during which the feature pointer stays on one step: an
entry action that moves the pointer there, then any number of the step's own actions. Every
action sequence splits into visits, so searching over visits (``apbot.plan.search``) loses
nothing as long as each visit offers every useful way to leave the step.

Inside a visit only the step's variable moves (plus constant side effects), so a breadth-first
search over its values finds the shortest press counts: ``+`` vs ``-``, wrap-around, piecewise
steps, dial turns, go-to keys, holds. Keypad steps are solved in closed form instead: the
shortest digit string that leaves the buffer reading the wanted value (see
:func:`keypad_presses`), since the buffer space is too large to search.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Sequence

from apbot.model.effects import entry_digits, typed_lengths
from apbot.model.schema import Entry
from apbot.plan.distances import INF, distances_to, typeable_values
from apbot.plan.goals import CompiledGoal
from apbot.sim.compiled import CLEAR, DIGIT, NONE, CompiledModel, State

Exit = tuple[State, tuple[int, ...]]

# Above this many values, a variable's exits are restricted to useful candidates (keypads).
SMALL_DOMAIN = 64


class VisitTooLarge(Exception):
    """One visit to a step ends in more distinct states than the search may hold."""


def explore_visit(
    compiled: CompiledModel,
    state: State,
    step: int,
    entry: Sequence[int],
    key: Callable[[State], Hashable],
    limit: int | None = None,
) -> list[Exit]:
    """Every distinct (by ``key``) state a visit to ``step`` can end in, with its shortest
    action sequence. ``entry`` are the actions that move the pointer into the step.

    Raises :class:`VisitTooLarge` past ``limit`` distinct ends: a step whose presses store a
    value per programme while changing the programme reaches every combination of what it
    remembers, which can outgrow any memory.
    """
    tree = explore_tree(compiled, state, step, entry, key, limit)
    return [(end, tree.path(i)) for i, end in enumerate(tree.ends)]


class VisitTree:
    """The ends of one visit as a breadth-first tree: ``ends[i]`` is reached by the press
    ``actions[i]`` from ``ends[parents[i]]`` (-1: from the state the visit starts in), in
    ``lengths[i]`` presses. Why a tree: a clock walked one press at a time has ends hundreds
    of presses away, and copying each end's whole path costs time and memory quadratic in
    the walk; the search needs only the lengths, and the path of the plan it returns."""

    __slots__ = ("actions", "ends", "lengths", "parents")

    def __init__(self) -> None:
        self.ends: list[State] = []
        self.parents: list[int] = []
        self.actions: list[int] = []
        self.lengths: list[int] = []

    def path(self, i: int) -> tuple[int, ...]:
        """The presses from the visit's start to end ``i``."""
        presses = []
        while i >= 0:
            presses.append(self.actions[i])
            i = self.parents[i]
        return tuple(reversed(presses))


def explore_tree(
    compiled: CompiledModel,
    state: State,
    step: int,
    entry: Sequence[int],
    key: Callable[[State], Hashable],
    limit: int | None = None,
) -> VisitTree:
    """:func:`explore_visit`, its ends kept as a :class:`VisitTree` (same ends, same order)."""
    apply = compiled.apply
    seen: set[Hashable] = set()
    tree = VisitTree()
    ends, parents, actions, lengths = tree.ends, tree.parents, tree.actions, tree.lengths

    def expand(source: State, parent: int, length: int, pressed: Sequence[int]) -> None:
        for action in pressed:
            after = apply(source, action)
            if after is None:
                continue
            k = key(after)
            if k not in seen:
                seen.add(k)
                ends.append(after)
                parents.append(parent)
                actions.append(action)
                lengths.append(length)
                if limit is not None and len(seen) > limit:
                    raise VisitTooLarge(f"a visit to step {step} ends in over {limit} states")

    expand(state, -1, 1, entry)
    own = sorted(compiled.steps[step].actions)
    i = 0
    while i < len(ends):  # the ends list is the breadth-first queue
        expand(ends[i], i, lengths[i] + 1, own)
        i += 1
    return tree


def keypad_presses(buffer: str, target: str, entry: Entry, typed: bool = True) -> str | None:
    """The fewest digits to type so that the buffer reads ``target`` (zero-padding allowed).

    ``buffer`` is what is typed already (``typed=False`` when the visit starts fresh).

    >>> e = Entry(format="mm:ss")
    >>> keypad_presses("", "130", e), keypad_presses("13", "130", e), keypad_presses("99", "130", e)
    ('130', '0', '0130')
    """
    width = entry.digits()
    if not typed:
        buffer = ""
    best: str | None = None
    for padding in range(width - len(target) + 1):
        wanted = "0" * padding + target
        for option in _ways_to_reach(buffer, wanted, width, entry.overflow):
            if option and (best is None or len(option) < len(best)):
                best = option
    return best


def _ways_to_reach(buffer: str, wanted: str, width: int, overflow: str) -> list[str]:
    """Digit strings that turn ``buffer`` into exactly ``wanted``."""
    ways = []
    if wanted.startswith(buffer) and len(wanted) <= width:
        ways.append(wanted[len(buffer) :])  # keep typing
    if overflow == "shift" and len(wanted) == width:
        for typed in range(1, width + 1):
            kept = width - typed  # the oldest digits shift out
            if (
                kept <= len(buffer)
                and buffer[len(buffer) - kept :] == wanted[:kept]
                and len(buffer) + typed >= width
            ):
                ways.append(wanted[kept:])
        ways.append(wanted)  # enough digits replace the whole buffer
    return ways


def keypad_exits(
    compiled: CompiledModel, state: State, step: int, entry: Sequence[int], targets: Sequence[float]
) -> list[Exit]:
    """Exits of a keypad visit: each entry action alone; for each target magnitude, the fewest
    presses that leave the variable at it; and CLEAR, which resets the variable.

    Typing starts after an entering press (a digit there is already typed, so "5" then "40"
    reads 40 on a shifting buffer — the only way in when a guard admits just the 5 key) or,
    at the search's start, from the half-typed buffer; CLEAR and typing afresh may beat both.
    Only the shortest accepted way to each target is kept: the buffer it leaves is emptied as
    soon as the pointer moves on, which is the only thing a visit can do next.
    """
    info = compiled.steps[step]
    var = compiled.vars[info.variable]
    spec_entry = var.spec.entry  # type: ignore[union-attr]
    assert spec_entry is not None
    digit_action = {
        str(compiled.model.actions[compiled.action_names[a]].digit): a
        for a in info.actions
        if info.effects[a][0] == DIGIT
    }
    clear = next((a for a in sorted(info.actions) if info.effects[a][0] == CLEAR), None)
    # a key of the step that only empties the buffer (Entry.other_keys: clear)
    blank = next(
        (a for a in sorted(info.actions) if info.blank_clears and info.effects[a][0] == NONE),
        None,
    )
    exits: list[Exit] = []
    origins: dict[State, tuple[int, ...]] = {}  # where typing starts, and the presses so far
    if state.step == step:
        origins[state] = ()
    for action in entry:  # the cheapest way through: one action
        after = compiled.apply(state, action)
        if after is not None:
            exits.append((after, (action,)))
            if state.step != step:
                origins.setdefault(after, (action,))
    if clear is not None:  # CLEAR resets the variable, also after a press that showed or typed
        exits.extend(_first_accepted(compiled, state, [(*o, clear) for o in origins.values() if o]))
    for magnitude in targets:
        digits = entry_digits(magnitude, spec_entry)
        if digits is None:
            continue
        ways: list[tuple[int, ...]] = []
        for origin, prefix in origins.items():
            presses = keypad_presses(origin.buffer, digits, spec_entry)
            typed = _digit_actions(presses, digit_action)
            if typed:
                ways.append((*prefix, *typed))
            for restart in (clear, blank):
                if origin.buffer and restart is not None:
                    fresh = _digit_actions(keypad_presses("", digits, spec_entry), digit_action)
                    if fresh:
                        ways.append((*prefix, restart, *fresh))
        exits.extend(_first_accepted(compiled, state, ways))
    return exits


def _first_accepted(
    compiled: CompiledModel, state: State, ways: Sequence[tuple[int, ...]]
) -> list[Exit]:
    """The shortest of ``ways`` the appliance accepts press by press, with where it ends."""
    for path in sorted(ways, key=len):
        current: State | None = state
        for action in path:
            current = compiled.apply(current, action) if current is not None else None
        if current is not None:
            return [(current, path)]
    return []


def _digit_actions(presses: str | None, digit_action: dict[str, int]) -> tuple[int, ...]:
    """The digit keys that type ``presses`` (empty when there are none or a key is missing)."""
    if not presses or any(d not in digit_action for d in presses):
        return ()
    return tuple(digit_action[d] for d in presses)


def keypad_targets(compiled: CompiledModel, goal: CompiledGoal, v: int) -> list[float]:
    """Values worth typing into a keypad variable: its goal; values from which another step
    reaches the goal about as cheaply (type 3:00, then +30 s) — the one place the planner
    filters candidates by a cost argument instead of enumerating them; and, for each way
    the guards can see the variable (inside or outside each guard's values), the value with
    the fewest digits. Small domains offer every value."""
    var = compiled.vars[v]
    magnitudes: dict[float, None] = {}
    if v in goal.variables:
        name = var.name
        goal_value = goal.canonical[name]
        dist, _ = distances_to(compiled, v, goal_value)
        typeable = dict(typeable_values(compiled, v))
        direct = typeable.get(goal_value, INF)
        # typing z and adjusting it in another step pays only if it costs about as much
        # as typing the goal; the slack covers side effects that visit may bring along
        slack = 1 + sum(
            1 for step in compiled.steps for target, _ in step.side if target in goal.variables
        )
        for domain in var.domains:
            if domain is None or domain.magnitudes is None:
                continue
            ranked = sorted(
                (cost, i)
                for i, value in enumerate(domain.values)
                if value in typeable
                and (cost := typeable[value] + dist.get(value, INF)) <= direct + slack
            )
            for _, i in ranked[:SMALL_DOMAIN]:
                magnitudes[domain.magnitudes[i]] = None
    magnitudes.update(dict.fromkeys(_fewest_digit_values(compiled, v)))
    return list(magnitudes)


def _fewest_digit_values(compiled: CompiledModel, v: int) -> list[float]:
    """Per domain, every value of a small one, and of a large one the value with the fewest
    digits for each way the guards see the variable. It depends on the model alone, so it is
    computed once per model: a long range walked digit by digit on every plan was a tenth of
    the benchmark's time."""
    cache: dict[int, list[float]] = compiled.cache.setdefault("fewest_digits", {})
    if v in cache:
        return cache[v]
    var = compiled.vars[v]
    found: dict[float, None] = {}
    guard_sets = [ok for guard in compiled.guards for gv, ok in guard.conditions if gv == v]
    entry = getattr(var.spec, "entry", None)
    for domain in var.domains:
        if domain is None or domain.magnitudes is None:
            continue
        if len(domain) <= SMALL_DOMAIN:
            found.update(dict.fromkeys(domain.magnitudes))
            continue
        if entry is None:
            continue
        cheapest: dict[tuple[bool, ...], tuple[int, float]] = {}
        lengths = typed_lengths(domain.magnitudes, entry)
        for i, (magnitude, length) in enumerate(zip(domain.magnitudes, lengths, strict=True)):
            if length is None:
                continue
            seen_by_guards = tuple(i in ok for ok in guard_sets)
            if seen_by_guards not in cheapest or length < cheapest[seen_by_guards][0]:
                cheapest[seen_by_guards] = (length, magnitude)
        found.update(dict.fromkeys(m for _, m in cheapest.values()))
    cache[v] = list(found)
    return cache[v]
