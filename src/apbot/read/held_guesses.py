"""What a held walk's keys were guessed to set before the walk was read (see ``held_walks``).

Read key by key, the hold that opens a walk looks like a switch of its own, and the short press
and the stepping pair that set its fields like amounts whose range the manual never gives.
Once the walk is read, those guesses are its job, and are dropped.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.build_base import PLACEHOLDERS


def drop_guess(b: Builder, hold: str) -> str:
    """Drop the setting the hold alone was guessed to set; return its name as a prefix
    ("sleep_period_") when that was more than the key's name and "hold"."""
    prefix = ""
    for fname, old in list(b.features.items()):
        if not old or old[0].get("actions") != [hold]:
            continue
        names = [s.get("variable") for s in old]
        if len(old) > 1 and not all(v is None or v.endswith("_hold") for v in names):
            continue  # (a hold opening a setting read as the key's own "…_hold" is a guess)
        del b.features[fname]
        for var in names:
            drop_unused(b, str(var))
        var = names[0]
        if len(old) == 1 and isinstance(var, str) and not var.endswith("_hold"):
            prefix = f"{var}_"
    return prefix


def drop_key_guesses(b: Builder, keys: set[str], said: str) -> None:
    """Drop what the walk's keys alone were guessed to set — a range the manual never gave, or
    placeholder choices ("▲ and ▼ have no function outside the menu"): the walk is their job.
    Only a setting named for one of those keys or by words of the walk's own steps (``said``:
    "Press ▲ for a longer time" gave ▲ / ▼ a "time"); a setting of their own named elsewhere
    (a temperature whose range the manual leaves out), or named beside the keys outside the
    walk though a field shares its word, stays."""
    placeholders = {n.subject.split(".")[1] for n in b.notes if n.what == PLACEHOLDERS}
    tokens = {c for i in b.infos if i.name in keys for c in i.controls}
    own = {w for t in tokens for w in t.split("_")}  # a setting named for the keys
    named = {w.lower() for w in re.findall(r"[A-Za-z]+", said)} | own
    for fname, steps in list(b.features.items()):
        names = [s.get("variable") for s in steps if s.get("variable")]
        acts = {a for s in steps for a in s.get("actions", [])}
        labels = [
            b.labels[c].text for i in b.infos if i.name in acts for c in i.controls if c in b.labels
        ]
        if (
            names
            and all(set(s.get("actions", [])) <= keys for s in steps)
            and all(v in b.unread or v in placeholders for v in names)
            and all(set(str(v).split("_")) <= named for v in names)
            and not any(
                _legend_names(b, str(v), labels, said)
                for v in names
                if not set(str(v).split("_")) <= own
            )
        ):
            del b.features[fname]
            for var in names:
                drop_unused(b, str(var))


def drop_unused(b: Builder, var: str) -> None:
    """Drop a guessed setting no feature sets any more, and every choice's reset of it."""
    if var not in b.variables or any(
        s.get("variable") == var for st in b.features.values() for s in st
    ):
        return
    del b.variables[var]
    for steps in b.features.values():
        for step in steps:
            if var in step.get("reset", []):
                step["reset"] = [r for r in step["reset"] if r != var]


def _legend_names(b: Builder, var: str, labels: list[str], said: str) -> bool:
    """Whether a sentence outside the walk names the setting beside one of the keys guessed to
    set it ("▲ / ▼   raise or lower the room temperature"): the keys' own setting, though a
    field of the walk shares its word ("the frost guard temperature")."""
    words = var.split("_")
    for u in b.manual.units:
        if u.text in said or not any(says(u.text, label) for label in labels):
            continue
        if all(says(u.text, w) for w in words):
            return True
    return False


def says(text: str, word: str) -> bool:
    """Whether ``text`` says ``word`` (a word or a key's label) standing alone."""
    return re.search(rf"(?<!\w){re.escape(word)}(?!\w)", text, re.I) is not None
