"""The parts of a drawn model that hold the rest back: a power key, START (running), a child
lock, a mode or a number that lets only some keys work — and the rule that the power key
always gets through. Split from :class:`apbot.testing.builder.Builder`, whose state these
methods share and whose draws they take in the same order."""

from __future__ import annotations

import random
from typing import TYPE_CHECKING, Any

from apbot.model.domain import all_values
from apbot.testing.variables import schema_var


class GuardedParts:
    """The guard-drawing half of :class:`apbot.testing.builder.Builder` (which sets these)."""

    rng: random.Random
    variables: dict[str, Any]
    controls: list[dict[str, Any]]
    actions: dict[str, Any]
    features: dict[str, list[dict[str, Any]]]
    guards: list[dict[str, Any]]
    anywhere: list[dict[str, Any]]
    power_key: str | None
    power_feature: str
    settings: list[str]

    if TYPE_CHECKING:

        def action(self, kind: str = "button", **extra: Any) -> str: ...

        def feature(self, steps: list[dict[str, Any]]) -> str: ...

    def _power_always_works(self) -> None:
        """Every other guard lets the power key through: with the power guard allowing only
        that key, a mode, a lock or a number that blocks it would leave an appliance switched
        off in that state with nothing that works, for good (the checker refuses such models)."""
        if not self.power_key:
            return
        for guard in self.guards:
            if guard["when"] != {"power": "off"} and self.power_key not in guard["only"]:
                guard["only"] = sorted([*guard["only"], self.power_key])

    def _add_power(self) -> None:
        """A power key guarding everything else; switching off may forget settings later."""
        self.variables["power"] = {"type": "discrete", "values": ["off", "on"]}
        self.power_key = self.action()
        self.power_feature = self.feature(
            [{"actions": [self.power_key], "variable": "power", "effect": "toggle"}]
        )
        guard: dict[str, Any] = {"when": {"power": "off"}, "only": [self.power_key]}
        if self.rng.random() < 0.5:
            guard["hide"] = True
            guard["display"] = ""
        self.guards.append(guard)

    def _add_running(self) -> None:
        """START (a toggle, or ON and a separate STOP); while running only those keys work."""
        rng = self.rng
        self.variables["running"] = {"type": "discrete", "values": ["off", "on"]}
        start = self.action()
        allowed = [start]
        anywhere = rng.random() < 0.3  # START from any screen, without leaving it

        def add(step: dict[str, Any]) -> None:
            if anywhere:
                self.anywhere.append(step)
            else:
                self.feature([step])

        if rng.random() < 0.5:
            add({"actions": [start], "variable": "running", "effect": "toggle"})
        else:
            stop = self.action()
            add({"actions": [start], "variable": "running", "effect": {"to": "on"}})
            step: dict[str, Any] = {
                "actions": [stop],
                "variable": "running",
                "effect": {"to": "off"},
            }
            if rng.random() < 0.5 and self.settings:
                step["reset"] = [rng.choice(self.settings)]  # CANCEL forgets a setting
            if anywhere and rng.random() < 0.5:
                step["leave"] = True
            add(step)
            allowed.append(stop)
        if self.power_key is not None:
            allowed.append(self.power_key)
            if rng.random() < 0.5:  # switching off stops the programme
                self.features[self.power_feature][0]["set"] = {"running": "off"}
        self.guards.append({"when": {"running": "on"}, "only": allowed, "display": "RUN"})

    def _add_lock(self) -> None:
        """A child lock on a hold, possibly of two controls; while locked only the hold works."""
        rng = self.rng
        self.variables["lock"] = {"type": "discrete", "values": ["off", "on"]}
        if rng.random() < 0.5 and len(self.controls) >= 2:
            a, b = rng.sample([c["id"] for c in self.controls], 2)
            name = f"a{len(self.actions)}"
            self.actions[name] = {"controls": [a, b], "skill": "hold", "seconds": 3}
        else:
            name = self.action(skill="hold", seconds=2)
            if rng.random() < 0.3:
                self.actions[name]["too_short"] = "enters"
        lock_step = {"actions": [name], "variable": "lock", "effect": "toggle"}
        if rng.random() < 0.3:  # a lock hold that belongs to no procedure
            self.anywhere.append(lock_step)
        else:
            self.feature([lock_step])
        allowed = [name] + ([self.power_key] if self.power_key and rng.random() < 0.5 else [])
        self.guards.append({"when": {"lock": "on"}, "only": allowed, "display": "LOCKED"})

    def _add_mode_guard(self) -> None:
        """A discrete setting whose value allows only some keys (its own among them), as a
        mode switch does: in mode A the programme keys do nothing."""
        rng = self.rng
        discrete = [
            v
            for v in self.settings
            if self.variables[v]["type"] == "discrete" and "depends_on" not in self.variables[v]
        ]
        if not discrete:
            return
        name = rng.choice(discrete)
        spec = self.variables[name]
        values = spec["values"]
        blocked = rng.sample(values, rng.randint(1, len(values) - 1))
        own = [
            a
            for steps in self.features.values()
            if any(step.get("variable") == name for step in steps)
            for step in steps
            for a in step["actions"]
        ]
        others = [a for a in self.actions if a not in own]
        allowed = sorted(set(own) | set(rng.sample(others, rng.randint(0, len(others)))))
        self.guards.append({"when": {name: blocked}, "only": allowed})

    def _add_number_guard(self) -> None:
        """A number's lowest values allow only its own keys ("set a time before starting")."""
        numeric = [
            v
            for v in self.settings
            if self.variables[v]["type"] == "numeric" and "depends_on" not in self.variables[v]
        ]
        if not numeric:
            return
        name = self.rng.choice(numeric)
        lowest = all_values(schema_var(self.variables[name]))[: self.rng.randint(1, 3)]
        own: set[str] = set()  # its keys, and the keys entering its features
        for steps in self.features.values():
            adjusting = [step for step in steps if step.get("variable") == name]
            if adjusting:
                own.update(steps[0]["actions"])
                own.update(a for step in adjusting for a in step["actions"])
        self.guards.append({"when": {name: lowest}, "only": sorted(own)})
