"""What the user will not let happen: "never let it go into the dim mode", "don't let the light
go out". Letting is said of two things. When the appliance ("it", "them") is not let do what a
setting does by itself, that setting is off: "never let it go to sleep" is SLEEP off, "never
let it go into the dim mode" AUTO DIM off. When the thing named is not let go out or off, it
is to stay on: "don't let the light go out" is the LIGHT on — the denial is of its going off,
not of the light.
"""

from __future__ import annotations

from apbot.read.goal_text import Text

_DENIALS = ("never", "don't", "dont", "not")
_LET_FILLERS = frozenset({"it", "them", "go", "to", "fall", "into", "the", "a"})


def never_let(text: Text, k: int) -> bool:
    """ "never let it go to sleep", "don't let it dim": what the setting named at ``k`` does
    by itself is forbidden, so the setting is off. Only when "it" / "them" (the appliance) is
    let do it: in "never let the fan stop" the setting is the subject kept going, not refused."""
    j = k - 1
    while j > 0 and text.word(j) in _LET_FILLERS:
        j -= 1
    denied = text.word(j - 1) in _DENIALS
    return text.word(j) == "let" and denied and text.word(j + 1) in ("it", "them")


_SUBJECT_FILLERS = frozenset({"the", "its", "my", "your", "that", "this"})
_GOING_OFF: tuple[tuple[str, ...], ...] = (
    ("go", "out"),
    ("go", "off"),
    ("go", "dark"),
    ("turn", "off"),
    ("switch", "off"),
    ("shut", "off"),
    ("run", "out"),
    ("die",),
    ("stop",),
)


def kept_on(text: Text, k: int, last: int) -> bool:
    """ "don't let the light go out", "never let the pump stop": the thing named from ``k`` to
    ``last`` is the one not let go off, so it stays on."""
    j = k - 1
    while j > 0 and text.word(j) in _SUBJECT_FILLERS:
        j -= 1
    if text.word(j) != "let" or text.word(j - 1) not in _DENIALS:
        return False
    after = tuple(text.word(last + 1 + d) for d in range(2))
    if after == ("go", "off") and any(text.word(i) in _SOUNDERS for i in range(k, last + 1)):
        return False  # "don't let the alarm go off": its ringing is refused, it is to be off
    return any(after[: len(words)] == words for words in _GOING_OFF)


_SOUNDERS = frozenset({"alarm", "alarms", "buzzer", "beep", "beeper", "timer", "alert", "chime"})
"""Things that "go off" by sounding, not by going dark."""
