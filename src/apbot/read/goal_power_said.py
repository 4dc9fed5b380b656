"""Power said with verbs: "turn the machine on", "switch it off", "leave it on" — the power
variable's part of a goal, apart from starting (goal_start), so each module keeps one job."""

from __future__ import annotations

from apbot.read.goal_held import KEEPING, START_WORDS
from apbot.read.goal_text import ACT_VERBS, CLAUSE_ENDS, STRONG_VERBS, WEAK_VERBS, Text
from apbot.read.goal_values import generic
from apbot.read.goal_view import Goal, Model, own_stems
from apbot.read.goal_vocab import concept, stem

_AFTER_ON = frozenset({"in", "at", "to", "with", "for"})


def says_power_on(view: Model, text: Text, goal: Goal) -> bool:
    """ "turn the machine on", "switch on, ...", "power the bread maker up"."""
    n = len(text.tokens)
    switch_words = {s for i in view.infos.values() if i.role == "switch" for s in own_stems(i)}
    for k, token in enumerate(text.tokens):
        if token.text not in ("turn", "switch", "power", "switched", "turned"):
            continue
        if token.text in ("switched", "turned") and text.stems[k - 1] in switch_words:
            continue  # "Keep Fresh switched on": that switch, not the power
        j = k + 1
        while j < n and (concept(text.word(j)) in view.appliance_words or text.word(j) == "the"):
            j += 1
        j = _past_qualified_unit(view, text, j)
        if text.word(j) not in ("on", "up"):
            continue
        if text.word(j + 1) == "to" and text.word(j + 2) in START_WORDS | {"run"}:
            continue  # "switch it on to run": a start, said with a switch's verb
        if j > k + 1:
            return True  # "turn it on", "power the bread maker up"
        m = j + 1
        while m < n and (concept(text.word(m)) in view.appliance_words or text.word(m) == "the"):
            m += 1
        if m >= n or text.word(m) in CLAUSE_ENDS | {",", "and", "then"} | _AFTER_ON:
            return True  # "switch on, ...", "switch on the cooker and ...", "switch on in fan"
        if _next_order(view, text, m, switch_words):
            return True  # "switch on set the front ring to 6": a comma left out before the verb
        if _mode_word(view, text.stems[m]) and not any(
            i.role == "running" for i in view.infos.values()
        ):
            return True  # "switch on heating at 30 °C": on, in that mode
    for k in range(n):  # "wake the panel", "wake it up"
        if text.stems[k] == stem("wake") and (k == 0 or text.word(k - 1) in CLAUSE_ENDS | {","}):
            return True
    for k, token in enumerate(text.tokens):  # "with the machine left on", "leave it on"
        if token.text in KEEPING | {"stay", "stays"}:
            j = k + 1
            while j < n and (
                concept(text.word(j)) in view.appliance_words or text.word(j) == "the"
            ):
                j += 1
            before = concept(text.word(k - 1)) in view.appliance_words
            if (
                text.word(j) == "on"
                and (j > k + 1 or before)
                and text.word(j + 1) in (CLAUSE_ENDS | {",", "and", "then", ""})
                and not a_switch_state(view, text, goal, j)
            ):
                return True
    return False


_CONDITIONS = frozenset({"when", "once", "after", "if", "until", "before", "let", "don't", "dont"})
_CONDITIONS |= frozenset({"not", "never", "then", "afterwards", "later"})  # "…, then switch it off"


def _next_order(view: Model, text: Text, m: int, switch_words: set[str]) -> bool:
    """The word at ``m`` opens the next order ("Power on use the bake-only menu", "switch on
    pump the water out"): what was switched on is the appliance. Not a word of a switch or a
    setting ("switch on steam" turns on the STEAM switch)."""
    if text.stems[m] in switch_words or text.stems[m] in setting_words(view):
        return False
    return text.word(m) in ACT_VERBS or text.stems[m] in STRONG_VERBS | WEAK_VERBS


def says_power_off(view: Model, text: Text) -> bool:
    """ "switch the heater off.", "turn it off", "switch off the machine": the power, off — said
    of now (not "switch it off when it's done", "after 2 hours", "let it turn itself off", nor
    "dry the laundry, then switch it off": a later step)."""
    n = len(text.tokens)
    for k, token in enumerate(text.tokens):
        if token.text not in ("turn", "switch", "power", "shut"):
            continue
        j = k + 1
        while j < n and (
            concept(text.word(j)) in view.appliance_words or text.word(j) in ("the", "it")
        ):
            j += 1  # "the machine", "it"
        if text.word(j) != "off":
            continue
        m = j + 1
        while m < n and (concept(text.word(m)) in view.appliance_words or text.word(m) == "the"):
            m += 1
        if j == k + 1 and m == j + 1:
            continue  # "switch off" with no appliance named: perhaps a setting's
        if text.word(m) not in CLAUSE_ENDS | {"", ",", "and", "then"}:
            continue  # "switch off after 2 hours", "turn it off when done"
        before = []
        for d in range(1, 10):
            if text.word(k - d) in CLAUSE_ENDS or k - d < 0:
                break
            before.append(text.word(k - d))
        if not _CONDITIONS & set(before):
            return True
    return False


def setting_words(view: Model) -> frozenset[str]:
    """Concepts that name a setting outright (its own name or label; not generic words)."""
    return frozenset(k for k in setting_names(view) if not generic(k) or k == concept("program"))


def setting_names(view: Model) -> frozenset[str]:
    """Every word that names a setting ("heat" of HEAT 3-9), generic ones too."""
    return frozenset(
        key
        for info in view.infos.values()
        if info.role == "setting"
        for key, weight in info.vocab.items()
        if weight >= 0.8
    )


def a_switch_state(view: Model, text: Text, goal: Goal, k: int) -> bool:
    """The word before k names a switch the goal sets, so the state said at k ("keep warm on",
    "with the circulation running") is that switch's, not the appliance's power."""
    key = text.concepts[k - 1] if k >= 1 else ""
    return any(
        info.role == "switch" and name in goal and info.vocab.get(key, 0.0) >= 0.8
        for name, info in view.infos.items()
    )


def _mode_word(view: Model, word: str) -> bool:
    """The word is a one-word value of a programme-like setting (HEAT, COOL, DRY)."""
    return any(
        stems == (word,)
        for var, _value, stems, weight in view.phrases
        if weight >= 1.0 and view.infos[var].role == "setting"
    )


def _past_qualified_unit(view: Model, text: Text, j: int) -> int:
    """ "turn the parent unit on": one word that names no setting before a word of the
    appliance is part of its name (the parent unit, the base station); past both, or ``j``."""
    said = text.stems[j] if j < len(text.stems) else ""
    named = any(said in own_stems(info) for info in view.infos.values())
    qualifier = text.word(j).isalpha() and said not in view.appliance_words and not named
    if qualifier and concept(text.word(j + 1)) in view.appliance_words:
        return j + 2
    return j
