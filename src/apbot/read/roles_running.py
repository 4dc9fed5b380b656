"""The running role an action's name gives away: the start and stop keys (with their guards), and
the word the display shows while the appliance runs, which the lock reads too.

Apart from ``roles_fixed`` (power, standby) and ``roles_locks`` (the child lock) because the start
and stop rules alone are a module's worth of reading.
"""

from __future__ import annotations

import itertools
import re

from apbot.read.build import Builder
from apbot.read.held_leads import add_held_lead, held_lead
from apbot.read.labels import words
from apbot.read.legend_starts import legend_start
from apbot.read.power_starts import power_starts_work
from apbot.read.printed_starts import printed_start_stop
from apbot.read.roles_common import NUMERIC_WORDS, dedupe, first_mention, mentions_of
from apbot.read.roles_holdcell import held_toggle
from apbot.read.roles_holds import held_named_switch, held_start, pushed_start
from apbot.read.shapes import RUNNING_RE, STOP_WORDS
from apbot.read.shown import RUNNING_CUE, shown_words
from apbot.read.work_keys import starts_and_stops

# "the menu cannot be opened … MENU shows STOP FIRST": what a key refused while it runs prints
_REFUSED_RE = re.compile(
    r"\b(?:cannot|can't|can\s+not)\s+be\b|\bis\s+refused\b|\bare\s+refused\b", re.IGNORECASE
)

# the other keys refused while the state lasts: the word shown then is the refusal's
_KEYS_REFUSED_RE = re.compile(
    r"\b(?:every|all|any)\s+other\s+keys?\s+(?:is|are)\s+(?:locked|ignored|refused|blocked)\b",
    re.IGNORECASE,
)


def _start_setting(token: str) -> bool:
    """START TIME, START DELAY: "start" names an amount the key sets, not the start itself
    ("START/+1 MIN" still starts: its amount is what a further press adds)."""
    ws = words(token)
    return any(w == "start" and nxt in NUMERIC_WORDS for w, nxt in itertools.pairwise(ws))


def _run_starts(b: Builder, token: str) -> bool:
    """A key called RUN that a sentence naming it says starts ("press ▶/■ to start the motor:
    RUN lights"), not one that steps a run time ("Touch RUN to go to the next run time")."""
    if words(token) != ["run"] or token not in b.labels:
        return False
    units = b.manual.units
    # the key and "start" in one clause ("Press RUN to show the hours the filter has run; the
    # count starts again after RESET" tells of a count, not of RUN)
    printed = re.compile(rf"(?<![\w-]){re.escape(b.labels[token].text.strip())}(?![\w-])")
    return any(
        printed.search(part) and re.search(r"\bstart(?:s|ed)?\b", part, re.IGNORECASE)
        for i in b.labels[token].mentions
        for part in re.split(r";|(?<=[.!?])\s+", units[i].text)
    )


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
        and (
            "start" in words(i.token)
            or _run_starts(b, i.token)
            or printed_start_stop(b, i.token)  # "START/STOP CLOCK" for press_clock
        )
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
    if stops and not starts:  # CANCEL stops, "MODE  Turn: … Push: START the function" starts
        starts = [i for i in infos if i.name not in done and legend_start(b, i) is not None][:1]
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
            b,
            [i.token for i in starts + stops],
            RUNNING_CUE,
            re.compile(r"LOC|^C?L$|^Lc$", re.I),
            _REFUSED_RE,
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
                lead = None if switched else held_lead(b, info)
                if lead:  # "Reverse: hold START/STOP for 2 s. The REV lamp lights"
                    add_held_lead(b, info, lead, var)
                    run_actions.append(info.name)
                    continue
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
    b: Builder,
    tokens: list[str],
    cue: re.Pattern[str],
    reject: re.Pattern[str] | None = None,
    refusal: re.Pattern[str] | None = None,
) -> tuple[str, int | None]:
    """The word the panel shows in a state (running, locked): first in the sentences about the
    keys that enter it (the sentence that names the key, or the one right after it), then in any
    sentence about the state; a word ``reject`` matches belongs to another state, and a
    sentence ``refusal`` matches shows what a refused key prints, not the state."""
    keys = {lab.text for lab in b.labels.values() if lab.text}
    mentions = {m for t in tokens for m in mentions_of(b, t)}
    near = [i for i in b.context(tokens) if i < len(b.manual.units)]
    rest = [i for i, u in enumerate(b.manual.units) if cue.search(u.text) and i not in near]
    for i in near + rest:
        text = b.manual.units[i].text
        if not cue.search(text) and not (i - 1 in mentions and i not in mentions):
            continue
        if i in rest and refusal is not None and refusal.search(text):
            continue  # "While it is running, MENU … cannot be opened: … show STOP FIRST"
        if refusal is not None and _KEYS_REFUSED_RE.search(text):
            continue  # "while it runs every other key is locked (the display shows BUSY)"
        for word in shown_words(text, keys):
            if _when_off(word, text):
                continue  # "♪ flag beep on (MUTE when off)": another sign's word while off
            if reject is None or not reject.search(word):
                return word, i
    return "", None


def _when_off(word: str, text: str) -> bool:
    """The display legend says the word is shown while something is off ("MUTE when off")."""
    return re.search(rf"\b{re.escape(word)}\s+when\s+(?:it\s+is\s+)?off\b", text) is not None
