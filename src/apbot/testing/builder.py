"""Draws one random model part by part (controls, programmes, settings, guards, timeouts);
:func:`apbot.testing.generate.random_model` keeps the draws that stay small."""

from __future__ import annotations

import random
from typing import Any

from apbot.model.schema import ApplianceModel
from apbot.model.validate import reachable_indices
from apbot.testing.extras import Extras
from apbot.testing.guarded import GuardedParts
from apbot.testing.variables import (
    add_amount,
    case_domains,
    dependent_variable,
    plain_variable,
    some_values,
    value_count,
)


class Builder(GuardedParts):
    """Collects the parts of one model; each ``_add_*`` method adds one kind of part (those
    that guard the rest: :class:`apbot.testing.guarded.GuardedParts`)."""

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
            self.variables[name] = plain_variable(rng)
            self.settings.append(name)
        for programme, prefix in zip(programmes, "de", strict=False):
            for j in range(rng.randint(1, 2 if programme == "prog" else 1)):
                name = f"{prefix}{j}"
                self.variables[name] = dependent_variable(rng, programme, self.variables)
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
        Extras(self, random.Random(repr((self.variables, self.features)))).add()
        if len(self.actions) % 2 == 0:  # decided without a draw: earlier seeds keep their models
            self._mark_unreachable()
        self._power_always_works()
        return self.model()

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
                ["next", "reset", {"to": rng.choice(some_values(self.variables[name]))}]
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
            for domain in case_domains(model, name):
                reached = reachable_indices(model, name, domain)
                found.update(v for i, v in enumerate(domain.values) if i not in reached)
            defaults = {d.values[d.initial] for d in case_domains(model, name)}
            if found - defaults:
                self.variables[name]["unreachable"] = sorted(found - defaults, key=str)

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
                two = value_count(var) == 2 and rng.random() < 0.4
                effects[self.action(**hold)] = (
                    "toggle" if two else rng.choice(["next", "next", "prev", "reset"])
                )
            if var["type"] != "discrete" and rng.random() < 0.3:
                effects[self.action()] = {"add": add_amount(rng, var)}
            if rng.random() < 0.2:
                effects[self.action()] = {"to": rng.choice(some_values(var))}
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
                step.setdefault("set", {})[target] = self.rng.choice(some_values(spec))

    def _add_side_effect_key(self) -> None:
        """A key whose only job is a side effect: RESET ALL, a preset, a programme reset."""
        step: dict[str, Any] = {"actions": [self.action()]}
        self._side_effects(step, exclude="")
        if "set" in step or "reset" in step:
            self.feature([step])
