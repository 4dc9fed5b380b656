"""What a manual calls the thing a key sets: "PUMP   Changes the circulation speed" in a key
legend, or a section titled "CIRCULATION SPEED (PUMP)", and the thing a legend says a switch
turns on and off ("LIGHT   Turns the LED display on and off"). A user names the setting by that
thing ("slow the water circulation", "the display off"), not by the key's printed label."""

from __future__ import annotations

import itertools
import re
from typing import Any

from apbot.model.schema import ApplianceModel
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
            # a heading "HANDS-FREE (VOX)" or "Hands-free (VOX)": the name, then the key
            title = re.compile(rf"^([A-Z][A-Za-z -]{{2,40}}?)\s*\({said}\)\s*$")
            for line in lines:
                found = legend.match(line)
                if found is not None and line.startswith(label):
                    out.setdefault(name, set()).update(_phrase(found[1]))
                found = title.match(line)
                if found is not None and _heading_name(found[1]):
                    out.setdefault(name, set()).update(_phrase(found[1]))
    return {name: words for name, words in out.items() if words}


def _heading_name(name: str) -> bool:
    """Whether the words before "(KEY)" are a heading's name, not a sentence ending on the key:
    a capitals heading ("CIRCULATION SPEED (PUMP)") always is; a mixed-case one ("Hands-free
    (VOX)") only without verbs or the small words sentences carry ("Then press (SET)")."""
    if name.upper() == name:
        return True
    words = {w.casefold() for w in re.split(r"[\s-]+", name) if w}
    return not words & (_LEGEND_VERBS | _ENDS | STOP_WORDS)


def _phrase(text: str) -> list[str]:
    """The noun phrase a description opens with: "circulation speed: LO → MED" → circulation,
    speed (up to three words, to the first punctuation or preposition)."""
    words: list[str] = []
    for word in re.split(r"\s+|(?<=[a-z])-(?=[a-z])", text.strip()):  # "hands-free": two
        bare = word.rstrip(".,:;").casefold()
        if not bare.isalpha() or bare in _ENDS or len(words) == 3:
            break
        words.append(bare)
        if bare != word.casefold():
            break  # "speed:" ends the phrase
    return [w for w in words if len(w) >= 3]


_LEGEND_VERBS = frozenset(
    {"turns", "turn", "switches", "switch", "sets", "set", "selects", "select", "press", "presses"}
    | {"changes", "change", "shows", "show", "starts", "start", "stops", "stop", "each", "when"}
    | {"with", "from", "into", "this", "that", "then", "also", "only", "between", "unit's"}
)


_KEY_NOUN = r"(?:(?:touch|push|soft)\s+)?(?:key|button)"
"""A legend may call the key by its noun after the label ("SET touch key", "MODE button")."""


def legend_words(
    model: ApplianceModel, manual: str, labels: dict[str, list[str]]
) -> dict[str, set[str]]:
    """The thing a manual's key legend says a switch turns on and off: "LIGHT   Turns the
    indoor unit's LED display on and off." — the LIGHT switch is the *display*. ``labels``:
    setting -> its keys' labels. Only legend lines count (a key's label opening a line, then
    its description), and only the word right before "on and off"."""
    out: dict[str, set[str]] = {}
    if not manual:
        return out
    raw = manual.splitlines()
    lines = [LEGEND_MARK.sub("", line.strip().strip("|*-• ")).strip() for line in raw]
    for name, keys in labels.items():
        for label in keys:
            if len(label) < 3 or not label.isupper():
                continue
            pattern = re.compile(  # "SET touch key - …": the key's noun before the dash
                rf"^{re.escape(label)}(?:\s+{_KEY_NOUN})?(?:\s{{2,}}|\s*[:|–—]\s*|\s+-\s+)(.+)$"
            )
            for index, line in enumerate(lines):
                found = pattern.match(line)
                if found is None:
                    continue
                sentences = re.split(r"[.;(]", _continued(found[1], raw, index))
                held = [x for x in sentences[1:] if re.search(r"\b(?:hold|held)\b", x, re.I)]
                for sentence in sentences[:1] + held:  # a later one: the key's hold
                    thing = re.search(
                        r"(?:([A-Za-z]{4,})\s+)?([A-Za-z]{4,})\s+on\s*(?:and|or|/)\s*off\b",
                        sentence,
                    )
                    if thing is None and not re.search(r"(?i)start|stop", label):
                        # "CLICK — starts and stops the metronome" (not START/STOP: the run)
                        thing = _STARTS_AND_STOPS.search(sentence)
                    if thing is not None and thing[2].casefold() not in _LEGEND_VERBS:
                        out.setdefault(name, set()).add(thing[2].casefold())
                        if thing[1] and thing[1].casefold() not in _LEGEND_VERBS:
                            # "the attractant lure": the thing's qualifier names it too
                            out[name].add(thing[1].casefold())
                out.setdefault(name, set()).update(_described(sentences[0]))
    return out


_STARTS_AND_STOPS = re.compile(
    r"\b(?:starts?\s+(?:and|or|/)\s+stops?|stops?\s+(?:and|or|/)\s+starts?)\s+(?:the\s+)?"
    r"(?:([A-Za-z]{4,})\s+)?([A-Za-z]{4,})\b(?!\s+[A-Za-z]{4,})",
    re.IGNORECASE,
)
"""A legend saying the key starts and stops a thing names the switch by it, as "on and off"
does."""


def _described(sentence: str) -> set[str]:
    """The nouns of a legend that only names what the switch is ("ADD-IN | Beep for adding fruit
    and nuts"): no verb opens it, so its words are the thing switched ("no fruit-and-nut
    beep"). A legend that says what the key does ("Turns the lamp on") gives none here."""
    found = re.findall(r"[A-Za-z]+", sentence)
    if not found or found[0].casefold() in _LEGEND_VERBS or found[0].casefold().endswith("s"):
        return set()
    return {
        w.casefold()
        for w in found
        if len(w) >= 4 and w.casefold() not in _LEGEND_VERBS and not w.casefold().endswith("ing")
    }


def _continued(text: str, raw: list[str], index: int) -> str:
    """A legend's description with its indented continuation lines ("COOK TIME  Sets the time.
    Press and hold for / (indented) 3 seconds to switch the sound on or off"): a key's second
    use, a hold, is often said in the legend's next sentence."""
    for line in raw[index + 1 : index + 4]:
        if not line.strip() or not line.startswith("  "):
            break
        text += " " + line.strip()
    return text


_CODED = re.compile(r"[A-Za-z]{1,2}[- ]?\d{1,2}")


def add_kind_nouns(infos: dict[str, Any], manual: str) -> None:
    """A setting of numbered codes (MEAL: M1 … M4) the manual keeps calling by its name and a
    noun ("the meal slot", "meal slots") is named by that noun too: "the first slot", "slot
    one". Only a noun said so at least three times, that no other setting has already."""
    if not manual:
        return
    said = manual.casefold()
    taken = {key for info in infos.values() for key in info.vocab}
    for name, info in infos.items():
        values = [str(v) for v in info.values]
        if info.role != "setting" or len(values) < 2 or "_" in name:
            continue
        if not all(_CODED.fullmatch(v) for v in values):
            continue
        counts: dict[str, int] = {}
        for noun in re.findall(rf"\b{re.escape(name.casefold())}\s+([a-z]{{3,}})\b", said):
            counts[noun] = counts.get(noun, 0) + 1
        for noun, count in counts.items():
            key = concept(noun)
            if count >= 3 and noun not in STOP_WORDS and key not in taken:
                info.vocab[key] = 0.5
