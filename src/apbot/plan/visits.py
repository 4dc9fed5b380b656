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

from collections import deque
from collections.abc import Callable, Hashable, Sequence

from apbot.model.schema import Entry
from apbot.sim.compiled import CLEAR, DIGIT, CompiledModel, State, entry_digits

Exit = tuple[State, tuple[int, ...]]

# Above this many values, a variable's exits are restricted to useful candidates (keypads).
SMALL_DOMAIN = 64


def explore_visit(
    compiled: CompiledModel,
    state: State,
    step: int,
    entry: Sequence[int],
    key: Callable[[State], Hashable],
) -> list[Exit]:
    """Every distinct (by ``key``) state a visit to ``step`` can end in, with its shortest
    action sequence. ``entry`` are the actions that move the pointer into the step."""
    apply = compiled.apply
    seen: dict[Hashable, Exit] = {}
    queue: deque[Exit] = deque()

    def expand(source: State, path: tuple[int, ...], actions: Sequence[int]) -> None:
        for action in actions:
            after = apply(source, action)
            if after is None:
                continue
            k = key(after)
            if k not in seen:
                seen[k] = (after, (*path, action))
                queue.append(seen[k])

    expand(state, (), entry)
    own = sorted(compiled.steps[step].actions)
    while queue:
        current, path = queue.popleft()
        expand(current, path, own)
    return list(seen.values())


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
    """Exits of a keypad visit: the entry actions alone, then typing each target magnitude."""
    info = compiled.steps[step]
    var = compiled.vars[info.variable]
    spec_entry = var.spec.entry  # type: ignore[union-attr]
    assert spec_entry is not None
    digit_action = {
        str(compiled.model.actions[compiled.action_names[a]].digit): a
        for a in info.actions
        if info.effects[a][0] == DIGIT
    }
    exits: list[Exit] = []
    for action in entry:  # the cheapest way through: one action
        after = compiled.apply(state, action)
        if after is not None:
            exits.append((after, (action,)))
    continuing = state.step == step
    # continuing a half-typed buffer, CLEAR then typing afresh can beat typing on (a full
    # buffer that ignores new digits, or one that would need every digit shifted in)
    clear = next((a for a in sorted(info.actions) if info.effects[a][0] == CLEAR), None)
    if clear is not None and not continuing and (info.show_on_entry or clear not in entry):
        # CLEAR also resets the variable: enter (only showing, or typing), then CLEAR
        after_entry = compiled.apply(state, entry[0])
        cleared = compiled.apply(after_entry, clear) if after_entry is not None else None
        if cleared is not None:
            exits.append((cleared, (entry[0], clear)))
    for magnitude in targets:
        digits = entry_digits(magnitude, spec_entry)
        if digits is None:
            continue
        ways: list[tuple[int, ...]] = []
        presses = keypad_presses(state.buffer, digits, spec_entry, typed=continuing)
        typed = _digit_actions(presses, digit_action)
        if typed:
            if not continuing:
                if info.show_on_entry:
                    typed = (entry[0], *typed)  # the entering press only wakes the display
                elif typed[0] not in entry:
                    non_digit = [a for a in entry if info.effects[a][0] != DIGIT]
                    if not non_digit:
                        continue
                    typed = (non_digit[0], *typed)  # enter with a non-digit action, then type
            ways.append(typed)
        if continuing and state.buffer and clear is not None:
            fresh = _digit_actions(keypad_presses("", digits, spec_entry), digit_action)
            if fresh:
                ways.append((clear, *fresh))
        for path in ways:
            current: State | None = state
            for action in path:
                current = compiled.apply(current, action) if current is not None else None
            if current is not None:
                exits.append((current, path))
    return exits


def _digit_actions(presses: str | None, digit_action: dict[str, int]) -> tuple[int, ...]:
    """The digit keys that type ``presses`` (empty when there are none or a key is missing)."""
    if not presses or any(d not in digit_action for d in presses):
        return ()
    return tuple(digit_action[d] for d in presses)
