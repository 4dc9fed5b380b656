"""A key label cut short (MIC, STERI, CHOC) that the manual's key legend writes out in full
("(10) MIC   microphone volume dial", "STERI   Select the sterilising time"). The reader names
the setting after the label, so a read belief's MIC knows only "mic"; the user says the whole
word ("the microphone turned right down", "25 minutes of sterilising"), which is the legend's
word that the label begins."""

from __future__ import annotations

import itertools
import re
from typing import Any

from apbot.model.domain import all_values
from apbot.read.goal_legends import LEGEND_MARK
from apbot.read.goal_vocab import STOP_WORDS, concept, stem

_REACH = 6  # the legend's first words: its noun phrase, not a later remark
_MORE = 3  # letters the written-out word has past the label: MICRO is no expansion of MIC


def label_expansions(manual: str, labels: dict[str, list[str]]) -> dict[str, set[str]]:
    """setting -> the words its keys' legend lines write out in full from the key's label.

    ``labels``: setting -> its keys' printed labels. Only a label of three to six capital
    letters opening a legend line, then two spaces or a dash, colon or bar, counts; the word
    is one of the description's first words that begins with the label and runs at least
    three letters past it.
    """
    out: dict[str, set[str]] = {}
    if not manual:
        return out
    lines = [
        LEGEND_MARK.sub("", line.strip().strip("|*• ")).strip() for line in manual.splitlines()
    ]
    for name, keys in labels.items():
        for label in {k for k in keys if 3 <= len(k) <= 6 and k.isalpha() and k.isupper()}:
            legend = re.compile(rf"^{re.escape(label)}(?:\s{{2,}}|\s*[:|–—-]\s*)(.+)$")
            short = label.casefold()
            for line in lines:
                found = legend.match(line)
                if found is None:
                    continue
                for word in re.findall(r"[A-Za-z]+", found[1])[:_REACH]:
                    said = word.casefold()
                    if said.startswith(short) and len(said) >= len(short) + _MORE:
                        out.setdefault(name, set()).add(said)
    return out


def add_expanded_labels(infos: dict[str, Any], manual: str, labels: dict[str, list[str]]) -> None:
    """Give each setting (``infos``: name -> VarInfo) the written-out word of its cut-short
    label, as strongly as the label — unless two settings share the word, another setting is
    named by it already, or it is a value's word (a MAN key writes out MANUAL, a mode, not a
    name)."""
    found = label_expansions(manual, labels)
    shared = {w for a, b in itertools.combinations(found.values(), 2) for w in a & b}
    values = {
        stem(w)
        for info in infos.values()
        for value in _values(info)
        for w in re.findall(r"[a-z]+", str(value).casefold())
    }
    for name, words in found.items():
        if name not in infos:
            continue
        taken = {k for other, info in infos.items() if other != name for k in info.vocab}
        for word in words - shared:
            key = concept(word)
            if word in STOP_WORDS or key in taken or stem(word) in values:
                continue
            infos[name].vocab.setdefault(key, 0.8)  # as strong as the label it writes out


def _values(info: Any) -> list[Any]:
    try:
        return list(all_values(info.var))[:200]
    except Exception:  # a domain that cannot be listed names no value words
        return []
