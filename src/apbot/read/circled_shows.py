"""Small whole numbers the display shows as circled figures ("① first dog / ② second dog",
zones ① ②, users ① ② ③). Apart from printed_pairs.py (read while the evidence is gathered)
because it runs on the built variables, after their values are settled.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words

# a part's name in capitals beside a circled figure ("① PROGRAM key", "TIMER knob ②"): the
# figure is a drawing's callout, not a value the display shows
_CAPS_BESIDE_RE = re.compile(
    r"[\u2460-\u2473]\W{0,3}([A-Z]{2,})\b"
    r"|\b([A-Z]{2,})(?:\s+(?:key|knob|button|switch|dial|lamp))?\W{0,3}[\u2460-\u2473]"
)


def _circled(n: int) -> str:
    return chr(0x2460 + n - 1)  # ① … ⑳


def circled_shows(b: Builder) -> None:
    """A setting of small whole numbers (1, 2; zones, users, dogs) that the display shows as
    circled figures, where a sentence naming the setting prints them all ("Dog icon: ① first
    dog / ② second dog"): its values are shown so, and the loop can read them back."""
    units = b.manual.units
    for name, spec in b.variables.items():
        if spec.get("depends_on") or spec.get("show"):
            continue
        if spec.get("type") == "numeric":
            ranges = spec.get("ranges") or []
            if len(ranges) != 1 or ranges[0][2] != 1 or spec.get("unit"):
                continue
            numbers = list(range(int(ranges[0][0]), int(ranges[0][1]) + 1))
        elif spec.get("type") == "discrete":
            values = [str(v) for v in spec.get("values") or []]
            if not all(v.isdigit() for v in values):
                continue
            numbers = [int(v) for v in values]
        else:
            continue
        if not numbers or not 2 <= len(numbers) <= 10 or min(numbers) < 1 or max(numbers) > 20:
            continue
        own = {w[:4] for w in words(f"{name.replace('_', ' ')} {spec.get('label', '')}")}
        signs = [_circled(n) for n in numbers]
        said = next(
            (
                i
                for i, u in enumerate(units)
                if all(s in u.text for s in signs) and _names_them(u.text, own)
            ),
            None,
        )
        if said is None:
            continue
        for key in ("ranges", "unit", "entry"):
            spec.pop(key, None)
        spec["type"] = "discrete"
        spec["values"] = [str(n) for n in numbers]
        if "initial" in spec:
            spec["initial"] = str(int(float(spec["initial"])))
        spec["show"] = dict(zip(spec["values"], signs, strict=True))
        b.note(f"variables.{name}.show", f"shown as {' '.join(signs)}", said)


def _names_them(text: str, own: set[str]) -> bool:
    """The setting is named before the circled figures ("Zone icon: ① hall / ② bedroom") and
    no other part's name in capitals stands beside one: a legend of a drawing's parts ("①
    PROGRAM key · ② TIMER key · ③ START key") numbers the parts, it shows no value."""
    first = min(i for i, c in enumerate(text) if "\u2460" <= c <= "\u2473")
    if not own & {w[:4] for w in words(text[:first])}:
        return False
    beside = (m.group(1) or m.group(2) for m in _CAPS_BESIDE_RE.finditer(text))
    return all(w.lower()[:4] in own for w in beside)
