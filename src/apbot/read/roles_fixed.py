"""The roles an action's name gives away: power, child lock, start and stop (with their guards)."""

from __future__ import annotations

import itertools
import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.evidence_checks import SENTENCE_END_RE
from apbot.read.labels import squash, words
from apbot.read.power_starts import power_starts_work
from apbot.read.roles_common import (
    NUMERIC_WORDS,
    dedupe,
    first_mention,
    label_of,
    mentions_of,
)
from apbot.read.roles_holdcell import held_lock, held_toggle
from apbot.read.roles_holds import (
    add_held_setting,
    held_named_switch,
    held_other_job,
    held_power,
    held_start,
    pushed_start,
)
from apbot.read.shapes import RUNNING_RE, STOP_WORDS
from apbot.read.shown import LOCK_CUE, RUNNING_CUE, shown_words
from apbot.read.work_keys import starts_and_stops

_DELIVERED_ON_RE = re.compile(
    r"\b(?:leaves? the factory|as delivered|on delivery|out of the box|factory (?:state|settings?))"
    r"\b[^.]*\b(?:is |are )?(?:switched|turned) on\b(?!\s+(?:when|after|by|with|once))"
    # the other way round: "The cooler is switched on when it leaves the factory"
    r"|\b(?:is|are) (?:switched|turned) on (?:when|as) (?:it|they) leaves? the factory\b",
    re.I,
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
        if holds and press:
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
            (i for i, u in enumerate(b.manual.units) if _DELIVERED_ON_RE.search(u.text)), None
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


def assign_locks(b: Builder, done: set[str]) -> list[str]:
    """Child-lock keys (two-key holds, holds whose sentences mention a lock) and the lock guard;
    adds them to ``done`` and returns them."""
    infos = b.infos
    lock_actions: list[str] = []
    # a panel with a key of its own for the lock: another key's hold near the word "lock"
    # (a key table's next row, "| LOCK | Key lock (touch and hold) |") is not the lock
    named = any("lock" in words(i.token) for i in infos)
    # a two-key hold is the lock where the panel has one ("hold ▲ and ▼ together for 3 s");
    # a single key's hold near the word "lock" is then something else (the clock, a jump)
    named = named or any(i.skill == "hold" and len(i.controls) > 1 for i in infos)
    for info in infos:
        if info.name in done:
            continue
        is_lock = "lock" in words(info.token) and info.skill in ("hold", "press")
        if info.skill == "hold" and not is_lock:
            texts = [b.manual.units[i].text for i in b.context(list(info.controls))]
            is_lock = (
                len(info.controls) > 1
                or (
                    not named and held_lock(b, info)  # "| ALARM | … | 5 s: key lock on / off |"
                )
                or (
                    not named
                    and not (_runs(info) and any(_held_lock(b, o) for o in infos if not _runs(o)))
                    # another key's own row says its hold is the lock ("LIGHT | Touch and hold
                    # 3 s: key lock"): that row, next to this key's, speaks of that one, unless
                    # this key's own rows say so too (then neither claim rules the other out)
                    and (
                        _holds_itself_to_lock(b, info)
                        or not any(_held_lock(b, o) for o in infos if o.token != info.token)
                    )
                    and any(
                        re.search(r"\bhold\b", t, re.I)
                        # the word lock, not a compound ("lockdown": an incubation's last days)
                        and LOCK_CUE.search(t)
                        for t in texts
                    )
                )
            )
        if not is_lock:
            continue
        at = first_mention(b, list(info.controls))
        var = "child_lock"
        if var not in b.variables:
            var = b.add_toggle("child_lock", "LOCK", at)
            word = (
                _lock_word(b, info)
                or _state_word(b, list(info.controls), LOCK_CUE, re.compile(r"^RUN", re.I))[0]
            )
            b.variables[var]["show"] = {"off": "", "on": word or "LOCK"}
            b.feature("child_lock", [{"actions": [info.name], "variable": var, "effect": "toggle"}])
        else:
            b.features["child_lock"][0]["actions"].append(info.name)
        lock_actions.append(info.name)
        done.add(info.name)
    if lock_actions:
        shown = b.variables["child_lock"]["show"]["on"]
        b.guards.insert(
            0,
            {
                "name": "child lock",
                "when": {"child_lock": "on"},
                "only": list(lock_actions),
                "display": shown,
            },
        )
        b.note("guards.child lock", "only the lock action works while locked")
    return lock_actions


def _runs(info: ActionInfo) -> bool:
    """A hold of a START or STOP key (a lock on many panels, or the start itself)."""
    return info.skill == "hold" and bool(set(words(info.token)) & ({"start"} | STOP_WORDS))


def _held_lock(b: Builder, info: ActionInfo) -> bool:
    """Another hold whose own legend says it is the lock ("OK — Hold 3 s: key lock on/off"):
    then "the lock disables START/STOP" near START's hold speaks of that lock, not of START."""
    if info.skill != "hold" or len(info.controls) != 1 or info.controls[0] not in b.labels:
        return False
    own = b.labels[info.controls[0]].mentions
    return any(
        re.search(r"\bhold\b", b.manual.units[i].text, re.I)
        and re.search(r"\block\b", b.manual.units[i].text, re.I)
        for i in own
    )


def _holds_itself_to_lock(b: Builder, info: ActionInfo) -> bool:
    """A sentence of the key's own that holds this very key and speaks of the lock ("Touch and
    hold LIGHT for 3 seconds to lock the keys"); a table's cells are apart ("LOCK shown |
    Hold TIMER for 3 seconds." speaks of another key's hold)."""
    if info.skill != "hold" or len(info.controls) != 1 or info.controls[0] not in b.labels:
        return False
    label = b.labels[info.controls[0]]
    # the lock after this key's hold, no other hold between ("hold TIMER 3 s … hold SIZE 3 s")
    held = re.compile(rf"\bhold\s+{re.escape(label.text)}(?!\w)(?:(?!\bhold\b).)*?\block\b", re.I)
    return any(
        held.search(s)
        for i in label.mentions
        if not b.manual.units[i].cells
        for s in re.split(rf"{SENTENCE_END_RE.pattern}|\s{{3,}}", b.manual.units[i].text)
    )


def _start_setting(token: str) -> bool:
    """START TIME, START DELAY: "start" names an amount the key sets, not the start itself
    ("START/+1 MIN" still starts: its amount is what a further press adds)."""
    ws = words(token)
    return any(w == "start" and nxt in NUMERIC_WORDS for w, nxt in itertools.pairwise(ws))


def assign_running(
    b: Builder, done: set[str], power_actions: list[str], lock_actions: list[str]
) -> list[str]:
    """START/STOP (START toggles unless a STOP or CANCEL key exists) and the running guard;
    adds them to ``done`` and returns them."""
    infos = b.infos
    run_actions: list[str] = []
    starts = [
        i
        for i in infos
        if i.name not in done
        and "start" in words(i.token)
        and i.skill == "press"
        and not _start_setting(i.token)  # START TIME: when it starts, a setting
    ]
    if not starts:  # a START/STOP that is only ever held ("press and hold for 2 s to start")
        starts = [
            i
            for i in infos
            if i.name not in done and "start" in words(i.token) and i.skill == "hold"
        ]
    stops = [
        i
        for i in infos
        if i.name not in done
        and i not in starts
        and i.digit is None
        and (set(words(i.token)) & STOP_WORDS)
        and not set(words(i.token)) & NUMERIC_WORDS  # END TIME, CLEAR TIMER: a setting
        and "auto" not in words(i.token)  # AUTO OFF: when it switches itself off, a setting
        and i.skill in ("press", "hold")
    ]
    if not starts and not stops:  # "SELECT dial … Press and hold 2 seconds: start or stop"
        starts = [i for i in infos if i.name not in done and held_start(b, i) is not None][:1]
    if not starts and not stops:  # "Thumb wheel: turn to choose …; push (click) to start or stop"
        starts = [i for i in infos if i.name not in done and pushed_start(b, i) is not None][:1]
    if not starts and not stops:  # "PLAY – starts or stops cooking": no START, PLAY is it
        starts = [i for i in infos if i.name not in done and starts_and_stops(b, i)][:1]
    if not starts and not stops:  # "then press ⏻. The brush starts": no START, ⏻ starts it
        starts = [i for i in infos if i.name not in done and power_starts_work(b, i)][:1]
    if starts or stops:
        var = b.unique("running", b.variables)
        b.variables[var] = {"type": "discrete", "values": ["off", "on"], "label": "RUN"}
        word, at = _state_word(
            b, [i.token for i in starts + stops], RUNNING_CUE, re.compile(r"LOC|^C?L$|^Lc$", re.I)
        )
        if word:
            b.variables[var]["show"] = {"off": "", "on": word}
            b.note(f"variables.{var}.show", f"the panel shows {word} while it runs", at)
        else:  # no word read: the belief does not predict the screen (the loop cannot misread it)
            b.variables[var]["visible"] = False
            b.note(f"variables.{var}.visible", "the manual names no sign of running")
        b.note(
            f"variables.{var}",
            "the appliance runs after START",
            first_mention(b, [i.token for i in starts + stops]),
        )
        for info in starts:
            toggle = bool(set(words(info.token)) & (STOP_WORDS | {"pause"})) or not stops
            b.feature(
                info.token if info.token != "start" else "start",
                [
                    {
                        "actions": [info.name],
                        "variable": var,
                        "effect": "toggle" if toggle else {"to": "on"},
                    }
                ],
            )
            run_actions.append(info.name)
        for info in stops:
            b.feature(
                info.name if info.skill == "hold" else info.token,
                [{"actions": [info.name], "variable": var, "effect": {"to": "off"}}],
            )
            run_actions.append(info.name)
        for info in infos:
            if (
                info.skill == "hold"
                and info.name not in done | set(run_actions)
                and info.token in {s.token for s in starts}
            ):
                switched: tuple[str, int | None] | None = held_named_switch(b, info)
                noun = "" if switched else held_toggle(b, info)
                if noun:  # "| START/STOP | start or stop | 3 sec: keep warm on / off |"
                    switched = (noun.upper(), first_mention(b, [info.token]))
                if switched:  # "press and hold START/STOP 3 s to switch AUTO OFF on": its own
                    var = b.add_toggle("_".join(words(switched[0])), switched[0], switched[1])
                    b.feature(var, [{"actions": [info.name], "variable": var, "effect": "toggle"}])
                    run_actions.append(info.name)
                    continue
                b.feature(
                    "cancel", [{"actions": [info.name], "variable": var, "effect": {"to": "off"}}]
                )
                run_actions.append(info.name)
                b.note("features.cancel", "holding START stops the programme")
        done.update(run_actions)
        ctx_units = [u for u in b.manual.units if RUNNING_RE.search(u.text)]
        if ctx_units:
            allowed = dedupe(run_actions + power_actions + lock_actions)
            b.guards.append(
                {"name": "running", "when": {var: "on"}, "only": allowed, "display": ""}
            )
            line = b.manual.units.index(ctx_units[0])
            b.note("guards.running", "only start/stop (and power, lock) work while running", line)
    return run_actions


def _state_word(
    b: Builder, tokens: list[str], cue: re.Pattern[str], reject: re.Pattern[str] | None = None
) -> tuple[str, int | None]:
    """The word the panel shows in a state (running, locked): first in the sentences about the
    keys that enter it (the sentence that names the key, or the one right after it), then in any
    sentence about the state; a word ``reject`` matches belongs to another state."""
    keys = {lab.text for lab in b.labels.values() if lab.text}
    mentions = {m for t in tokens for m in mentions_of(b, t)}
    near = [i for i in b.context(tokens) if i < len(b.manual.units)]
    rest = [i for i, u in enumerate(b.manual.units) if cue.search(u.text) and i not in near]
    for i in near + rest:
        text = b.manual.units[i].text
        if not cue.search(text) and not (i - 1 in mentions and i not in mentions):
            continue
        for word in shown_words(text, keys):
            if reject is None or not reject.search(word):
                return word, i
    return "", None


_LOCK_WORDS = (r"[A-Z][A-Z-]*LOC[A-Z]*|LOC|Loc|LOCK(?:ED)?", r"[A-Z]-?L")
# the word the display is said to show: "The display shows C-L.", "LOCK appears", "LOCK lights"
_SHOWN = (
    r"\b(?:shows?|displays?|reads?)\s+(?:the\s+)?(?:(?:word|code|symbol)\s+)?[\"'“‘]?\b({word})\b"
    r"|\b({word})\b[\"'”’]?\s+"
    r"(?:appears|is\s+(?:shown|displayed|lit)|flashes|lights(?:\s+up)?|comes\s+on)"
)


def _lock_word(b: Builder, info: ActionInfo) -> str:
    """The word the display shows while locked: one the text says it shows (C-L in "the
    display shows C-L", beside a CHILD LOCK symbol), else one spelling LOCK anywhere in the
    key's context, else a two-letter code (C-L, LL) — a code near the keys may be another
    setting's (SL for a sleep mode the same keys' section lists)."""
    context = b.context(list(info.controls))
    either = "|".join(_LOCK_WORDS)
    patterns = [_SHOWN.format(word=either), *(rf"\b({w})\b" for w in _LOCK_WORDS)]
    for pattern in patterns:
        for i in context:
            for m in re.finditer(pattern, b.manual.units[i].text):
                word = next(g for g in m.groups() if g)
                if "CLOCK" not in word:
                    return word
    return ""


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
