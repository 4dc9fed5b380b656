"""Random small appliance models and goals, for checking the planner against brute force.

The models use every part of the format a planner has to get right: discrete, numeric and time
variables, piecewise ranges, wrap and clamp, keypads (numbers and times, a CLEAR key),
programme-dependent settings (a programme chosen by a cycling key, a dial or go-to keys, a
programme without a case), entry steps, confirm steps, ``on_entry: show``, go-to, add, reset,
toggle and ``none`` effects, holds and two-control holds (some entering when released early),
dial turns, side effects (``set``, ``reset``) on any step, optional steps, keys that act from
anywhere (some leaving the procedure), step timeouts with a wait, keypads whose other keys
clear the typing, and guards — power off, a child lock, "only these keys while running",
a mode that allows only some keys, a number that must be set first. They stay small enough
(mostly a few thousand states) for breadth-first search over the whole simulator.
Generation is driven by a ``random.Random`` so a failing case is reproducible from its seed;
:func:`format_parts` says which parts a model uses, so tests can check the generator's reach.
"""

from __future__ import annotations

import random
from typing import Any

from pydantic import TypeAdapter

from apbot.model.domain import all_values, build_domain
from apbot.model.schema import (
    Add,
    ApplianceModel,
    Conditional,
    GoTo,
    OtherThan,
    Skip,
    Variable,
)
from apbot.model.validate import reachable_indices
from apbot.sim.checks import guard_problems
from apbot.sim.compiled import compiled_model
from apbot.testing.bfs import random_walk

# What :func:`format_parts` can report; the generator is tested to produce every one.
FORMAT_PARTS = (
    "add",
    "anywhere key",
    "leave key",
    "optional step",
    "short hold enters",
    "timeout",
    "keypad other keys clear",
    "keypad shows typed",
    "clamp",
    "conditional effect",
    "confirm step",
    "cycling programme key",
    "dependent setting",
    "dial",
    "entry step",
    "go-to",
    "go-to programme key",
    "hidden display",
    "hold",
    "keypad",
    "keypad clear",
    "large domain",
    "lock guard",
    "missing case",
    "mode guard",
    "none effect",
    "number guard",
    "on_entry show",
    "one-position guard",
    "piecewise",
    "power guard",
    "prev",
    "remembered setting",
    "reset effect",
    "reset side effect",
    "running guard",
    "set side effect",
    "skip",
    "time",
    "time keypad",
    "timed cycle",
    "toggle",
    "two-control hold",
    "two programmes",
    "unreachable values",
    "wrap",
)

_VARIABLE: TypeAdapter[Any] = TypeAdapter(Variable)


def random_model(rng: random.Random, max_states: int = 30_000) -> ApplianceModel:
    """A schema-valid model with all references resolved (semantic checks may still warn),
    with at most ``max_states`` states (:func:`state_bound`) and no guard that holds for good
    (:func:`apbot.sim.checks.guard_problems`): other draws are discarded and drawn again from
    the same ``rng``, so such cases are not generated at all."""
    for _ in range(1_000):
        model = _Builder(rng).build()
        if state_bound(model) <= max_states and not guard_problems(model):
            return model  # (guards that together lock the appliance for good are drawn again)
    raise ValueError(f"no model with at most {max_states} states in 1,000 draws; allow more")


def state_bound(model: ApplianceModel) -> int:
    """An upper bound on the number of states: every combination of values (a dependent
    setting counts its largest case, plus "absent"; a remembered one every combination of
    its cases' values), times every pointer position, where a
    keypad step counts once per buffer it can hold."""
    total = 1
    for var in model.variables.values():
        if var.depends_on is None:
            total *= len(build_domain(var))
        else:
            parent = build_domain(model.variables[var.depends_on]).values
            cases = var.cases or {}
            if var.remember:  # a value kept for every programme (the current one shown)
                for case in cases.values():
                    total *= len(build_domain(var, case))
                continue
            total *= max(len(build_domain(var, c)) for c in cases.values()) + (
                len(cases) < len(parent)
            )
    positions = 1  # no feature entered yet
    for steps in model.features.values():
        for step in steps:
            entry = None
            if step.variable is not None:
                entry = getattr(model.variables[step.variable], "entry", None)
            positions += 1 if entry is None else sum(10**k for k in range(entry.digits() + 1))
    return total * positions


class _Builder:
    """Collects the parts of one model; each ``_add_*`` method adds one kind of part."""

    def __init__(self, rng: random.Random) -> None:
        self.rng = rng
        self.variables: dict[str, Any] = {}
        self.controls: list[dict[str, Any]] = []
        self.actions: dict[str, Any] = {}
        self.features: dict[str, list[dict[str, Any]]] = {}
        self.guards: list[dict[str, Any]] = []
        self.cycles: list[dict[str, Any]] = []
        self.arrows: tuple[str, str] | None = None  # one ▲/▼ pair shared by several steps
        self.digits: list[str] | None = None  # one keypad shared by every keypad step
        self.anywhere: list[dict[str, Any]] = []
        self.power_key: str | None = None
        self.power_feature = ""
        self.settings: list[str] = []  # variables with features of their own

    # --- pieces ----------------------------------------------------------------------------

    def action(self, kind: str = "button", **extra: Any) -> str:
        index = len(self.actions)
        control = f"c{index}"
        self.controls.append({"id": control, "kind": kind, "label": control.upper()})
        name = f"a{index}"
        self.actions[name] = {"control": control, **extra}
        return name

    def dial(self) -> tuple[str, str]:
        """A dial's two turns (one control)."""
        control = f"c{len(self.actions)}"
        self.controls.append({"id": control, "kind": "dial", "label": control.upper()})
        turns = []
        for skill in ("turn_cw", "turn_ccw"):
            name = f"a{len(self.actions)}"
            self.actions[name] = {"control": control, "skill": skill}
            turns.append(name)
        return turns[0], turns[1]

    def arrows_pair(self) -> tuple[str, str]:
        if self.arrows is None or self.rng.random() < 0.3:
            self.arrows = (self.action(), self.action())
        return self.arrows

    def keypad(self) -> list[str]:
        if self.digits is None:
            self.digits = [self.action("key", digit=d) for d in range(10)]
        return self.digits

    def feature(self, steps: list[dict[str, Any]]) -> str:
        name = f"f{len(self.features)}"
        self.features[name] = steps
        return name

    def model(self) -> ApplianceModel:
        return ApplianceModel.model_validate(
            {
                "appliance": {"id": "generated", "category": "generated"},
                "controls": self.controls,
                "variables": self.variables,
                "actions": self.actions,
                "features": self.features,
                "anywhere": self.anywhere,
                "guards": self.guards,
                "cycles": self.cycles,
            }
        )

    # --- the whole model -------------------------------------------------------------------

    def build(self) -> ApplianceModel:
        rng = self.rng
        if rng.random() < 0.4:
            self._add_power()
        programmes = []
        if rng.random() < 0.5:  # a programme; sometimes a second one (two cooking zones)
            programmes.append(self._add_programme("prog"))
            if rng.random() < 0.4:
                programmes.append(self._add_programme("zone"))
        for i in range(rng.randint(1, 3 - len(programmes))):
            name = f"v{i}"
            self.variables[name] = _plain_variable(rng)
            self.settings.append(name)
        for programme, prefix in zip(programmes, "de", strict=False):
            for j in range(rng.randint(1, 2 if programme == "prog" else 1)):
                name = f"{prefix}{j}"
                self.variables[name] = _dependent_variable(rng, programme, self.variables)
                self.settings.append(name)
        for name in self.settings:
            for _ in range(rng.randint(1, 2)):
                self._add_setting_feature(name)
        if self.power_key is not None and rng.random() < 0.4:  # switching off forgets
            forgotten = rng.sample(self.settings, rng.randint(1, min(2, len(self.settings))))
            self.features[self.power_feature][0]["reset"] = forgotten
        if rng.random() < 0.3:
            self._add_running()
        if rng.random() < 0.25:
            self._add_lock()
        if rng.random() < 0.25:
            self._add_mode_guard()
        if rng.random() < 0.15:
            self._add_number_guard()
        if rng.random() < 0.3:
            self._add_side_effect_key()
        if rng.random() < 0.25:
            self._add_anywhere_key()
        if rng.random() < 0.25:
            self._add_timeouts()
        # newer parts of the format come from a second generator seeded by what was drawn,
        # so that every earlier seed still draws the same model underneath
        _Extras(self, random.Random(repr((self.variables, self.features)))).add()
        if len(self.actions) % 2 == 0:  # decided without a draw: earlier seeds keep their models
            self._mark_unreachable()
        self._power_always_works()
        return self.model()

    def _power_always_works(self) -> None:
        """Every other guard lets the power key through: with the power guard allowing only
        that key, a mode, a lock or a number that blocks it would leave an appliance switched
        off in that state with nothing that works, for good (the checker refuses such models)."""
        if not self.power_key:
            return
        for guard in self.guards:
            if guard["when"] != {"power": "off"} and self.power_key not in guard["only"]:
                guard["only"] = sorted([*guard["only"], self.power_key])

    def _add_anywhere_key(self) -> None:
        """A key that acts from any screen: a go-to, a step or a reset of a setting (an EXPRESS
        key), or a CANCEL that only leaves the procedure (sometimes forgetting a setting)."""
        rng = self.rng
        plain = [
            v
            for v in self.settings
            if "depends_on" not in self.variables[v] and "entry" not in self.variables[v]
        ]
        if plain and rng.random() < 0.6:
            name = rng.choice(plain)
            effect = rng.choice(
                ["next", "reset", {"to": rng.choice(_some_values(self.variables[name]))}]
            )
            entry: dict[str, Any] = {"actions": [self.action()], "variable": name, "effect": effect}
            if rng.random() < 0.3:
                entry["leave"] = True
        else:
            entry = {"actions": [self.action()], "leave": True}
            if rng.random() < 0.4:
                self._side_effects(entry, exclude="")
        self.anywhere.append(entry)

    def _add_timeouts(self) -> None:
        """A wait of some seconds, and steps that time out back to no feature after it (or,
        for some, only after a longer wait that is not declared)."""
        rng = self.rng
        seconds = rng.choice([2, 5])
        name = f"a{len(self.actions)}"
        self.actions[name] = {"skill": "wait", "seconds": seconds}
        for steps in self.features.values():
            for step in steps:
                if rng.random() < 0.4:
                    step["timeout"] = rng.choice([seconds, seconds, 10])
        self._add_idle_meaning(seconds)

    def _add_idle_meaning(self, seconds: int) -> None:
        """Sometimes a key of a procedure's later step also starts a procedure of its own from
        no feature (UP sets the timer inside TIMER, the volume from the clock): inside the
        first procedure, only its timeout leads to the second."""
        rng = self.rng
        firsts = {a for steps in self.features.values() for a in steps[0]["actions"]}
        plain = [
            v
            for v in self.settings
            if "depends_on" not in self.variables[v] and "entry" not in self.variables[v]
        ]
        hosts = [steps for steps in self.features.values() if len(steps) >= 2]
        if not plain or not hosts or rng.random() < 0.5:
            return
        steps = rng.choice(hosts)
        keys = [
            a for a in steps[1]["actions"] if a not in firsts and "digit" not in self.actions[a]
        ]
        if not keys:
            return
        for step in steps:
            step["timeout"] = seconds
        self.feature(
            [{"actions": [rng.choice(keys)], "variable": rng.choice(plain), "effect": "next"}]
        )

    def _mark_unreachable(self) -> None:
        """Declare the values no key reaches ``unreachable`` (an automatic programme's own
        stages): a go-to key per programme for only some programmes leaves some out."""
        model = self.model()
        for name in model.variables:
            found: set[Any] = set()
            for domain in _case_domains(model, name):
                reached = reachable_indices(model, name, domain)
                found.update(v for i, v in enumerate(domain.values) if i not in reached)
            defaults = {d.values[d.initial] for d in _case_domains(model, name)}
            if found - defaults:
                self.variables[name]["unreachable"] = sorted(found - defaults, key=str)

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

    def _add_programme(self, name: str) -> str:
        """A programme chosen by a cycling key, a dial, or one go-to key per programme."""
        rng = self.rng
        values = [f"p{j}" for j in range(rng.randint(2, 4))]
        self.variables[name] = {
            "type": "discrete",
            "values": values,
            "initial": rng.choice(values),
            "wrap": rng.random() < 0.7,
        }
        self.settings.append(name)  # more features may come with the other settings
        how = rng.choice(["cycle", "dial", "goto", "goto"])
        separate = how == "goto" and rng.random() < 0.5
        entry = [{"actions": [self.action()]}] if not separate and rng.random() < 0.3 else []
        if how == "cycle":
            step: dict[str, Any] = {
                "actions": [self.action()],
                "variable": name,
                "effect": "next",
            }
            if rng.random() < 0.3:
                step["on_entry"] = "show"
            self.feature([*entry, step])
        elif how == "dial":
            cw, ccw = self.dial()
            self.feature(
                [
                    *entry,
                    {"actions": [cw, ccw], "variable": name, "effect": {cw: "next", ccw: "prev"}},
                ]
            )
        elif separate:  # one feature per programme key (POPCORN, PIZZA…)
            for value in rng.sample(values, rng.randint(1, len(values))):
                key = self.action()
                self.feature([{"actions": [key], "variable": name, "effect": {"to": value}}])
        else:  # the keys share one step
            keys = {self.action(): {"to": value} for value in values}
            self.feature([*entry, {"actions": list(keys), "variable": name, "effect": keys}])
        return name

    def _add_setting_feature(self, name: str) -> None:
        """A procedure adjusting ``name`` (sometimes a second variable after it), with an entry
        key sometimes, a confirm key sometimes, and side effects sometimes."""
        rng = self.rng
        steps: list[dict[str, Any]] = []
        # "press TEMP, then ▲/▼" is how most programme-dependent settings are adjusted
        if rng.random() < (0.75 if "depends_on" in self.variables[name] else 0.5):
            steps.append({"actions": [self.action()]})
        steps.append(self._adjusting_step(name))
        others = [v for v in self.settings if v != name]
        if others and rng.random() < 0.25:
            if rng.random() < 0.5:
                steps.append({"actions": [self.action()]})
            steps.append(self._adjusting_step(rng.choice(others)))
        if rng.random() < 0.2:
            steps.append({"actions": [self.action()]})
        if len(steps) >= 3 and rng.random() < 0.5:  # press HR, or go straight on to MIN
            steps[rng.randrange(1, len(steps) - 1)]["optional"] = True
        self.feature(steps)

    def _adjusting_step(self, name: str) -> dict[str, Any]:
        rng = self.rng
        var = self.variables[name]
        step: dict[str, Any] = {"actions": [], "variable": name}
        if "entry" in var:
            effects: dict[str, Any] = dict.fromkeys(self.keypad(), "digit")
            if rng.random() < 0.3:
                effects[self.action()] = "clear"
            if var["entry"].get("other_keys") == "clear" and rng.random() < 0.7:
                effects[self.action()] = "none"  # a key that only ends the typing
            step["actions"] = list(effects)
            if len(effects) > 10 or rng.random() < 0.5:  # else the default effect: digits
                step["effect"] = effects
        else:
            effects = {}
            shape = rng.random()
            if shape < 0.4:
                up, down = self.arrows_pair()
                effects = {up: "next", down: "prev"}
            elif shape < 0.55:
                cw, ccw = self.dial()
                effects = {cw: "next", ccw: "prev"}
            else:
                hold: dict[str, Any] = (
                    {"skill": "hold", "seconds": 1} if rng.random() < 0.15 else {}
                )
                if hold and rng.random() < 0.5:
                    hold["too_short"] = "enters"
                two = _value_count(var) == 2 and rng.random() < 0.4
                effects[self.action(**hold)] = (
                    "toggle" if two else rng.choice(["next", "next", "prev", "reset"])
                )
            if var["type"] != "discrete" and rng.random() < 0.3:
                effects[self.action()] = {"add": _add_amount(rng, var)}
            if rng.random() < 0.2:
                effects[self.action()] = {"to": rng.choice(_some_values(var))}
            if rng.random() < 0.1:
                effects[self.action()] = "none"
            step["actions"] = list(effects)
            step["effect"] = effects
        if rng.random() < 0.2:
            step["on_entry"] = "show"
        if rng.random() < 0.15:
            self._side_effects(step, exclude=name)
        return step

    def _side_effects(self, step: dict[str, Any], exclude: str) -> None:
        """``set`` or ``reset`` of other variables, as SET TEMP resetting the timer does (and
        RESET ALL resetting both zones' programmes)."""
        targets = [v for v in self.variables if v != exclude]
        if not targets:
            return
        chosen = self.rng.sample(targets, min(len(targets), self.rng.choice([1, 1, 2])))
        for target in chosen:
            spec = self.variables[target]
            if "depends_on" in spec or self.rng.random() < 0.5:
                step.setdefault("reset", []).append(target)
            else:
                step.setdefault("set", {})[target] = self.rng.choice(_some_values(spec))

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
        lowest = all_values(_schema_var(self.variables[name]))[: self.rng.randint(1, 3)]
        own: set[str] = set()  # its keys, and the keys entering its features
        for steps in self.features.values():
            adjusting = [step for step in steps if step.get("variable") == name]
            if adjusting:
                own.update(steps[0]["actions"])
                own.update(a for step in adjusting for a in step["actions"])
        self.guards.append({"when": {name: lowest}, "only": sorted(own)})

    def _add_side_effect_key(self) -> None:
        """A key whose only job is a side effect: RESET ALL, a preset, a programme reset."""
        step: dict[str, Any] = {"actions": [self.action()]}
        self._side_effects(step, exclude="")
        if "set" in step or "reset" in step:
            self.feature([step])


class _Extras:
    """Parts of the format added after the generator's first version, sprinkled over a drawn
    model: a held key scrolling several values (``skip``), effects that depend on the state
    (``when``/``then``/``otherwise``), and guards that let keys work in one position of a
    mode only (``other_than``), settings remembered per programme (``remember``), and
    cycles that end by themselves (``cycles``)."""

    def __init__(self, builder: _Builder, rng: random.Random) -> None:
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
        values = _some_values(b.variables[name])
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


def _ranges(rng: random.Random) -> list[list[int]]:
    start = rng.choice([0, 1, 5, 10])
    step = rng.choice([1, 2, 5])
    first = [start, start + step * rng.randint(1, 3), step]
    if rng.random() < 0.5:
        return [first]
    step2 = step * rng.choice([2, 3])
    return [first, [first[1], first[1] + step2 * rng.randint(1, 3), step2]]


def _plain_variable(rng: random.Random) -> dict[str, Any]:
    wrap = rng.random() < 0.5
    kind = rng.choice(
        ["discrete", "discrete", "numeric", "time", "keypad", "time keypad", "large", "mode"]
    )
    if kind == "discrete":
        values = [f"x{j}" for j in range(rng.randint(2, 4))]
        return {"type": "discrete", "values": values, "wrap": wrap, "initial": rng.choice(values)}
    if kind == "mode":
        return {"type": "discrete", "values": ["m0", "m1"]}
    if kind == "numeric":
        return {"type": "numeric", "ranges": _ranges(rng), "wrap": wrap, "unit": "min"}
    if kind == "large":  # more values than the planner enumerates cheaply (> 64)
        return {"type": "numeric", "ranges": [[0, rng.choice([70, 100]), 1]], "wrap": wrap}
    if kind == "time":
        return {
            "type": "time",
            "wrap": wrap,
            "ranges": [["00:00:00", "00:02:00", 30], ["00:02:00", "00:04:00", 60]],
        }
    if kind == "time keypad":
        fmt, digits, ranges = rng.choice(
            [
                ("mm:ss", 3, [["00:00:00", "00:01:30", 30]]),
                ("mm:ss", 2, [["00:00:10", "00:00:50", 10], ["00:00:50", "00:02:00", 70]]),
                ("minutes", rng.choice([1, 2]), [["00:00:00", "00:05:00", 60]]),
            ]
        )
        overflow = rng.choice(["shift", "ignore"])
        entry = {"format": fmt, "max_digits": digits, "overflow": overflow}
        if rng.random() < 0.4:
            entry["other_keys"] = "clear"
        if rng.random() < 0.4:
            entry["shows"] = "typed"
        return {"type": "time", "ranges": ranges, "entry": entry}
    top, step = rng.choice([(9, 1), (12, 3), (20, 5), (120, 30)])
    return {
        "type": "numeric",
        "ranges": [[0, top, step]],
        "entry": {
            "format": "number",
            "max_digits": rng.choice([2, 2, 3]),
            "overflow": rng.choice(["shift", "ignore"]),
            "other_keys": rng.choice(["keep", "keep", "clear"]),
            "shows": rng.choice(["value", "value", "typed"]),
        },
    }


def _dependent_variable(
    rng: random.Random, parent: str, variables: dict[str, Any]
) -> dict[str, Any]:
    """A setting with one domain per programme (sometimes none for one): value names shared
    across programmes with different defaults, so changing programme can be a shortcut."""
    parent_values = variables[parent]["values"]
    wrap = rng.random() < 0.5
    numeric = rng.random() < 0.3
    cases: dict[str, Any] = {}
    for value in parent_values:
        if rng.random() < 0.15 and (cases or value != parent_values[-1]):
            continue  # this programme has no such setting
        if numeric:
            top = rng.randint(2, 4)
            cases[value] = {"ranges": [[0, top, 1]], "initial": rng.randint(0, top)}
        else:
            size = rng.randint(2, 4)
            cases[value] = {
                "values": [f"y{j}" for j in range(size)],
                "initial": f"y{rng.randrange(size)}",
            }
    kind = "numeric" if numeric else "discrete"
    return {"type": kind, "depends_on": parent, "cases": cases, "wrap": wrap}


def _case_domains(model: ApplianceModel, name: str) -> list[Any]:
    var = model.variables[name]
    if var.depends_on is None:
        return [build_domain(var)]
    return [build_domain(var, case) for case in (var.cases or {}).values()]


def _value_count(var: dict[str, Any]) -> int:
    if "values" in var:
        return len(var["values"])
    return 0


def _some_values(var: dict[str, Any]) -> list[Any]:
    """Values a ``to:`` or ``set:`` may name: in every case of a dependent variable."""
    if "values" in var:
        return list(var["values"])
    if "cases" in var:
        domains = [build_domain(_schema_var(var), case) for case in _schema_var(var).cases.values()]
        common = set(domains[0].values).intersection(*(d.values for d in domains[1:]))
        return sorted(common, key=str) or list(domains[0].values)
    return all_values(_schema_var(var))


def _schema_var(var: dict[str, Any]) -> Any:
    return _VARIABLE.validate_python(var)


def _add_amount(rng: random.Random, var: dict[str, Any]) -> Any:
    if var["type"] == "time":
        return rng.choice([30, 60, -30, "00:01:00"])
    return rng.choice([1, 2, 5, 10, -1])


def format_parts(model: ApplianceModel) -> set[str]:
    """The parts of the format a model uses (names from :data:`FORMAT_PARTS`)."""
    parts: set[str] = set()
    parents = {v.depends_on for v in model.variables.values() if v.depends_on}
    if len(parents) > 1:
        parts.add("two programmes")
    if model.cycles:
        parts.add("timed cycle")
    for var in model.variables.values():
        if var.unreachable:
            parts.add("unreachable values")
        if var.remember:
            parts.add("remembered setting")
        if var.depends_on:
            parts.add("dependent setting")
            parent_values = build_domain(model.variables[var.depends_on]).values
            if set(parent_values) - set(var.cases or {}):
                parts.add("missing case")
        if getattr(var, "entry", None) is not None:
            parts.add("time keypad" if var.type == "time" else "keypad")
        if var.type == "time":
            parts.add("time")
        ranges = getattr(var, "ranges", None) or []
        if len(ranges) > 1:
            parts.add("piecewise")
        if var.depends_on is None and len(build_domain(var)) > 64:
            parts.add("large domain")
        parts.add("wrap" if var.wrap else "clamp")
    for action in model.actions.values():
        if action.skill == "hold":
            parts.add("two-control hold" if action.controls else "hold")
        if action.too_short == "enters":
            parts.add("short hold enters")
        if action.skill in ("turn_cw", "turn_ccw"):
            parts.add("dial")
    for entry in model.anywhere:
        parts.add("anywhere key")
        if entry.leave:
            parts.add("leave key")
    for var in model.variables.values():
        if getattr(var, "entry", None) is not None and var.entry.other_keys == "clear":  # type: ignore[union-attr]
            parts.add("keypad other keys clear")
        if getattr(var, "entry", None) is not None and var.entry.shows == "typed":  # type: ignore[union-attr]
            parts.add("keypad shows typed")
    for steps in model.features.values():
        for index, step in enumerate(steps):
            if step.optional:
                parts.add("optional step")
            if step.timeout is not None:
                parts.add("timeout")
            if step.variable is None and not step.set and not step.reset:
                parts.add("entry step" if index + 1 < len(steps) else "confirm step")
            if step.on_entry == "show":
                parts.add("on_entry show")
            if step.set:
                parts.add("set side effect")
            if step.reset:
                parts.add("reset side effect")
            effects = list(step.effect.values()) if isinstance(step.effect, dict) else [step.effect]
            for effect in effects:
                if isinstance(effect, Add):
                    parts.add("add")
                elif isinstance(effect, GoTo):
                    parts.add("go-to programme key" if step.variable in parents else "go-to")
                elif isinstance(effect, Skip):
                    parts.add("skip")
                elif isinstance(effect, Conditional):
                    parts.add("conditional effect")
                elif effect in ("prev", "toggle", "none"):
                    parts.add(str(effect) + (" effect" if effect == "none" else ""))
                elif effect == "reset":
                    parts.add("reset effect")
                elif effect == "clear":
                    parts.add("keypad clear")
                if step.variable in parents and effect in ("next", "prev", None):
                    parts.add("cycling programme key")
    for guard in model.guards:
        names = set(guard.when)
        if any(isinstance(w, OtherThan) for w in guard.when.values()):
            parts.add("one-position guard")
        if guard.hide:
            parts.add("hidden display")
        if "power" in names:
            parts.add("power guard")
        elif "lock" in names:
            parts.add("lock guard")
        elif "running" in names:
            parts.add("running guard")
        elif any(model.variables[n].type == "discrete" for n in names):
            parts.add("mode guard")
        else:
            parts.add("number guard")
    return parts


def random_goal(rng: random.Random, model: ApplianceModel) -> dict[str, Any]:
    """A goal over one to three variables: values drawn from their domains, or (half the
    time) read off a state reached by a random walk, so that it is usually reachable.

    With programme-dependent settings, a quarter of the goals ask for a setting's value that
    is some programme's default without naming the programme, so that changing programme is
    a candidate route (the family of ``planner_not_optimal`` in issue 8)."""
    dependents = [n for n, v in model.variables.items() if v.depends_on is not None]
    if dependents and rng.random() < 0.25:
        return _default_elsewhere_goal(rng, model, rng.choice(dependents))
    names = rng.sample(list(model.variables), rng.randint(1, min(3, len(model.variables))))
    if rng.random() < 0.5:
        compiled = compiled_model(model)
        state = random_walk(compiled, rng, rng.randint(3, 30))
        walked = {n: compiled.value(state, n) for n in names}
        if all(v is not None for v in walked.values()):
            return walked
    names.sort(key=lambda n: model.variables[n].depends_on is not None)  # parents first
    goal: dict[str, Any] = {}
    programme: dict[str, Any] = {}  # the programme each dependent value was drawn for
    for name in names:
        var = model.variables[name]
        if var.depends_on is not None:
            parent = var.depends_on
            parent_domain = build_domain(model.variables[parent])
            options = [v for v in parent_domain.values if v in (var.cases or {})]
            chosen = goal.get(parent) or programme.get(parent) or rng.choice(options)
            programme[parent] = chosen  # a second setting of it must exist there too
            if chosen not in (var.cases or {}):
                continue
            if parent in goal or rng.random() < 0.5:  # else: any programme offering it will do
                goal.setdefault(parent, chosen)
            domain = build_domain(var, (var.cases or {})[chosen])
        else:
            domain = build_domain(var)
        goal[name] = domain.values[rng.randrange(len(domain))]
    return goal


def _default_elsewhere_goal(rng: random.Random, model: ApplianceModel, name: str) -> dict[str, Any]:
    """A dependent setting at one programme's default (the programme not named), and
    sometimes one more variable that is neither."""
    var = model.variables[name]
    case = rng.choice(list((var.cases or {}).values()))
    domain = build_domain(var, case)
    goal: dict[str, Any] = {name: domain.values[domain.initial]}
    others = [n for n in model.variables if n not in (name, var.depends_on)]
    if others and rng.random() < 0.3:
        other = rng.choice(others)
        spec = model.variables[other]
        if spec.depends_on is None:
            values = build_domain(spec).values
            goal[other] = values[rng.randrange(len(values))]
    return goal
