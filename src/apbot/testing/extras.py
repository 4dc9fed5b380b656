"""Format parts sprinkled over a drawn model after the generator's first version (scrolling
holds, conditional effects, one-position guards, remembered settings, self-ending cycles)."""

from __future__ import annotations

import random
from typing import TYPE_CHECKING, Any

from apbot.testing.variables import some_values

if TYPE_CHECKING:
    from apbot.testing.builder import Builder


class Extras:
    """Parts of the format added after the generator's first version, sprinkled over a drawn
    model: a held key scrolling several values (``skip``), effects that depend on the state
    (``when``/``then``/``otherwise``), and guards that let keys work in one position of a
    mode only (``other_than``), settings remembered per programme (``remember``), and
    cycles that end by themselves (``cycles``)."""

    def __init__(self, builder: Builder, rng: random.Random) -> None:
        self.builder = builder
        self.rng = rng

    def add(self) -> None:
        if self.rng.random() < 0.3:
            self._hold_to_scroll()
        if self.rng.random() < 0.35:
            self._conditional()
        if self.rng.random() < 0.5:
            self._one_position()
        if "running" in self.builder.variables and self.rng.random() < 0.5:
            self._cycle()
        dependents = [n for n, v in self.builder.variables.items() if "depends_on" in v]
        if dependents and self.rng.random() < 0.5:  # a setting kept per programme (zone)
            self.builder.variables[self.rng.choice(dependents)]["remember"] = True

    def _conditional(self) -> None:
        """One key's effect depends on an independent variable (its own, a mode, power)."""
        b = self.builder
        guarded = {n for g in b.guards for n in g["when"]}  # their release stays unconditional
        steps = [s for s in self._adjusting() if s["variable"] not in guarded]
        readable = [n for n, v in b.variables.items() if "depends_on" not in v]
        if not steps or not readable:
            return
        step = self.rng.choice(steps)
        key = self.rng.choice(step["actions"])
        name = self.rng.choice(readable)
        values = some_values(b.variables[name])
        chosen = self.rng.sample(values, self.rng.randint(1, max(1, len(values) - 1)))
        condition: Any = chosen[0] if len(chosen) == 1 else chosen
        if self.rng.random() < 0.3:
            condition = {"other_than": chosen[0]}
        otherwise = self.rng.choice(["none", "next", "prev", "reset"])
        step["effect"][key] = {
            "when": {name: condition},
            "then": step["effect"][key],
            "otherwise": otherwise,
        }

    def _cycle(self) -> None:
        """Running ends by itself after a time or number setting (presses take no time, so
        it never ends during a plan: the planner and BFS must agree all the same)."""
        b = self.builder
        lengths = [
            n
            for n, v in b.variables.items()
            if "depends_on" not in v
            and (v["type"] == "time" or (v["type"] == "numeric" and v.get("unit") == "min"))
        ]
        if lengths:
            cycle: dict[str, Any] = {"when": {"running": "on"}, "lasts": self.rng.choice(lengths)}
            cycle["set"] = {"running": "off"}
            if self.rng.random() < 0.5:
                cycle["reset"] = [cycle["lasts"]]
            b.cycles.append(cycle)

    def _one_position(self) -> None:
        """A mode guard becomes one whose keys work in one position only (``other_than``)."""
        b = self.builder
        for guard in b.guards:
            [(name, blocked)] = list(guard["when"].items())[:1] or [(None, None)]
            spec = b.variables.get(name) if name else None
            if isinstance(blocked, list) and spec and spec["type"] == "discrete":
                free = [v for v in spec["values"] if v not in blocked]
                guard["when"] = {name: {"other_than": self.rng.choice(free)}}
                return

    def _adjusting(self) -> list[dict[str, Any]]:
        """Steps that adjust a variable by effects of their own (not keypad digits)."""
        return [
            step
            for steps in self.builder.features.values()
            for step in steps
            if step.get("variable")
            and isinstance(step.get("effect"), dict)
            and set(step["effect"]) == set(step["actions"])  # a map from action to effect
            and "digit" not in step["effect"].values()
        ]

    def _hold_to_scroll(self) -> None:
        """Holding one of a step's keys (pressed, it moves one value) moves several at once."""
        b = self.builder
        keys = [
            (step, key)
            for step in self._adjusting()
            for key in step["actions"]
            if b.actions[key].get("skill", "press") == "press" and "control" in b.actions[key]
        ]
        if not keys:
            return
        step, key = self.rng.choice(keys)
        name = f"a{len(b.actions)}"
        b.actions[name] = {"control": b.actions[key]["control"], "skill": "hold", "seconds": 2}
        step["actions"].append(name)
        step["effect"][name] = {"skip": self.rng.choice([2, 3, -2, 5])}
