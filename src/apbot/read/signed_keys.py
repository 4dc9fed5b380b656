"""Keys that each add their own signed amount to one count: "+1  +2  +3  −1" per team.

A scoreboard, a tally counter or a stock counter has a row of keys printed with an amount and a
sign ("+1", "+2", "+3", "−1"); each press adds its amount to one number, and no key types it.
The action names carry the amounts (``press_home_plus2``, ``press_minus1``). Read key by key,
each key looked like a stepper of its own number (home1, home2, home3). They are one number per
stem, each key adding its amount; the range is the one the manual gives for what the keys count
("Scores run from 0 to 199").

Numbered zones use the same names (``press_plus1`` / ``press_minus1`` for zone 1, ``plus2`` /
``minus2`` for zone 2): there, plus and minus come with the same run of numbers 1, 2, …, and
this rule leaves them alone. It also wants the manual to print each amount with its sign.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.value_keys import drop_key_roles

# "home_plus2", "plus_3", "minus1": a stem, the sign's word and the amount
_TOKEN_RE = re.compile(r"^(?:([a-z][a-z0-9]*?)_)?(plus|minus|add|sub)_?(\d{1,3})$")
_MINUS = "−–-"
# "Scores run from 0 to 199", "the count goes from 0 to 9999"
_RANGE_RE = re.compile(
    r"\b([a-z]{3,}?)s?\s+(?:runs?|goes|go|counts?|ranges?|can\s+be)\s+from\s+(\d{1,5})\s+"
    r"(?:to|up\s+to)\s+(\d{1,5})\b",
    re.IGNORECASE,
)
# "The course is a compass heading from 000 to 359": the count named as what it is
_IS_FROM_RE = re.compile(
    r"\bthe\s+([a-z]{3,})\s+is\s+an?\s+(?:[a-z]+\s+){0,3}?from\s+(\d{1,5})\s+to\s+(\d{1,5})\b",
    re.IGNORECASE,
)
_SIGNED = re.compile(rf"(?<![\w.])[+{_MINUS}]\d")
_NOT_NOUNS = frozenset({"the", "it", "this", "that", "they", "value", "values", "number"})


def _families(b: Builder) -> dict[str, dict[str, int]]:
    """Stem → {action: signed amount} for pressed keys whose names carry a sign and an amount."""
    out: dict[str, dict[str, int]] = {}
    for info in b.infos:
        if info.skill != "press" or len(info.controls) != 1 or info.digit is not None:
            continue
        m = _TOKEN_RE.match(info.controls[0])
        if m is None:
            continue
        sign = 1 if m.group(2) in ("plus", "add") else -1
        out.setdefault(m.group(1) or "", {})[info.name] = sign * int(m.group(3))
    return out


def _amounts_keys(amounts: dict[str, int]) -> bool:
    """Whether the signed numbers are amounts, not zone numbers: zones give plus and minus the
    same run 1, 2, …, n; amounts differ (+1 +2 +3 but only −1) or skip (+1 +10)."""
    ups = {a for a in amounts.values() if a > 0}
    downs = {-a for a in amounts.values() if a < 0}
    if not ups or len(set(amounts.values())) < 3:
        return False
    return not (ups == downs and ups == set(range(1, len(ups) + 1)))


def _printed(text: str, amounts: dict[str, int]) -> bool:
    """Whether the manual prints every amount with its sign glued on ("+2", "−1")."""
    for a in set(amounts.values()):
        signs = "+" if a > 0 else _MINUS
        if not re.search(rf"(?<![\w.])[{re.escape(signs)}]{abs(a)}(?![\d.])", text):
            return False
    return True


def _range(b: Builder) -> tuple[str, int, int, int] | None:
    """(noun, low, high, unit) of the sentence giving what the keys count and its range."""
    for at, unit in enumerate(b.manual.units):
        for m in [*_RANGE_RE.finditer(unit.text), *_IS_FROM_RE.finditer(unit.text)]:
            noun = m.group(1).lower()
            lo, hi = int(m.group(2)), int(m.group(3))
            if noun in _NOT_NOUNS or hi <= lo:
                continue
            near = b.manual.units[max(0, at - 8) : at + 8]
            if not any(_SIGNED.search(u.text) for u in near):
                continue  # (a range far from the keys' amounts is another setting's)
            return noun, lo, hi, at
    return None


def read_signed_keys(b: Builder) -> None:
    """Make each family of signed-amount keys one count the keys add to."""
    text = "\n".join(u.text for u in b.manual.units)
    families = {s: a for s, a in _families(b).items() if _amounts_keys(a) and _printed(text, a)}
    if not families:
        return
    said = _range(b)
    for stem, amounts in families.items():
        drop_key_roles(b, set(amounts))
        noun = said[0] if said else "count"
        name = b.unique(f"{stem}_{noun}" if stem else noun, b.variables)
        lo, hi = (said[1], said[2]) if said else (0, 99)
        spec: dict[str, Any] = {
            "type": "numeric",
            "ranges": [[lo, hi, 1]],
            "label": (stem or noun).upper(),
        }
        if said and _wraps(b, said[1], said[2], said[3]):
            spec["wrap"] = True
        b.variables[name] = spec
        effect = {action: {"add": amount} for action, amount in amounts.items()}
        b.feature(name, [{"actions": list(amounts), "variable": name, "effect": effect}])
        keys = ", ".join(f"{a:+d}" for a in amounts.values())
        at = next((i for i, u in enumerate(b.manual.units) if _SIGNED.search(u.text)), None)
        b.note(f"variables.{name}", f"keys {keys} add their amounts to one {noun}", at)
        if said:
            b.note(f"variables.{name}.ranges", f"range {lo}–{hi}", said[3])
        else:
            b.unread.add(name)


def _wraps(b: Builder, lo: int, hi: int, at: int) -> bool:
    """Whether the count runs on past its ends, as a worked case near its range says: "+1 at
    359° gives 000°", "one more after 99 shows 0"."""
    ends = rf"0*{hi}\D{{0,3}}\s*(?:gives|shows|becomes|goes\s+to|→|->)\s*0*{lo}(?!\d)"
    near = b.manual.units[max(0, at - 3) : at + 4]
    return any(re.search(ends, u.text) for u in near)
