"""The roles an action's name gives away: the power switch (with its guards), and whether a key
works only in standby.

The child lock (``roles_locks``) and start and stop (``roles_running``) are read apart: each has
evidence of its own, and together they outgrew one module.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.held_power_only import held_press_free
from apbot.read.labels import squash
from apbot.read.power_starts import power_starts_work
from apbot.read.roles_common import first_mention, label_of
from apbot.read.roles_holds import add_held_setting, held_other_job, held_power

_DELIVERED_ON_RE = re.compile(
    r"\b(?:leaves? the factory|as delivered|on delivery|out of the box|factory (?:state|settings?))"
    r"\b[^.]*\b(?:is |are )?(?:switched|turned) on\b(?!\s+(?:when|after|by|with|once))"
    # the other way round: "The cooler is switched on when it leaves the factory"
    r"|\b(?:is|are) (?:switched|turned) on (?:when|as) (?:it|they) leaves? the factory\b",
    re.I,
)
# examples that start from the factory settings with the appliance on ("Examples (starting
# from the factory settings, switched on)"): where the examples start, not how it is delivered
_EXAMPLES_FROM_RE = re.compile(
    r"\b(?:start(?:s|ing)?|begin(?:s|ning)?)\s+(?:from|at|with)\s+the\s+factory\b", re.I
)


def assign_power(b: Builder) -> list[str]:
    """The power key (ON/OFF, or POWER unless the manual uses it for a power level) and its
    guard; returns the power actions."""
    infos = b.infos
    by_token: dict[str, list[ActionInfo]] = {}
    for info in infos:
        by_token.setdefault(info.token, []).append(info)
    power_actions: list[str] = []
    standby_hold: tuple[str, int] | None = None  # "Hold 3 seconds while OFF: °C / °F"

    tokens = {i.token for i in infos if i.skill == "press" and i.digit is None}
    power_token: str | None = next(
        (t for t in ("on_off", "onoff", "power_on_off", "standby") if t in tokens), None
    )
    if power_token is None:  # a key printed I / O or ON/OFF, whatever its action calls it
        power_token = next(
            (t for t in sorted(tokens) if t in b.labels and _printed_power(b.labels[t].text)),
            None,
        )
    if power_token is None:  # "Move the switch to ON": a bare switch set to ON / OFF
        power_token = next((t for t in sorted(tokens) if _switched_on_off(b, t)), None)
    if power_token is None and "power" in tokens:
        ctx = " ".join(b.manual.units[i].text for i in b.context(["power"]))
        if not re.search(r"\b(?:level|watt|output)\b", ctx, re.I) or re.search(
            r"\b(?:switch|turn)\w*\b[^.]*\b(?:on|off)\b", ctx, re.I
        ):
            power_token = "power"
    if (
        power_token is not None
        and all(power_starts_work(b, i) for i in by_token[power_token] if i.skill == "press")
        and any(i.skill == "press" for i in by_token[power_token])
    ):
        return []  # "press ⏻. The brush starts": the key starts the work (assign_running)
    var = ""
    if power_token is None:  # a key held to switch the appliance on and off ("M: hold 2 s")
        for info in infos:
            at = held_power(b, info)
            if at is not None:
                var = b.add_toggle("power", label_of(b, info.token), at)
                b.feature("power", [{"actions": [info.name], "variable": var, "effect": "toggle"}])
                b.note("features.power", f"holding {label_of(b, info.token)} switches it", at)
                power_actions.append(info.name)
                break
    else:
        press = [i for i in by_token[power_token] if i.skill == "press"]
        holds = [i for i in by_token[power_token] if i.skill == "hold"]
        job = held_other_job(b, holds[0]) if holds and press else None
        if job is not None:  # "hold 3 s: window detection on / off": a setting's, not power off
            add_held_setting(b, holds[0], *job[:3])
            standby_hold = (holds[0].name, job[0]) if job[3] else None
            holds = []
        var = b.add_toggle("power", label_of(b, power_token), first_mention(b, [power_token]))
        held_both = held_press_free(b, holds[0], press[0]) if holds and press else None
        if held_both is not None:  # held on and off; the short press has a job of its own
            b.feature("power", [{"actions": [holds[0].name], "variable": var, "effect": "toggle"}])
            b.note("features.power", "holding the power key switches on and off", held_both)
            power_actions.append(holds[0].name)
        elif holds and press:
            b.feature(
                "power_on", [{"actions": [press[0].name], "variable": var, "effect": {"to": "on"}}]
            )
            b.feature(
                "power_off",
                [{"actions": [holds[0].name], "variable": var, "effect": {"to": "off"}}],
            )
            b.note(
                "features.power_off",
                "holding the power key switches off (a short press switches on)",
                first_mention(b, [power_token]),
            )
            power_actions += [press[0].name, holds[0].name]
        else:
            acts = [i.name for i in press]
            b.feature("power", [{"actions": acts, "variable": var, "effect": "toggle"}])
            power_actions += acts
    if var:
        b.indicators.remove(var) if var in b.indicators else None
        delivered = next(
            (
                i
                for i, u in enumerate(b.manual.units)
                if _DELIVERED_ON_RE.search(u.text) and not _EXAMPLES_FROM_RE.search(u.text)
            ),
            None,
        )
        if delivered is not None:  # "leaves the factory: mode COMF, …, heater switched on"
            b.variables[var]["initial"] = "on"
            b.note(f"variables.{var}.initial", "it is switched on as delivered", delivered)
        b.guards.append(
            {
                "name": "power off",
                "when": {var: "off"},
                "only": list(power_actions),
                "display": "",
                "hide": True,
            }
        )
        b.note("guards.power off", "keys do nothing while the appliance is off")
        if standby_hold:
            held, at = standby_hold
            _only_in_standby(b, b.guards[-1], held, label_of(b, power_token or ""), at)
    return power_actions


_TO_ON_OFF_RE = re.compile(
    r"\b(?:to|at|in)\s+(?:the\s+)?(?:ON|OFF|I|O|0)\b(?:\s+position)?|\(\s*(?:ON|OFF)\s*/\s*(?:ON|OFF)\s*\)"
)


def _switched_on_off(b: Builder, token: str) -> bool:
    """Whether a control named only by its kind ("slide_switch": the manual's "the switch")
    is moved between ON and OFF positions ("a slide switch (OFF / ON)", "Move the switch to
    ON"): the appliance's power switch. Capital ON / OFF only: "turn it to the on position"
    is as often a setting's."""
    if token not in ("switch", "slide", "rocker", "toggle"):
        return False
    named = re.compile(rf"\b{token}\b", re.IGNORECASE)  # (in lower case too: "the switch")
    for unit in b.manual.units:
        said = named.search(unit.text)
        if said and _TO_ON_OFF_RE.search(unit.text[said.start() :]):
            return True
    return False


def _printed_power(label: str) -> bool:
    """Whether a key's printing is the on/off mark itself ("I / O", "ON/OFF")."""
    return "/" in label and squash(label) in ("io", "onoff")


_STANDBY_ONLY_RE = (  # "The timer can only be programmed while the appliance is in standby"
    r"\b{label}\b(?:\s+(?:key|button))?[^.;]{{0,30}}?\bcan\s+only\s+be\s+"
    r"(?:programmed|set|used|selected|activated|changed)\s+(?:while|when|in)\b[^.;]{{0,30}}?"
    r"\b(?:standby|switched\s+off|turned\s+off)\b"
)


_STANDBY_WORDS_RE = re.compile(r"\b(?:standby|switched\s+off|turned\s+off)\b", re.IGNORECASE)


def standby_only(b: Builder) -> None:
    """A key the manual says works only in standby ("The timer can only be programmed while
    the appliance is in standby") is the one key besides power that works while the appliance
    is off, and does nothing while it is on."""
    off = next((g for g in b.guards if g.get("name") == "power off"), None)
    if off is None:
        return
    # every wording ends in standby or off: only those sentences are searched, per key
    said_off = [
        (i, u.text) for i, u in enumerate(b.manual.units) if _STANDBY_WORDS_RE.search(u.text)
    ]
    if not said_off:
        return
    for info in b.infos:
        if info.skill != "press" or info.name in off["only"] or len(info.controls) != 1:
            continue
        label = b.labels[info.controls[0]].text if info.controls[0] in b.labels else ""
        if not label or not re.search(r"\w", label):
            continue
        said = re.compile(_STANDBY_ONLY_RE.format(label=re.escape(label)), re.IGNORECASE)
        at = next((i for i, text in said_off if said.search(text)), None)
        if at is None:
            continue
        _only_in_standby(b, off, info.name, label, at)


def _only_in_standby(b: Builder, off: dict, name: str, label: str, at: int) -> None:
    """Action ``name`` works while the appliance is off (guard ``off``), and only then."""
    (power,) = off["when"]
    off["only"].append(name)
    off.pop("hide", None)  # what it sets lights the panel while the rest is dark
    others = [i.name for i in b.infos if i.name != name]
    b.guards.append(
        {"name": f"{name} in standby only", "when": {power: "on"}, "only": others, "display": ""}
    )
    b.note(f"guards.{name} in standby only", f"{label} works only in standby", at)
