"""The steps of a walk as the manual writes them: numbered steps, or a paragraph of prose.

Many manuals tell a walk in running prose rather than numbered steps: "Press and hold SET for
3 seconds. The hour flashes. Press + or - to set the hour. Press SET again and the minutes
flash. Press + or - to set the minutes." Each sentence that tells the reader to work a key
begins a step; a sentence that only says what the display does ("The hour flashes.") belongs
to the step before it. Read so, a prose walk has the same steps as its numbered form.
"""

from __future__ import annotations

import re

from apbot.model.values import NUMBER_WORDS, words_to_number
from apbot.read.build import Builder
from apbot.read.held_guesses import drop_unused
from apbot.read.text import Unit

# a sentence that works a key, so begins a step: "Press SET again …", "Then hold ▲ …"
_ACTS_RE = re.compile(
    r"^(?:then,?\s+|now,?\s+|next,?\s+)?(?:press|touch|tap|push|hold|turn)\b", re.I
)
# "Use ▲ …", "Keep holding SET …" work a key too, but only with its label right after: "Keep in
# mind …", "Use only dry cloths …" are advice inside the step before
_KEY_VERB_RE = re.compile(
    r"^(?:[Tt]hen,?\s+|[Nn]ow,?\s+|[Nn]ext,?\s+)?(?:[Uu]se|[Kk]eep(?:\s+(?:holding|pressing))?)"
    r"\s+(?:the\s+)?(?:[A-Z0-9][A-Z0-9+/-]*[A-Z0-9+]\b|[^\w\s\"'(])"
)
_MAX_STEPS = 9
# a key worked after a comma, mid-sentence: ", then press SET: the minutes flash"
_THEN_PRESS_RE = re.compile(r",\s+(?:and\s+)?then\s+(?=(?:press|touch|tap|push)\s)", re.I)


def walk_steps(units: list[Unit], i: int) -> list[tuple[int, str]]:
    """The steps from unit ``i`` on, each with the sentences that follow it: numbered steps
    when unit ``i`` is one, else the sentences of its prose (within its section, up to a
    table, a list or a heading)."""
    if units[i].step is not None:
        return _numbered(units, i)
    return _prose(units, i)


def _numbered(units: list[Unit], i: int) -> list[tuple[int, str]]:
    out: list[tuple[int, str]] = []
    first = units[i].step
    for u in units[i:]:
        if u.step is not None:
            if first is None or u.step != first + len(out) or len(out) >= _MAX_STEPS:
                break
            out.append((u.step, u.text))
        elif u.cells or u.heading != units[i].heading:
            break
        else:
            out[-1] = (out[-1][0], f"{out[-1][1]} {u.text}")
    return out


def _prose(units: list[Unit], i: int) -> list[tuple[int, str]]:
    out: list[tuple[int, str]] = []
    for u in units[i:]:
        if u.cells or u.bullet or u.step is not None or u.heading != units[i].heading:
            break
        for text in _moves_within(u.text):
            if not out or _ACTS_RE.match(text) or _KEY_VERB_RE.match(text):
                if len(out) >= _MAX_STEPS:
                    return out
                out.append((len(out) + 1, text))
            else:
                out[-1] = (out[-1][0], f"{out[-1][1]} {text}")
    return out


def _moves_within(text: str) -> list[str]:
    """A sentence of prose cut where it goes on to work a key ("Set the hour with + and −,
    then press SET: the minutes flash"): the clause after "then" is the next step, as if the
    manual had begun a sentence there."""
    parts = _THEN_PRESS_RE.split(text)
    return [parts[0], *(p[:1].upper() + p[1:] for p in parts[1:])]


def prose_opener(unit: Unit, paired: bool) -> bool:
    """A sentence of running prose (not a step, a list item or a table row) that may open a
    walk told in prose; not a hold of a stepping key ("Hold ▲ or ▼ for 2 seconds: the desk
    travels 10 cm"), which steps a value fast rather than opening fields."""
    return unit.step is None and not unit.bullet and not unit.cells and not paired


def moves_at_ends(groups: list[tuple[int, str]], label: str) -> list[tuple[int, str]]:
    """Steps that end by moving on ("2. Press MEM to change the unit. Then press SET. 3. The
    month flashes …") rewritten so the move opens the next step ("Press SET. The month
    flashes …"), the shape the walk is read in: many manuals close each step with the key
    that moves on rather than opening the next with it."""
    tail = re.compile(rf"\s*\b(?:then\s+)?press\s+{re.escape(label)}(?!\w)\s*\.?\s*$", re.I)
    out: list[tuple[int, str]] = []
    carried = ""
    for k, (n, text) in enumerate(groups):
        text = f"{carried} {text}".strip() if carried else text
        carried = ""
        m = _SENTENCE_TAIL.search(text)
        end = m.start() if m else 0
        if k + 1 < len(groups) and tail.match(text[end:]) and end > 0:
            out.append((n, text[:end].strip()))
            carried = f"Press {label}."
        else:
            out.append((n, text))
    return out


# the last sentence of a step: what follows its last full stop (or colon) before the end
_SENTENCE_TAIL = re.compile(r"(?<=[.:!])\s+[^.:!]*\.?\s*$")


def adjusts(text: str, label: str) -> bool:
    """The step tells to press one key to change the flashing value: "Press MEM to change the
    unit", "Press ADJ until your number shows", "Press UP repeatedly"."""
    return (
        re.search(
            rf"\bpress\s+{re.escape(label)}(?!\w)\s+(?:to\s+(?:change|set|select|choose|adjust)|until|repeatedly)\b",
            text,
            re.I,
        )
        is not None
    )


def single_keys(
    b: Builder, pairs: list[tuple[list[str], list[str]]]
) -> list[tuple[list[str], list[str]]]:
    """Keys that alone step a value forward (a feature's "next" with no "prev" beside it) and
    belong to no pair: the one key some walks adjust every field with ("MEM changes the
    flashing value"), as a pair without its down side."""
    paired = {a for up, down in pairs for a in up + down}
    press = {i.name for i in b.infos if i.skill == "press"}
    out: list[tuple[list[str], list[str]]] = []
    for steps in b.features.values():
        for step in steps:
            effect = step.get("effect")
            if effect == "next":  # (one key's press: the effect said once for its actions)
                effect = {a: "next" for a in step.get("actions", [])}
            if not isinstance(effect, dict) or "prev" in effect.values():
                continue
            for a, e in effect.items():
                if e == "next" and a in press and a not in paired and ([a], []) not in out:
                    out.append(([a], []))
    return out


def drop_adjuster_settings(b: Builder, adjuster: list[str]) -> None:
    """Drop the settings read as the lone adjusting key's own ("mem", "mem_hold": its presses
    and holds stepping a value): a key that changes every field of a walk has none of its own.
    Only settings named for the key itself, and only for actions the walk still uses (a hold
    of the key no step takes keeps its reading)."""
    tokens = {c for i in b.infos if i.name in adjuster for c in i.controls}
    actions = {i.name for i in b.infos if set(i.controls) & tokens}
    names = set(tokens) | {f"{t}_hold" for t in tokens}
    for fname, steps in list(b.features.items()):
        acts = {a for s in steps for a in s.get("actions", [])}
        owned = [s.get("variable") for s in steps if s.get("variable")]
        elsewhere = {
            a
            for f, st in b.features.items()
            if f != fname
            for x in st
            for a in x.get("actions", [])
        }
        if acts <= actions & elsewhere and owned and all(v in names for v in owned):
            del b.features[fname]
            for var in owned:
                drop_unused(b, str(var))


# (not "a" / "an": "adds a lot" says no amount)
_NUMBER_WORD = "|".join(sorted((w for w in NUMBER_WORDS if len(w) > 2), key=len, reverse=True))
# "(MEM held 2 s adds ten months)", "holding ADJ adds 10 cm at a time"
_HELD_ADDS_RE = re.compile(
    rf"\b(?:held|holding)\b[^.()]{{0,25}}?\badds?\s+(\d+|(?:{_NUMBER_WORD})\b)\s+([a-z]+)",
    re.I,
)


def held_adds(text: str) -> tuple[int, str] | None:
    """What a hold of the lone adjusting key adds in a field's step, and the word of its unit
    ("MEM held 2 s adds ten months": 10, "months")."""
    m = _HELD_ADDS_RE.search(text)
    if not m:
        return None
    amount = words_to_number(m.group(1))
    if amount is None or amount != int(amount):
        return None
    return int(amount), m.group(2).lower()


def adjuster_hold(b: Builder, adjuster: list[str]) -> str | None:
    """The hold of the lone adjusting key, when the panel has one."""
    tokens = {c for i in b.infos if i.name in adjuster for c in i.controls}
    return next(
        (i.name for i in b.infos if i.skill == "hold" and set(i.controls) == tokens and tokens),
        None,
    )
