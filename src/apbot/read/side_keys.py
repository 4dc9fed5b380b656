"""Two keys named for the two sides of one thing, only one side at a time: ◄ / ► indicators.

A panel may have a key per side of one thing, named by the side (LEFT / RIGHT, FRONT / REAR),
each switching that side on and off again, and only one side can be on ("Press ◄ to flash the
left indicators … Only one side can flash: pressing ► stops the left and starts the right").
That is ONE setting of three values, off and the two sides: each key selects its side, or turns
the setting off when its side is already on. Read as two toggles, a goal "signal left" has no
setting to name, and the keys look like a list pair (◄ / ►) stepping some other list.

The manual must say the side words before one noun ("left indicators", "right indicator"; the
noun names the setting) and, in a sentence naming that noun or "side", that only one is on at a
time ("only one side", "only one … at a time").
"""

from __future__ import annotations

import re
from collections import Counter

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words

_SIDES = (("left", "right"), ("front", "rear"), ("upper", "lower"))
_NOT_NOUNS = frozenset({"side", "hand", "half", "then", "when", "with"})
_LAMPS = re.compile(r"\b(?:lamps?|lights?|leds?|symbols?)\b", re.IGNORECASE)
# "both seats may be on together": both sides at once, two settings (review31)
_BOTH = re.compile(
    r"\bboth\b[^.;]{0,40}?\b(?:together|at\s+once|at\s+the\s+same\s+time|simultaneously)\b",
    re.IGNORECASE,
)
_ONE = re.compile(r"\bonly\s+one\b|\bone\s+(?:side|at\s+a\s+time)\b", re.IGNORECASE)


def read_side_keys(b: Builder, infos: list[ActionInfo], done: set[str]) -> set[str]:
    """Read each such pair of keys as one setting: off and the two sides; the actions taken."""
    keys = {
        info.token: info.name
        for info in infos
        if info.name not in done and info.skill == "press" and info.digit is None
    }
    taken: set[str] = set()
    texts = [u.text for u in b.manual.units]
    for one, other in _SIDES:
        if one not in keys or other not in keys:
            continue
        noun = _shared_noun(texts, one, other)
        if noun is None or not any(
            _ONE.search(t) and (noun in words(t) or "side" in words(t)) for t in texts
        ):
            continue
        if any(_BOTH.search(t) and {noun, "side"} & _singular(t) for t in texts):
            continue  # ("both seats may be on together"; not "both leg rests rise together")
        var = b.add_discrete(noun, ["off", one, other], noun.upper(), None)
        for side in (one, other):
            b.feature(
                f"{side}_{var}",
                [
                    {
                        "actions": [keys[side]],
                        "variable": var,
                        "effect": {
                            "when": {var: side},
                            "then": {"to": "off"},
                            "otherwise": {"to": side},
                        },
                    }
                ],
            )
        shows = _lamp_signs(b, texts, one, other)
        if shows:
            b.variables[var]["show"] = {"off": "", **shows}  # "◄ / ► lamps flash with …"
        at = next(i for i, t in enumerate(texts) if _ONE.search(t))
        b.note(f"variables.{var}", f"one {noun} of two sides, {one} or {other}, or off", at)
        taken |= {keys[one], keys[other]}
    return taken


def _shared_noun(texts: list[str], one: str, other: str) -> str | None:
    """The noun both side words stand before most often ("left indicators" / "right
    indicator"), singular; None when two nouns tie."""
    after: dict[str, Counter[str]] = {one: Counter(), other: Counter()}
    for text in texts:
        ws = words(text)
        for i, w in enumerate(ws[:-1]):
            if w in after:
                after[w][ws[i + 1].removesuffix("s")] += 1
    counts = {
        n: min(after[one][n], after[other][n])
        for n in set(after[one]) & set(after[other])
        if len(n) >= 4 and n.isalpha() and n not in _NOT_NOUNS
    }
    ranked = sorted(counts.values(), reverse=True)
    if not ranked or (len(ranked) > 1 and ranked[0] == ranked[1]):
        return None
    return max(counts, key=lambda n: counts[n])


def _lamp_signs(b: Builder, texts: list[str], one: str, other: str) -> dict[str, str]:
    """Each side shown as its key's sign, where the keys are printed as signs and the manual
    calls those signs lamps ("◄ / ► lamps flash with the indicators"); else nothing."""
    signs = {side: b.labels[side].text for side in (one, other) if side in b.labels}
    if len(signs) != 2 or any(len(s) > 2 or any(c.isalnum() for c in s) for s in signs.values()):
        return {}
    said = any(all(s in t for s in signs.values()) and _LAMPS.search(t) for t in texts)
    return signs if said else {}


def _singular(text: str) -> set[str]:
    return {w.removesuffix("s") for w in words(text)}
