"""What a manual calls the thing a key sets: "PUMP   Changes the circulation speed" in a key
legend, or a section titled "CIRCULATION SPEED (PUMP)". A user names the setting by that
thing ("slow the water circulation"), not by the key's printed label."""

from __future__ import annotations

import itertools
import re
from typing import Any

from apbot.read.goal_vocab import STOP_WORDS, concept

_VERBS = r"(?:changes?|sets?|selects?|adjusts?|chooses?|controls?|regulates?|varies)"
# what numbers or marks a legend line before the key's name: "⑧", "(6)", "4.", "|", "•"
LEGEND_MARK = re.compile(r"^\s*(?:[①-⑳❶-❿➀-➉]|\(?\d{1,2}[.)]?|[|*•-])\s+")
_ENDS = frozenset(
    {"from", "in", "of", "between", "to", "by", "with", "and", "or", "for", "on", "at", "per"}
    | {"up", "down", "while", "when", "if", "until", "each", "every", "one"}
)


def add_setting_words(infos: dict[str, Any], manual: str, keys: dict[str, list[str]]) -> None:
    """Give each setting (``infos``: name -> VarInfo) the words its keys' legend or section
    title call it, at half weight, unless another setting or value has them already."""
    found = setting_words(manual, keys)
    shared = {w for a, b in itertools.combinations(found.values(), 2) for w in a & b}
    taken = {key for info in infos.values() for key in info.vocab}
    for name, words in found.items():
        for key in {concept(w) for w in words - shared if w not in STOP_WORDS} - taken:
            infos[name].vocab[key] = 0.5


def setting_words(manual: str, labels: dict[str, list[str]]) -> dict[str, set[str]]:
    """setting -> the words its key's legend or its section title give it. ``labels``: setting
    -> its keys' printed labels (only labels of three or more capitals count, so "▲" or "+",
    which many legends share, say nothing)."""
    out: dict[str, set[str]] = {}
    if not manual:
        return out
    raw = manual.splitlines()
    lines = [LEGEND_MARK.sub("", line).strip() for line in raw]
    for name, keys in labels.items():
        for label in {k for k in keys if len(k) >= 3 and k.isupper()}:
            said = re.escape(label)
            legend = re.compile(
                rf"^{said}(?:\s{{2,}}|\s*[:|–—]\s*){_VERBS}\s+(?:the\s+)?(.+)$", re.I
            )
            title = re.compile(rf"^([A-Z][A-Z -]{{2,40}}?)\s*\({said}\)\s*$")
            for line in lines:
                found = legend.match(line)
                if found is not None and line.startswith(label):
                    out.setdefault(name, set()).update(_phrase(found[1]))
                found = title.match(line)
                if found is not None:
                    out.setdefault(name, set()).update(_phrase(found[1]))
    return {name: words for name, words in out.items() if words}


def _phrase(text: str) -> list[str]:
    """The noun phrase a description opens with: "circulation speed: LO → MED" → circulation,
    speed (up to three words, to the first punctuation or preposition)."""
    words: list[str] = []
    for word in re.split(r"\s+", text.strip()):
        bare = word.rstrip(".,:;").casefold()
        if not bare.isalpha() or bare in _ENDS or len(words) == 3:
            break
        words.append(bare)
        if bare != word.casefold():
            break  # "speed:" ends the phrase
    return [w for w in words if len(w) >= 3]
