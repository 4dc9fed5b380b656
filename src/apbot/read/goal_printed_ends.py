"""A superlative the manual prints beside a number of a setting: "the finest setting" is 1
where the manual says "positions 1 (finest) to 12 (coarsest)".

A dial numbered 1–12 has no word of its own for which end is fine: the manual says it once,
beside the end's number. The user says the word ("the finest pastry flour setting", "the
coarsest for cracked beans", "the second finest"), so a superlative that a manual line prints
in brackets after a number ("12 (coarsest)", "1 (the finest)") is that number, for the open
number setting the same line names (its label or name) and whose values hold it; an ordinal
before it ("the second finest") counts that many steps in from the end.
"""

from __future__ import annotations

import re

from apbot.model.schema import NumericVariable
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model, domain_values

_ORDINALS = {"second": 1, "third": 2, "fourth": 3}


def _printed_number(line: str, word: str) -> int | None:
    """The number a line prints the superlative beside: "1 (finest)", "12 (the coarsest)"."""
    m = re.search(rf"\b(\d{{1,3}})\s*\(\s*(?:the\s+)?{re.escape(word)}\b[^()]*\)", line)
    return int(m.group(1)) if m else None


def _names(line: str, name: str, label: str) -> bool:
    words = {w for w in re.findall(r"[a-z]+", f"{name} {label}".casefold()) if len(w) >= 4}
    return any(re.search(rf"\b{w}", line) for w in words)


def printed_ends(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Read "the finest", "the second coarsest" as the number the manual prints it beside."""
    for k, token in enumerate(text.tokens):
        word = token.text
        if k in claimed or not word.endswith("est") or len(word) < 5:
            continue
        for line in view.manual_lines:
            number = _printed_number(line, word)
            if number is None:
                continue
            found = [
                name
                for name, info in view.infos.items()
                if name not in goal
                and info.role == "setting"
                and isinstance(info.var, NumericVariable)
                and _names(line, name, str(info.var.label or ""))
                and float(number) in [float(v) for v in domain_values(view, info, goal)]
            ]
            if len(found) != 1:
                continue
            name = found[0]
            values = sorted(domain_values(view, view.infos[name], goal), key=float)
            at = [float(v) for v in values].index(float(number))
            steps = _ORDINALS.get(text.tokens[k - 1].text, 0) if k else 0
            inward = 1 if at < len(values) / 2 else -1
            pick = at + inward * steps
            if not 0 <= pick < len(values):
                continue
            goal[name] = values[pick]
            where[name] = k
            claimed.add(k)
            break
