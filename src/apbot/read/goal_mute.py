"""Silence said of an appliance that has a volume but no sound switch: "mute the doorbell",
"silent, with one-touch locking", "mute the beeps", "no beeping", "sound off" set the one
VOLUME setting to its silent value (0 on a 0-10 scale, MUTE or OFF among its levels). Where
a switch of sound exists (BEEP on/off) the word is that switch's, read elsewhere; a volume the
goal already sets is left."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable, NumericVariable
from apbot.read.goal_text import Text
from apbot.read.goal_values import magnitude
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values, own_concepts, own_stems
from apbot.read.goal_vocab import concept, stem

_SILENT_WORDS = frozenset({"mute", "muted", "silence", "silenced", "silent"})
# the names a level list gives its silent level
_SILENT_VALUES = frozenset({"mute", "muted", "silent", "off", "0"})


def muted_volume(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """Set the one volume setting silent when the instruction says silence and nothing else
    of the model is a sound to switch off."""
    said = [k for k in range(len(text.tokens)) if _silence_at(text, k) and k not in claimed]
    if not said or _sound_switch(view):
        return
    settings = [info for info in view.infos.values() if info.role == "setting"]
    volumes = [info for info in settings if stem("volume") in own_stems(info)]
    volumes = volumes or [info for info in settings if _named_sound(info)]
    if len(volumes) != 1 or volumes[0].name in goal:
        return
    said = [k for k in said if not _of_another(view, text, k, volumes[0])]
    if not said:
        return
    silent = _silent_value(view, volumes[0], goal)
    if silent is not None:
        goal[volumes[0].name] = silent
        claimed.add(said[0])


_DETERMINERS = frozenset({"the", "a", "an", "its", "my", "your", "that", "this"})
_SOUNDS = frozenset({"sound", "sounds", "beep", "beeps", "beeping", "tone", "tones"})
"""What a panel's sound is called: "no beeping", "sound off", "without the key tones"."""


def _silence_at(text: Text, k: int) -> bool:
    """Silence said at ``k``: a word of silence, or the sound denied ("no beeping", "without
    the beeps") or switched off ("sound off", "beeps off")."""
    word = text.word(k)
    if word in _SILENT_WORDS:
        return True
    if word not in _SOUNDS:
        return False
    before = text.word(k - 2) if text.word(k - 1) in _DETERMINERS else text.word(k - 1)
    return before in ("no", "without") or text.word(k + 1) == "off"


def _of_another(view: Model, text: Text, k: int, volume: VarInfo) -> bool:
    """The silence word's object names another setting of the model ("silence the alarm",
    "mute the radio"): that thing is silenced, not the volume turned down to nothing."""
    others = [i for i in view.infos.values() if i.name != volume.name]
    if k > 0 and text.word(k) in _SOUNDS and any(text.stems[k - 1] in own_stems(i) for i in others):
        return True  # "the roger beep off": a sound that has a setting of its own (ROGER)
    n = k + 1
    while n < len(text.tokens) and text.tokens[n].text in _DETERMINERS:
        n += 1
    if n >= len(text.tokens):
        return False
    said = text.stems[n]
    return any(said in own_stems(i) for i in others)


def _named_sound(info: VarInfo) -> bool:
    """A setting of loudness levels named for the sound itself (SOUND LOUD / SOFT / MUTE): a
    volume by another name, silenced the same way where no setting is named VOLUME."""
    return isinstance(info.var, DiscreteVariable) and concept(info.name) == concept("sound")


def _sound_switch(view: Model) -> bool:
    """A switch of sound (BEEP, BUZZER, SOUND on/off), which "mute" switches off."""
    buzzer = concept("buzzer")
    return any(i.role == "switch" and buzzer in own_concepts(i) for i in view.infos.values())


def _silent_value(view: Model, info: VarInfo, goal: Goal) -> object:
    """0 of a numeric volume, or the level named MUTE / OFF / SILENT."""
    values = domain_values(view, info, goal)
    if isinstance(info.var, NumericVariable):
        return next((v for v in values if magnitude(v) == 0), None)
    if isinstance(info.var, DiscreteVariable):
        silent = [v for v in values if str(v).casefold() in _SILENT_VALUES]
        return silent[0] if len(silent) == 1 else None
    return None


_QUIET_WORDS = _SILENT_WORDS | frozenset({"quiet", "quietly", "silently"})


def silenced_sounds(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """ "keep it quiet", "silently", "mute it" switch the one sound switch (BUZZER, BEEP on /
    off) off when the switch is not named itself (then its words say its state) and no
    setting is named by the word ("the quiet mode")."""
    sounds = [
        info
        for info in view.infos.values()
        if _sound_switch(view)
        and info.role == "switch"
        and concept("buzzer") in own_concepts(info)
        and not own_stems(info) & {stem(w) for w in _QUIET_WORDS}  # QUIET on is the silence
        and info.off is not None
    ]
    if len(sounds) != 1 or sounds[0].name in goal:
        return
    info = sounds[0]
    if any(
        text.word(k) not in _QUIET_WORDS and text.concepts[k] in own_concepts(info)
        for k in range(len(text.tokens))
    ):
        return  # "the buzzer off", "quiet beeps": the switch is named, its state said
    for k in range(len(text.tokens)):
        word = text.word(k)
        if word not in _QUIET_WORDS or k in claimed:
            continue
        if any(concept(word) in other.vocab for other in view.infos.values() if other is not info):
            continue  # "the quiet mode": another setting's own word
        goal[info.name] = info.off
        claimed.add(k)
        return
