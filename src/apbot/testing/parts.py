"""Which parts of the model format a model uses (:func:`format_parts`), so tests can check
that the random generator reaches every one (:data:`FORMAT_PARTS`)."""

from __future__ import annotations

from apbot.model.domain import build_domain
from apbot.model.schema import Add, ApplianceModel, Conditional, GoTo, OtherThan, Skip

# What :func:`format_parts` can report; the generator is tested to produce every one.
FORMAT_PARTS = (
    "add",
    "anywhere key",
    "leave key",
    "optional step",
    "short hold enters",
    "timeout",
    "keypad other keys clear",
    "keypad shows typed",
    "clamp",
    "conditional effect",
    "confirm step",
    "cycling programme key",
    "dependent setting",
    "dial",
    "entry step",
    "go-to",
    "go-to programme key",
    "hidden display",
    "hold",
    "keypad",
    "keypad clear",
    "large domain",
    "lock guard",
    "missing case",
    "mode guard",
    "none effect",
    "number guard",
    "on_entry show",
    "one-position guard",
    "piecewise",
    "power guard",
    "prev",
    "remembered setting",
    "reset effect",
    "reset side effect",
    "running guard",
    "set side effect",
    "skip",
    "time",
    "time keypad",
    "timed cycle",
    "toggle",
    "two-control hold",
    "two programmes",
    "unreachable values",
    "wrap",
)


def format_parts(model: ApplianceModel) -> set[str]:
    """The parts of the format a model uses (names from :data:`FORMAT_PARTS`)."""
    parts: set[str] = set()
    parents = {v.depends_on for v in model.variables.values() if v.depends_on}
    if len(parents) > 1:
        parts.add("two programmes")
    if model.cycles:
        parts.add("timed cycle")
    for var in model.variables.values():
        if var.unreachable:
            parts.add("unreachable values")
        if var.remember:
            parts.add("remembered setting")
        if var.depends_on:
            parts.add("dependent setting")
            parent_values = build_domain(model.variables[var.depends_on]).values
            if set(parent_values) - set(var.cases or {}):
                parts.add("missing case")
        if getattr(var, "entry", None) is not None:
            parts.add("time keypad" if var.type == "time" else "keypad")
        if var.type == "time":
            parts.add("time")
        ranges = getattr(var, "ranges", None) or []
        if len(ranges) > 1:
            parts.add("piecewise")
        if var.depends_on is None and len(build_domain(var)) > 64:
            parts.add("large domain")
        parts.add("wrap" if var.wrap else "clamp")
    for action in model.actions.values():
        if action.skill == "hold":
            parts.add("two-control hold" if action.controls else "hold")
        if action.too_short == "enters":
            parts.add("short hold enters")
        if action.skill in ("turn_cw", "turn_ccw"):
            parts.add("dial")
    for entry in model.anywhere:
        parts.add("anywhere key")
        if entry.leave:
            parts.add("leave key")
    for var in model.variables.values():
        if getattr(var, "entry", None) is not None and var.entry.other_keys == "clear":  # type: ignore[union-attr]
            parts.add("keypad other keys clear")
        if getattr(var, "entry", None) is not None and var.entry.shows == "typed":  # type: ignore[union-attr]
            parts.add("keypad shows typed")
    for steps in model.features.values():
        for index, step in enumerate(steps):
            if step.optional:
                parts.add("optional step")
            if step.timeout is not None:
                parts.add("timeout")
            if step.variable is None and not step.set and not step.reset:
                parts.add("entry step" if index + 1 < len(steps) else "confirm step")
            if step.on_entry == "show":
                parts.add("on_entry show")
            if step.set:
                parts.add("set side effect")
            if step.reset:
                parts.add("reset side effect")
            effects = list(step.effect.values()) if isinstance(step.effect, dict) else [step.effect]
            for effect in effects:
                if isinstance(effect, Add):
                    parts.add("add")
                elif isinstance(effect, GoTo):
                    parts.add("go-to programme key" if step.variable in parents else "go-to")
                elif isinstance(effect, Skip):
                    parts.add("skip")
                elif isinstance(effect, Conditional):
                    parts.add("conditional effect")
                elif effect in ("prev", "toggle", "none"):
                    parts.add(str(effect) + (" effect" if effect == "none" else ""))
                elif effect == "reset":
                    parts.add("reset effect")
                elif effect == "clear":
                    parts.add("keypad clear")
                if step.variable in parents and effect in ("next", "prev", None):
                    parts.add("cycling programme key")
    for guard in model.guards:
        names = set(guard.when)
        if any(isinstance(w, OtherThan) for w in guard.when.values()):
            parts.add("one-position guard")
        if guard.hide:
            parts.add("hidden display")
        if "power" in names:
            parts.add("power guard")
        elif "lock" in names:
            parts.add("lock guard")
        elif "running" in names:
            parts.add("running guard")
        elif any(model.variables[n].type == "discrete" for n in names):
            parts.add("mode guard")
        else:
            parts.add("number guard")
    return parts
