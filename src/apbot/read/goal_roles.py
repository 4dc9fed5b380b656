"""Which variables of a model are its power and its running state, and what START sets.

Part of the goal parser's view of a model (:mod:`apbot.read.goal_view`): the power switch hides
the panel or is called power; the running variable is what a START key sets or is named for an
operation under way. Read from the model's own names and procedures only.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from apbot.model.domain import all_values
from apbot.model.schema import AnywhereStep, ApplianceModel, DiscreteVariable, GoTo, Step
from apbot.read.goal_values import OFF_WORDS, ON_WORDS, name_words
from apbot.read.goal_vocab import concept

if TYPE_CHECKING:
    from apbot.read.goal_view import VarInfo

_OPERATION_NAMES = frozenset(
    w
    for w in (
        "running",
        "run",
        "heating",
        "cooking",
        "dispensing",
        "pouring",
        "status",
        "state",
        "operation",
        "washing",
        "brewing",
        "working",
    )
)


START_LABELS = ("start", "run", "go", "begin", "dispense", "pour")

_PLAY_STOP = re.compile(r"[▶►]\s*/?\s*[■‖⏸⏹]|⏯")
"""A key marked play-and-stop ("▶/■", "▶‖"), with no word: it starts and stops the work, so
the switch it toggles is the running state (a lone "▶" is as often an arrow: "next")."""


def steps_of(model: ApplianceModel) -> Iterable[tuple[str, int, Step | AnywhereStep]]:
    """Every step of every feature, and the keys that act from anywhere (START, CANCEL) as
    one-step procedures of their own."""
    for feature, steps in model.features.items():
        for index, step in enumerate(steps):
            yield feature, index, step
    for index, anywhere in enumerate(model.anywhere):
        yield f"anywhere_{index}", 0, anywhere


def control_labels(model: ApplianceModel, actions: Iterable[str]) -> list[str]:
    labels: list[str] = []
    controls = {c.id: c for c in model.controls}
    for action_id in actions:
        action = model.actions.get(action_id)
        if action is None:
            continue
        for cid in [action.control] if action.control else list(action.controls or []):
            control = controls.get(cid or "")
            if control is not None and control.label:
                labels.append(control.label)
    return labels


def step_effects(step: Step | AnywhereStep) -> list[tuple[str, Any]]:
    """(action, effect) pairs of a step."""
    if isinstance(step.effect, dict):
        return list(step.effect.items())
    return [(a, step.effect) for a in step.actions]


def mark_power_and_running(model: ApplianceModel, infos: dict[str, VarInfo]) -> None:
    """The power switch hides the panel (or is called power); the running variable is what a
    START key sets, or is named for an operation (heating, dispensing, status)."""
    hiding = {name for guard in model.guards if guard.hide for name in guard.when}
    for name, info in infos.items():
        dark = name in hiding and concept("lock") not in info.vocab  # a panel that goes dark
        named = name in ("power", "on_off", "power_switch") or dark
        if info.role == "switch" and named:
            info.role = "power"
    if not any(info.role == "power" for info in infos.values()):
        _power_by_symbol(model, infos)
    for _feature, _index, step in steps_of(model):
        pressed = [a for a in step.actions if model.actions[a].skill == "press"]
        labels = " ".join(control_labels(model, pressed)).casefold()
        play_stop = bool(_PLAY_STOP.search(labels))
        if not play_stop and not any(word in name_words(labels) for word in START_LABELS):
            continue
        goes = any(isinstance(effect, GoTo) for _a, effect in step_effects(step))
        goes = goes or (play_stop and any(e == "toggle" for _a, e in step_effects(step)))
        goes = goes or _named_for_key(step.variable or "", labels)
        targets = [step.variable] if step.variable and goes else []
        targets += list(step.set)
        for target in targets:
            found = infos.get(target or "")
            if (
                found is not None
                and isinstance(found.var, DiscreteVariable)
                and found.role != "power"
                and concept("lock") not in found.vocab
                and (_operation(target or "") or found.role == "switch")
            ):
                found.role = "running"
    for name, info in infos.items():
        operation = _operation(name)
        if (
            operation
            and info.role in ("switch", "setting")
            and isinstance(info.var, DiscreteVariable)
        ):
            info.role = "running"
    if not any(info.role == "running" for info in infos.values()):
        doing = [i for n, i in infos.items() if i.role == "switch" and doing_name(n)]
        if len(doing) == 1:
            doing[0].role = "running"  # PRINTING, CARBONATING: the work under way


_POWER_MARKS = re.compile(r"^\s*(?:[⏻⏼⏽]|power)\s*$", re.IGNORECASE)


def _power_by_symbol(model: ApplianceModel, infos: dict[str, VarInfo]) -> None:
    """The one switch labelled with the power symbol ⏻ (or POWER), by its own label or its
    key's, is the power on a model that has none by name: a belief that read the key held to
    switch on as ``power_hold`` (a RUNNING the key starts stays the running state; an ON/OFF
    key switches as often one zone as the whole)."""
    marked = set()
    for _feature, _index, step in steps_of(model):
        labels = control_labels(model, step.actions)
        if step.variable and any(_POWER_MARKS.match(label) for label in labels):
            marked.add(step.variable)
    marked |= {n for n, i in infos.items() if _POWER_MARKS.match(i.var.label or "")}
    found = [
        n
        for n in marked
        if n in infos
        and infos[n].role == "switch"
        and not _operation(n)
        and not infos[n].var.depends_on  # one zone's own switch
        and concept("lock") not in infos[n].vocab  # hold ⏻ to lock it for travel
        and _named_as_power(n)  # a POWER key's BOOST, a ⏻ key's LIGHT: that part's switch
    ]
    if len(found) == 1:
        infos[found[0]].role = "power"


_POWER_NAME_WORDS = frozenset(
    {"power", "main", "hold", "on", "off", "onoff", "switch", "standby", "key", "button", "unit"}
)


def _named_as_power(name: str) -> bool:
    """A switch whose name says nothing but power (``power_hold``, ``main_hold``) or the work
    under way (``brushing``): one named for a part of its own (BOOST of a vacuum's POWER key,
    LIGHT) is that part's switch, whatever symbol its key carries."""
    words = name.casefold().split("_")
    return doing_name(name) or all(w in _POWER_NAME_WORDS for w in words)


def doing_name(name: str) -> bool:
    """A one-word name of a doing ("printing", "carbonating", "swinging"): on a model with no
    running state otherwise, the switch that is the work under way, which "start" sets — not a
    thing named with it ("candling light", "daily drying"), nor a general RUNNING, HEATING."""
    words = name.casefold().split("_")
    one = len(words) == 1 and words[0] not in _OPERATION_NAMES
    return one and words[0].endswith("ing") and len(words[0]) > 5


def _past_question(var: Any, later: list[Any]) -> Any:
    """The state START asks for among those after the first (READY, CONFIRM, FRYING): the
    first, unless it is a question on the display ("START?", CONFIRM) — a state that waits for
    a second press — then the one after it: the work under way is what the user wants."""
    if len(later) >= 2 and _asks(var, later[0]):
        return later[1]
    return later[0] if later else None


def _asks(var: Any, value: Any) -> bool:
    """The state is a question: its display text ends in "?", or it is named CONFIRM."""
    shown = var.show.get(str(value)) if isinstance(getattr(var, "show", None), dict) else None
    said = str(value).casefold()
    return (isinstance(shown, str) and shown.strip().endswith("?")) or said.startswith("confirm")


def _named_for_key(name: str, labels: str) -> bool:
    """A switch named for the operation its own key starts (DISPENSE toggles ``dispense``): the
    operation under way, started by the operation's verbs, not a setting."""
    own = name_words(name)
    return bool(own) and all(w in START_LABELS and w in name_words(labels) for w in own)


def _operation(name: str) -> bool:
    """A variable named for an operation under way ("running", "heating", "brew_status"), not
    a setting that shares a stem with one ("heat" is a level, "heating" is running)."""
    return bool(set(name.casefold().split("_")) & _OPERATION_NAMES)


def start_values_of(
    model: ApplianceModel, infos: dict[str, VarInfo]
) -> dict[str | None, tuple[str, Any]]:
    """What START sets the running variable to: by the variable whose feature ends with it
    (a timer programme ends in "timer" rather than "cooking"), and in general (key None)."""
    found: dict[str | None, tuple[str, Any]] = {}
    running = [n for n, i in infos.items() if i.role == "running"]
    procedures: list[list[Step | AnywhereStep]] = [list(s) for s in model.features.values()]
    procedures += [[anywhere] for anywhere in model.anywhere]
    for steps in procedures:
        adjusted = [s.variable for s in steps if s.variable and s.variable not in running]
        for step in steps:
            for action, effect in step_effects(step):
                if not isinstance(effect, GoTo) or step.variable not in running:
                    continue
                labels = " ".join(control_labels(model, [action])).casefold()
                if not any(word in name_words(labels) for word in START_LABELS):
                    continue
                if str(effect.to).casefold() in OFF_WORDS:
                    continue  # START held to cancel: it stops, it does not start
                value = (step.variable, effect.to)
                if len(steps) == 1 or not adjusted:
                    found.setdefault(None, value)
                for var in adjusted:
                    found.setdefault(var, value)
    for name in running:
        info = infos[name]
        known = all_values(info.var)  # a dependent running state has its values per case
        said_on = (v for v in info.values if str(v).casefold() in ON_WORDS)  # off/request/on
        on = info.on or next(said_on, None)
        on = on or _past_question(info.var, [v for v in info.values if known and v != known[0]])
        if on is not None:
            found.setdefault(None, (name, on))
    return found
