"""The power said to stay off: "without switching the speaker on, turn the echo up", "set it
to sensitive mode, leave it off". A user who sets things up for later says the appliance is
not to be switched on; a goal that leaves the power out lets the plan switch it on to reach the
rest, and the task ends with the appliance on though it was asked to stay off."""

from __future__ import annotations

from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_view import Model
from apbot.read.goal_vocab import concept

_SWITCHING = frozenset({"switching", "turning", "powering"})
_KEEP = frozenset({"leave", "keep"})
_STATE = frozenset({"switched", "turned", "powered"})
_AFTER = frozenset({"", ",", "and", "afterwards", "now", "for", "please"})


def _past_the_appliance(view: Model, text: Text, j: int) -> int:
    """The token past "it" / "the speaker" / "the massage brush" standing at ``j``."""
    n = len(text.tokens)
    while j < n and (
        text.word(j) in ("it", "the") or concept(text.word(j)) in view.appliance_words
    ):
        j += 1
    return j


def says_kept_off(view: Model, text: Text) -> bool:
    """ "without switching (it / the speaker) on", "leave it off", "keep the brush switched
    off": the power, off. "leave" / "keep" must name the appliance or "it" right after them
    (not "leave the beeper off": a switch's own words), and the words must end there; on a
    model with a running state "leave it off for now" is not starting it (`goal_start`)."""
    running = any(info.role == "running" for info in view.infos.values())
    for k in range(len(text.tokens)):
        word = text.word(k)
        if word == "without" and text.word(k + 1) in _SWITCHING:
            j = _past_the_appliance(view, text, k + 2)
            if text.word(j - 1) == "the" and not _names_a_setting(view, text, j):
                j += 1  # "without switching the speaker on": a switching verb's thing is
                # the appliance, unless the word names a setting of it ("the light")
            if text.word(j) in ("on", "up") and not _particle_before_a_setting(view, text, k, j):
                return True
        if word in _KEEP and not running:
            j = _past_the_appliance(view, text, k + 1)
            if j == k + 1:
                continue  # nothing of the appliance named: "leave the beeper off" is a switch's
            if text.word(j) in _STATE:
                j += 1
            if text.word(j) == "off" and text.word(j + 1) in _AFTER | CLAUSE_ENDS:
                return True
    return False


def _particle_before_a_setting(view: Model, text: Text, k: int, j: int) -> bool:
    """ "without turning up the volume", "without switching on the beep": the particle right
    after the verb, then "the" and a word that is no name of the appliance — the thing switched
    is that setting, not the appliance."""
    if j != k + 2:
        return False
    past = _past_the_appliance(view, text, j + 1)
    return past > j + 1 and text.word(past - 1) == "the" and text.word(past) not in CLAUSE_ENDS


def _names_a_setting(view: Model, text: Text, j: int) -> bool:
    """Whether the word at ``j`` is one of a setting's or switch's own words."""
    return any(info.vocab.get(text.concepts[j], 0.0) >= 0.5 for info in view.infos.values())
