"""The child-lock role an action's name or hold gives away, and the word the display shows for it.

Apart from ``roles_fixed`` (power, standby) and ``roles_running`` (start, stop) because the lock
has evidence of its own (a held key, a LOCK word shown) that neither of the others reads.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.evidence_checks import SENTENCE_END_RE
from apbot.read.held_flips import held_flip
from apbot.read.labels import words
from apbot.read.roles_common import first_mention
from apbot.read.roles_holdcell import held_lock
from apbot.read.roles_running import _state_word
from apbot.read.shapes import STOP_WORDS
from apbot.read.shown import LOCK_CUE


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
                (len(info.controls) > 1 and held_flip(b, info) is None)  # (not "24H or 12H")
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
