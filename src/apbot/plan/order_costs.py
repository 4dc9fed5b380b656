"""Which of two plans of the same length the search takes: the one in the order people operate.

Plans that press the same number of keys often differ only in the order of their parts (set the
temperature, then start; or start, then set the temperature). The search used to take whichever
it generated first, and that followed the order the actions happened to be listed in. These
costs, far below one press, make the choice one of meaning:

* the run last — a change of the run state (START, STOP) while another goal setting is still
  unmet costs one unit: settings made while it runs may be refused or come too late;
* the clock first — changing another time of day of the goal (a READY AT 0:00–23:50, not a
  duration) while the clock's goal is unmet costs one unit: a finish time is counted from the
  clock, so setting the clock later can move it.

A run state is a variable named for the run (running, heating…), a clock one named clock: the
names models and the reader give them.
"""

from __future__ import annotations

from collections.abc import Sequence

from apbot.plan.goals import CompiledGoal
from apbot.sim.compiled import CompiledModel

RUN_WORDS = ("running", "heating", "dispensing", "brewing", "cooking", "status")
CLOCK_WORDS = ("clock",)

Wanted = tuple[int, int, tuple[int, ...]]  # variable, its parent (-1: none), goal index per case


class OrderCosts:
    """The sub-press cost of one edge of the search, from the goal's run states and clock."""

    def __init__(self, compiled: CompiledModel, goal: CompiledGoal) -> None:
        run: list[Wanted] = []
        clock: list[Wanted] = []
        other: list[Wanted] = []
        of_day: list[Wanted] = []
        for name, v, wanted in zip(goal.names, goal.variables, goal.wanted, strict=True):
            item = (v, compiled.vars[v].parent, wanted)
            if any(w in name for w in RUN_WORDS):
                run.append(item)
            elif any(w in name for w in CLOCK_WORDS):
                clock.append(item)
            else:
                other.append(item)
                if _of_day(compiled, v):
                    of_day.append(item)
        self.run, self.clock, self.other = tuple(run), tuple(clock), tuple(other)
        self.of_day = tuple(of_day)
        self.active = bool(run and (clock or other)) or bool(clock and of_day)

    def __call__(self, before: Sequence[int], after: Sequence[int]) -> int:
        """1 when the edge from ``before`` to ``after`` breaks the order (0 if not)."""
        if not self.active:
            return 0
        if (
            self.run
            and _changed(self.run, before, after)
            and not (_hold(self.other, after) and _hold(self.clock, after))
        ):
            return 1
        if self.of_day and _changed(self.of_day, before, after) and not _hold(self.clock, before):
            return 1
        return 0


DAY = 24 * 3600
LATE = 23 * 3600


def _of_day(compiled: CompiledModel, v: int) -> bool:
    """A time of day: a time setting whose every case runs to the day's last hour and stops
    short of 24:00 (a 0–24 h timer ends at 24:00 and stays a duration)."""
    domains = [d for d in compiled.vars[v].domains if d is not None]
    return bool(domains) and all(
        d.kind == "time" and d.magnitudes and LATE <= max(d.magnitudes) < DAY for d in domains
    )


def _changed(items: tuple[Wanted, ...], before: Sequence[int], after: Sequence[int]) -> bool:
    return any(before[v] != after[v] for v, _, _ in items)


def _hold(items: tuple[Wanted, ...], values: Sequence[int]) -> bool:
    for v, parent, wanted in items:
        index = values[v]
        if index < 0 or wanted[values[parent] if parent >= 0 else 0] != index:
            return False
    return True
