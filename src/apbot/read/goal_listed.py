"""A word the manual lists as one of a setting's choices, outside the values read for it: kept.

Only for a read belief (``parse_instruction(..., outside=[...])``). A reader often gets a
setting but not its values: a STYLE key read as a switch (off/on), a MODE key read with only
the short presses' modes. The user names the value ("Feta, 2 hours"), no read value has that
word, and the word would be dropped — so the closed loop never looks for it. The manual the
robot holds still says what the setting's choices are, the way manuals list them: a run of
single words joined by arrows, commas, slashes or "or" ("LEFT or RIGHT", "MOZZARELLA →
RICOTTA → FETA", "(REPAIR, SUPPLY)"), on a line that names the setting (a key's row in a
legend, a sentence) or right below one ("… the next style. Order:" then the run) — not one
saying what the lamps or display show.

A word of the instruction that no step took, that names no setting or key and is no value of
the belief, is given to the one setting whose listed choices hold it, as said; the reason is
noted in ``outside``, and the agent walks that setting to look for it on the display
(``agent/checking.py``). A word listed for two settings, or two words for one, is left alone.
"""

from __future__ import annotations

import re
from functools import lru_cache

from apbot.model.schema import ApplianceModel, TimeVariable
from apbot.model.values import preview
from apbot.read.goal_error import GoalParseError
from apbot.read.goal_text import Text, negative_around
from apbot.read.goal_values import OFF_WORDS, ON_WORDS, kind_noun, name_words
from apbot.read.goal_view import Goal, Model, domain_values, own_stems
from apbot.read.goal_vocab import STOP_WORDS, stem
from apbot.read.text_sections import box_label

_TOKENS = re.compile(r"[A-Za-z][A-Za-z'-]*|\d+|→|->|\.\.\.|…|\s{2,}|[^\sA-Za-z\d]")
_JOINS = frozenset({"→", "->", ",", "/", "|", "…", "...", "or"})
_OBJECTS = frozenset({"the", "a", "an", "it", "them", "my", "our", "your", "some", "this", "these"})
_ROLES = frozenset({"setting", "switch"})  # a switch too: a STYLE key read as off/on
_ABOVE = 2
"""Non-blank lines above a run (with no setting's word of its own) that may name its setting."""
# a lead line saying what lamps or a display show: the run below is states, not choices
_SHOWN = re.compile(
    r"\b(?:lamps?|indicators?|lights|LEDs?|display|screen)\s+(?:\w+\s+){0,2}"
    r"(?:shows?|showing|reads?|lights?\s+up)\b",
    re.IGNORECASE,
)


def listed_outside(
    view: Model,
    text: Text,
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
    outside: list[str],
    manual: str,
) -> None:
    """Give each unclaimed word the manual lists among one setting's choices (and the belief
    does not have) to that setting, as said; note why in ``outside``."""
    if not manual:
        return
    owners = _owners(view)
    taken = _belief_words(view)
    choices = _choices(manual, tuple(sorted(owners.items())), _named(view))
    found: dict[str, list[int]] = {}
    for k in range(len(text.tokens)):
        word = text.word(k)
        if k in claimed or not word.isalpha() or len(word) < 3 or word in STOP_WORDS:
            continue
        if word in ON_WORDS or word in OFF_WORDS or text.stems[k] in taken:
            continue
        if kind_noun(text.concepts[k]):
            continue  # "the mode", "a menu": what kind of setting, not which value
        if text.word(k + 1) in _OBJECTS:
            continue  # "open the door", "degas the solution": a verb, not a value
        names = [n for n in choices.get(text.stems[k], ()) if _open(view, n, goal)]
        if len(names) != 1 or negative_around(text, k):
            continue
        found.setdefault(names[0], []).append(k)
    for name, places in found.items():
        words = {text.stems[k] for k in places}
        if len(words) != 1:
            continue  # two of its choices said: which one is meant is not clear
        k = places[0]
        info = view.infos[name]
        values = domain_values(view, info, goal)
        goal[name] = text.word(k)
        where[name] = k
        claimed.update(places)
        reason = (
            f"not a value of {name} as read: {name} can be {preview(values, quote=False)}; "
            "kept as said, for the manual lists it among that setting's choices"
        )
        outside.append(str(GoalParseError(text.word(k), reason)))


def _open(view: Model, name: str, goal: Goal) -> bool:
    """A setting still to be given a value, of words rather than a time."""
    info = view.infos.get(name)
    return (
        info is not None
        and info.role in _ROLES
        and name not in goal
        and not isinstance(info.var, TimeVariable)
    )


def _owners(view: Model) -> dict[str, str]:
    """Stem → the one setting its word names: the one setting whose own name or label has it,
    or of several, the one whose whole name it is (MODE beside ``mode_hold``)."""
    seen: dict[str, set[str]] = {}
    for info in view.infos.values():
        if info.role in _ROLES:
            for s in own_stems(info):
                seen.setdefault(s, set()).add(info.name)
    owners: dict[str, str] = {}
    for s, names in seen.items():
        whole = [n for n in names if stem(n) == s]
        if len(names) == 1 or len(whole) == 1:
            owners[s] = next(iter(names)) if len(names) == 1 else whole[0]
    return owners


def _belief_words(view: Model) -> frozenset[str]:
    """Stems that already name something of the belief: a variable, a key, a value."""
    words = set(_named(view))
    for info in view.infos.values():
        for value in info.values if len(info.values) < 500 else []:
            words |= {stem(w) for w in name_words(str(value))}
    return frozenset(words)


def _named(view: Model) -> frozenset[str]:
    """Stems of the belief's variables' and keys' names: a list with one of them in it
    ("DEGAS, SWEEP, RUN" lamps, "START/STOP") lists things, not one setting's choices."""
    model: ApplianceModel = view.model
    words: set[str] = set()
    for info in view.infos.values():
        words |= own_stems(info)
    for action in model.actions:
        words |= {stem(w) for w in action.split("_")}
    return frozenset(words)


@lru_cache(maxsize=32)
def _choices(
    manual: str, owners: tuple[tuple[str, str], ...], named: frozenset[str]
) -> dict[str, frozenset[str]]:
    """Stem of a listed word → the settings the manual lists it for (a list naming a
    variable or key of the belief, ``named``, lists no choices)."""
    own = dict(owners)
    found: dict[str, set[str]] = {}
    above: list[list[str]] = []  # the nearest non-blank lines above, nearest last
    for line in manual.splitlines():
        tokens = [t if t.strip() else "  " for t in _TOKENS.findall(line)]
        if not tokens:
            continue
        for run, at in _runs(tokens):
            if any(stem(word.lower()) in named for word in run) or box_label(" ".join(run)):
                continue  # (a safety legend's "DANGER / WARNING / CAUTION" lists no choices)
            owner = _owner(tokens, at, own)
            if owner is None and not any(t[0].isalnum() for t in tokens[:at]):
                owner = _owner_above(above, own)  # "Model  PRO / MAX": its own row's, not above's
            if owner is not None:
                for word in run:
                    if word.isupper() and len(word) >= 3:  # as the panel prints it
                        found.setdefault(stem(word.lower()), set()).add(owner)
        above = [*above, tokens][-_ABOVE:]
    return {s: frozenset(names) for s, names in found.items()}


def _runs(tokens: list[str]) -> list[tuple[list[str], int]]:
    """Runs of two or more lone words joined by list marks, with where each starts."""
    out: list[tuple[list[str], int]] = []
    k = 0
    while k < len(tokens):
        run: list[str] = []
        j = k
        while _lone_word(tokens, j):
            run.append(tokens[j])
            if (
                j + 2 < len(tokens)
                and tokens[j + 1].lower() in _JOINS
                and _lone_word(tokens, j + 2)
            ):
                j += 2
                continue
            break
        if len(run) >= 2:
            out.append((run, k))
            k = j + 1
        else:
            k += 1
    return out


def _lone_word(tokens: list[str], j: int) -> bool:
    """A word with no other word right beside it (a list's item, not a phrase's)."""
    if not 0 <= j < len(tokens) or not tokens[j][0].isalpha() or tokens[j].lower() in _JOINS:
        return False
    for side in (j - 1, j + 1):
        if 0 <= side < len(tokens):
            near = tokens[side]
            if (near[0].isalnum() or near.startswith("'")) and near.lower() not in _JOINS:
                return False
    return True


def _owner(tokens: list[str], at: int, own: dict[str, str]) -> str | None:
    """The setting a line names: its first word when that is a setting's, else the nearest
    setting word to the run — in the run's cell or the one before it (a key's row: its name,
    then what it does), not across a page's columns flattened onto one line ("MODE  selects
    a programme      Model  PRO / MAX")."""
    cell = [0]
    for t in tokens:
        cell.append(cell[-1] + (t == "  "))
    places = [
        (k, own[s])
        for k, t in enumerate(tokens)
        if t[0].isalpha() and (s := stem(t.lower())) in own and 0 <= cell[at] - cell[k] <= 1
    ]
    if not places:
        return None
    first = next((k for k, t in enumerate(tokens) if t[0].isalpha()), None)
    if places[0][0] == first:
        return places[0][1]
    return min(places, key=lambda p: abs(p[0] - at))[1]


def _owner_above(above: list[list[str]], own: dict[str, str]) -> str | None:
    """The setting the nearest line above names last (a sentence that leads into a list), unless
    that line says what lamps or the display show ("After you press MODE, the lamps show:"):
    the run is then the states they show, not the setting's choices."""
    for tokens in reversed(above):
        places = [own[s] for t in tokens if t[0].isalpha() and (s := stem(t.lower())) in own]
        if places:
            return None if _SHOWN.search(" ".join(tokens)) else places[-1]
    return None
