"""The mode a setting's value implies. A setting the automatic programmes fix (a melt
temperature of 50 in DARK, 45 in MILK, 40 in WHITE, free 40-55 only in MANUAL) given a value only
its one free case admits can only be set there: the goal holds that mode too. So does a setting
whose every procedure first puts a mode to one value (CONVECTION, then the temperature typed).

Nothing is guessed: when two cases admit the value, or the mode starts in that case anyway (what
the panel shows before anything is pressed), the mode is left as the user left it. Nor is it
set for a setting that other cases merely lack (MODE: POWER / TEMPERATURE, each with its own
setting): such a mode chooses what the keys adjust, and saying the setting is choosing it —
unless the setting's case is the only one of three or more ways of working with a setting at
all (ALWAYS ON / DUSK TO DAWN / DUSK TIMER with its hours): then the setting asks for it."""

from __future__ import annotations

from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import DiscreteVariable, GoTo
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_view import Goal, Model, own_concepts, step_effects
from apbot.read.goal_vocab import stem


def implied_cases(view: Model, goal: Goal, start_known: bool = True) -> None:
    """Set the mode of each goal setting that only one case of that mode lets the user adjust
    (the others lack it or fix it at one value), given a value that case admits.
    ``start_known`` False (a read belief): a mode whose start the belief does not state is not
    assumed to start in its first value (:func:`_starts_at`)."""
    for name in list(goal):
        var = view.infos[name].var
        parent = var.depends_on
        if not parent or not var.cases or parent in goal or parent not in view.infos:
            continue
        mode = view.infos[parent]
        if mode.role != "setting" or not isinstance(mode.var, DiscreteVariable):
            continue
        admitting = [
            case for case in mode.values if _admits(var, var.cases.get(str(case)), goal[name])
        ]
        sizes = [_size(var, var.cases.get(str(case))) for case in mode.values]
        free = [case for case, size in zip(mode.values, sizes, strict=True) if size > 1]
        apart = len(free) > 1 and _apart(var, mode.values)  # the value tells the case
        named = len(free) > 1 and _named_choice(var, goal[name])  # "continuity": only Ω has it
        if len(admitting) != 1 or (free != admitting and not apart and not named):
            continue  # adjusted in other cases too (a guess)
        if 1 not in sizes and not (apart or named or _way_of_working(view, parent, admitting[0])):
            continue  # no case fixes it: the mode may only choose what the keys adjust
        if str(admitting[0]) == str(_starts_at(mode.var, start_known)):
            continue  # the panel is in that case before anything is pressed
        goal[parent] = admitting[0]


def entry_modes(view: Model, goal: Goal, start_known: bool = True) -> None:
    """Set the mode each goal setting's procedures all enter first (a key that goes to one
    value of a mode, then the setting's own step), unless the panel starts in it (``start_known``
    as for :func:`implied_cases`)."""
    for name in list(goal):
        if view.infos[name].role != "setting":
            continue
        common: set[tuple[str, str]] | None = None
        for steps in view.model.features.values():
            for index, step in enumerate(steps):
                if step.variable != name:
                    continue
                entered = _entered(steps[:index], name)
                common = entered if common is None else common & entered
        for mode_name, value in sorted(common or ()):
            mode = view.infos.get(mode_name)
            if mode is None or mode_name in goal or mode.role != "setting":
                continue
            if view.infos[name].var.depends_on == mode_name:
                continue  # a case of that mode: implied_cases has judged it
            if not isinstance(mode.var, DiscreteVariable):
                continue
            chosen = next((v for v in mode.values if str(v) == value), None)
            if chosen is not None and str(chosen) != str(_starts_at(mode.var, start_known)):
                goal[mode_name] = chosen


def _entered(earlier: list[Any], name: str) -> set[tuple[str, str]]:
    """(mode, value) of each earlier step whose keys all put a mode to the same one value."""
    found: set[tuple[str, str]] = set()
    for step in earlier:
        if step.variable in (None, name):
            continue
        effects = [effect for _action, effect in step_effects(step)]
        targets = {str(e.to) for e in effects if isinstance(e, GoTo)}
        if effects and len(targets) == 1 and all(isinstance(e, GoTo) for e in effects):
            found.add((step.variable, targets.pop()))
    return found


def _apart(var: Any, cases: list[Any]) -> bool:
    """Every case that has the setting gives it values no other case has (COLD 4-10 °C, HOT
    45-100 °C): a value then tells the case, as a unit would."""
    seen: set[str] = set()
    for case in cases:
        spec = (var.cases or {}).get(str(case))
        if spec is None:
            continue
        try:
            values = {str(v) for v in build_domain(var, spec).values}
        except ValueError:
            return False
        if values & seen:
            return False
        seen |= values
    return True


def _named_choice(var: Any, value: Any) -> bool:
    """A discrete setting's value named by a word, not a number ("continuity", "fahrenheit"):
    a sub-function whose choices differ with the mode (a meter's SELECT: Ω / continuity /
    diode on the Ω position, °C / °F on TEMP), so the one case that has it is the one meant."""
    return isinstance(var, DiscreteVariable) and any(c.isalpha() for c in str(value))


def _way_of_working(view: Model, parent: str, case: Any) -> bool:
    """``case`` is the only one of three or more cases of mode ``parent`` with a setting of its
    own (DUSK TIMER's hours beside ALWAYS ON and DUSK TO DAWN): the mode is a way of working,
    and saying that setting asks for it. Not a mode whose cases each have their own setting
    (POWER / TEMPERATURE: it chooses what the keys adjust), nor a two-way AUTO / MAN whose
    other case only works the setting out itself (saying the hours is choosing them), nor a
    MANUAL case beside automatic ones (asked for only when the user says they set it)."""
    mode = view.infos[parent]
    if isinstance(mode.var, DiscreteVariable) and _manual(mode.var, case):
        return False  # MANUAL beside automatic ways: set only when said by hand (set_by_hand)
    values = mode.values
    dependents = [i.var for i in view.infos.values() if i.var.depends_on == parent]
    owning = [
        value
        for value in values
        if any(_size(var, (var.cases or {}).get(str(value))) > 0 for var in dependents)
    ]
    return len(values) >= 3 and owning == [case]


def _size(var: Any, spec: Any) -> int:
    """Values the setting can take in one case (0: the case lacks it)."""
    if spec is None:
        return 0
    try:
        return len(build_domain(var, spec).values)
    except ValueError:
        return 0


def _admits(var: Any, spec: Any, value: Any) -> bool:
    if spec is None:
        return False
    try:
        values = build_domain(var, spec).values
    except ValueError:
        return False
    return any(str(v) == str(value) or _same_number(v, value) for v in values)


def _same_number(a: Any, b: Any) -> bool:
    try:
        return abs(float(a) - float(b)) < 1e-9
    except (TypeError, ValueError):
        return False


def _starts_at(var: DiscreteVariable, start_known: bool = True) -> Any:
    """The value the panel starts in: the stated one, else the first — which a model's author
    means, but a belief read from a manual only guesses (the first key the manual names, not
    what the panel shows when switched on): then None, no start known."""
    initial = getattr(var, "initial", None)
    if initial is not None:
        return initial
    if not start_known:
        return None
    return var.values[0] if var.values else None


_BY_HAND = frozenset({"myself", "ourselves"})
_MANUAL = frozenset({stem("manual"), stem("man")})


def set_by_hand(view: Model, text: Text, goal: Goal) -> None:
    """ "I'll set the hours myself", "set the mist myself": the user sets that setting by hand,
    so the mode it depends on is its MANUAL case (the automatic ones choose it themselves) —
    unless the panel starts in MANUAL anyway. Only a setting named in the same clause."""
    for k, token in enumerate(text.tokens):
        own = token.text == "own" and text.word(k - 1) in ("my", "our")
        if token.text not in _BY_HAND and not own:
            continue
        clause = _clause(text, k)
        if any(_denial(text.word(j)) for j in clause if j < k):
            continue  # "I don't want to pick the speed myself": not by hand
        if not own and not _chooses(text, clause):
            continue  # "I'll refill the tank myself": something else done by hand
        if own and _own_programme(view, text, goal, k):
            continue  # "my own recipe": the CUSTOM (MANUAL, USER) programme
        for info in view.infos.values():
            parent = info.var.depends_on
            mode = view.infos.get(parent or "")
            if mode is None or parent in goal or not info.var.cases:
                continue
            if mode.role != "setting" or not isinstance(mode.var, DiscreteVariable):
                continue
            manual = [v for v in mode.values if _manual(mode.var, v)]
            if len(manual) != 1 or str(manual[0]) not in info.var.cases:
                continue
            if str(manual[0]) == str(_starts_at(mode.var)):
                continue
            if own_concepts(info) & {text.concepts[j] for j in clause}:
                goal[mode.name] = manual[0]
        if not any(i.var.depends_on for i in view.infos.values()):
            _by_hand_unlinked(view, text, goal, clause)


_OWN_KINDS = frozenset(
    stem(w) for w in ("setting", "settings", "recipe", "recipes", "programme", "program", "mode")
)
_OWN_VALUES = _MANUAL | frozenset({stem("custom"), stem("user"), stem("personal")})


def _own_programme(view: Model, text: Text, goal: Goal, k: int) -> bool:
    """ "my own settings", "my own recipe" (own at k): the one selector with a value kept for
    the user's own settings — CUSTOM, MANUAL, USER beside presets — is set to it."""
    following = text.stems[k + 1] if k + 1 < len(text.stems) else ""
    if following not in _OWN_KINDS:
        return False  # "I'll do it on my own": no programme named
    found = []
    for info in view.infos.values():
        if info.role != "setting" or not isinstance(info.var, DiscreteVariable):
            continue
        own = [v for v in info.values if _own_value(info.var, v)]
        if len(own) == 1 and len(info.values) > 2:
            found.append((info.name, own[0]))
    if len(found) != 1 or found[0][0] in goal:
        return False
    goal[found[0][0]] = found[0][1]
    return True


def _own_value(var: DiscreteVariable, value: Any) -> bool:
    """The value is the user's own (CUSTOM, MANUAL, USER, or shown so)."""
    show = var.show.get(str(value), "") if isinstance(var.show, dict) else ""
    words = f"{value} {show}".casefold().replace("_", " ").split()
    return any(stem(w) in _OWN_VALUES for w in words)


# what one does to a setting by hand: "set", "pick", "adjust" it ("check the fan myself",
# "add the water myself", "clean the filter myself" do something else with it)
_CHOOSING = frozenset(
    stem(w)
    for w in (
        "set", "setting", "choose", "choosing", "pick", "picking", "select", "selecting",
        "adjust", "adjusting", "control", "controlling", "decide", "deciding", "program",
        "programme", "dial", "tune", "change", "changing", "regulate", "manage", "tweak",
        "fiddle",
    )
)  # fmt: skip


def _chooses(text: Text, clause: range) -> bool:
    """The clause of "myself" says the user sets something ("I'll pick the fan myself")."""
    return any(stem(text.word(j)) in _CHOOSING for j in clause)


def _by_hand_unlinked(view: Model, text: Text, goal: Goal, clause: range) -> None:
    """The same on a model that says nothing of which mode a setting depends on (a belief read
    from a manual seldom does): the one selector with a MANUAL value beside others (AUTO, the
    presets) is set to MANUAL when the clause of "myself" names another adjustable setting, or
    the quantity it measures — not a clock, which no mode chooses — unless the panel starts in
    MANUAL."""
    modes = [
        i
        for i in view.infos.values()
        if i.role == "setting"
        and isinstance(i.var, DiscreteVariable)
        and len(i.values) > 1
        and sum(_manual(i.var, v) for v in i.values) == 1
    ]
    if len(modes) != 1 or modes[0].name in goal:
        return
    mode, var = modes[0], modes[0].var
    assert isinstance(var, DiscreteVariable)
    manual = next(v for v in mode.values if _manual(var, v))
    if str(manual) == str(_starts_at(var)):
        return
    said = {text.concepts[j] for j in clause}
    for info in view.infos.values():
        if info is mode or info.role != "setting" or info.timing in ("clock", "at"):
            continue
        if own_concepts(info) & said or (info.dimension and stem(info.dimension) in said):
            goal[mode.name] = manual  # "the mist", or what it measures: "the temperatures"
            return


_DENIALS = frozenset({"not", "no", "never", "nor", "without", "dont", "cannot"})


def _denial(word: str) -> bool:
    """A word that denies what follows it ("don't", "won't", "never", "no need")."""
    return word in _DENIALS or word.endswith("n't")


def _clause(text: Text, k: int) -> range:
    """The positions of the clause around k, up to a full stop, a comma or a dash."""
    ends = CLAUSE_ENDS | {"-", ":", ","}
    start = k
    while start > 0 and text.word(start - 1) not in ends:
        start -= 1
    end = k
    while end + 1 < len(text.tokens) and text.word(end + 1) not in ends:
        end += 1
    return range(start, end + 1)


def _manual(var: DiscreteVariable, value: Any) -> bool:
    """The value is MANUAL (or its display's MAN)."""
    show = var.show.get(str(value), "") if isinstance(var.show, dict) else ""
    words = f"{value} {show}".casefold().replace("_", " ").split()
    return any(stem(w) in _MANUAL for w in words)
