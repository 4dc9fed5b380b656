"""Load a model from YAML/JSON text into the schema, turning every failure into a :class:`Problem`.

YAML syntax errors, schema errors and semantic errors all come back as one
:class:`~apbot.model.problems.ModelError` whose problems name a path such as
``features.set_delay[1].actions`` and, when the text is at hand, its line number.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from pydantic import ValidationError

from apbot.model.problems import MORE, ModelError, PathPart, Problem
from apbot.model.schema import ApplianceModel
from apbot.model.values import closest_matches
from apbot.model.yaml_text import dump_yaml, line_of, read_text, read_yaml

_UNION_TAGS = {
    "discrete",
    "numeric",
    "time",
    "GoTo",
    "Add",
    "Skip",
    "Conditional",
    "OtherThan",
    "DiscreteCase",
    "NumericCase",
    "TimeCase",
    "function-after[_domain_given_once(), DiscreteVariable]",
}


def _clean_loc(loc: tuple[Any, ...]) -> tuple[PathPart, ...]:
    parts: list[PathPart] = []
    for part in loc:
        text = str(part)
        if text == "[key]":
            continue
        if text in _UNION_TAGS or text.startswith(("literal[", "function-", "list[", "dict[")):
            continue
        if text in ("str", "int", "float", "bool", "tuple"):
            continue
        parts.append(part)
    return tuple(parts)


MAX_REPORTED = 100
"""Problems explained in full; past this many, one more line counts the rest."""

_FIELD_HINTS = {
    "string_pattern_mismatch": "ids use lowercase letters, digits and underscores, "
    "starting with a letter",
    "missing": "this key is required",
}


def _message(error: Any, model_fields: dict[str, list[str]]) -> str:
    kind = error["type"]
    loc = error["loc"]
    if kind == "extra_forbidden":
        key = str(loc[-1])
        return f"unknown key {key!r}" + _hint_for_key(key, loc, model_fields)
    if kind == "missing":
        return f"missing required key {str(loc[-1])!r}"
    if kind == "union_tag_invalid":
        return "`type` must be discrete, numeric or time"
    if kind == "union_tag_not_found":
        return "missing `type` (discrete, numeric or time)"
    if kind == "string_pattern_mismatch":
        return f"{error.get('input')!r}: {_FIELD_HINTS[kind]}"
    context = error.get("ctx") or {}
    if kind == "too_short" and context.get("actual_length") == 0:
        return f"is empty; give at least {context.get('min_length', 1)}"
    if kind == "string_too_short":
        return (
            f"{error.get('input')!r} is too short: at least {context.get('min_length')} characters"
        )
    if kind == "string_type" and isinstance(error.get("input"), bool):
        word = "on/yes/true" if error["input"] else "off/no/false"
        return (
            f"YAML read this as the boolean {error['input']} (it does so for {word}); "
            'quote it, e.g. "off"'
        )
    message = str(error["msg"])
    if message.startswith("Value error, "):
        message = message[len("Value error, ") :]
    return message


def _hint_for_key(key: str, loc: tuple[Any, ...], fields: dict[str, list[str]]) -> str:
    """A near spelling of a known key, or, for a key that is right but in the wrong place
    (``wrap`` on a feature step, where it belongs to the variable), where it belongs."""
    owners = [_OWNER_WORDS.get(owner, owner) for owner, names in fields.items() if key in names]
    if owners:
        return f"; {key!r} is a key of {' or '.join(dict.fromkeys(owners))}, not of this part"
    options = [f for names in fields.values() for f in names]
    close = closest_matches(key, options, limit=1)
    return f"; did you mean {close[0]!r}?" if close else ""


_OWNER_WORDS = {
    "Appliance": "`appliance`",
    "Control": "a control",
    "Action": "an action",
    "Entry": "an entry",
    "DiscreteVariable": "a variable",
    "NumericVariable": "a variable",
    "TimeVariable": "a variable",
    "Step": "a feature step",
    "Guard": "a guard",
    "Display": "`display`",
    "ApplianceModel": "the model's top level",
}


def _known_fields() -> dict[str, list[str]]:
    from apbot.model import schema

    names: dict[str, list[str]] = {}
    for cls in (
        schema.Appliance,
        schema.Control,
        schema.Action,
        schema.Entry,
        schema.DiscreteVariable,
        schema.NumericVariable,
        schema.TimeVariable,
        schema.Step,
        schema.Guard,
        schema.Display,
        schema.ApplianceModel,
    ):
        names[cls.__name__] = list(cls.model_fields)
    return names


def schema_problems(error: ValidationError, text: str | None = None) -> list[Problem]:
    """Problems from a pydantic error, one per location, with union noise collapsed."""
    fields = _known_fields()
    by_path: dict[tuple[PathPart, ...], list[str]] = {}
    effect_paths: set[tuple[PathPart, ...]] = set()
    skipped: set[tuple[PathPart, ...]] = set()
    for item in error.errors():
        loc = tuple(item["loc"])
        if loc and loc[-1] == "[key]" and isinstance(item.get("input"), bool):
            loc = (*loc[:-2], str(item["input"]).lower())  # pydantic shows the key False as 0
        path = _clean_loc(loc)
        if "effect" in path and item["type"] not in ("extra_forbidden",):
            index = path.index("effect")
            effect_path = path[: index + 1] + tuple(
                p
                for p in path[index + 1 : index + 2]
                if str(p) not in ("to", "add", "skip", "when", "then", "otherwise")
            )
            effect_paths.add(effect_path)
            continue
        if path not in by_path and len(by_path) >= MAX_REPORTED:
            skipped.add(path)  # counted, not explained: a hint per key costs a difflib search
            continue
        by_path.setdefault(path, [])
        message = _message(item, fields)
        if message not in by_path[path]:
            by_path[path].append(message)
    for path in effect_paths:
        by_path.setdefault(path, []).append(
            "an effect is next, prev, toggle, digit, clear, reset, none, {to: VALUE}, "
            "{skip: N}, {when: CONDITIONS, then: EFFECT, otherwise: EFFECT} or "
            "{add: AMOUNT}; or a map from each action of the step to one of these"
        )
    problems = []
    for path, messages in by_path.items():
        # a union that failed every branch reports each; keep the most specific one
        message = messages[0] if len(messages) > 2 else "; ".join(messages)
        problems.append(Problem(path, message, "schema", line=line_of(text, path)))
    skipped -= by_path.keys()
    if skipped:
        problems.append(_more(len(skipped), "schema"))
    return problems


def _more(count: int, check: str) -> Problem:
    return Problem(
        (), f"{MORE}{count:,} more problem(s) like these; fix the ones above first", check
    )


def capped(problems: list[Problem], limit: int = MAX_REPORTED) -> list[Problem]:
    """At most ``limit`` problems, errors first, and one line counting the rest."""
    if len(problems) <= limit:
        return problems
    ordered = sorted(problems, key=lambda p: p.severity != "error")
    return [*ordered[:limit], _more(len(ordered) - limit, ordered[limit].check)]


def parse_model(
    data: Any, source: str | None = None, text: str | None = None, check: bool = True
) -> ApplianceModel:
    """Validate plain data as a model; with ``check``, also run the semantic checks.

    Raises :class:`ModelError` when there is any error (warnings alone do not raise).
    """
    if not isinstance(data, dict):
        raise ModelError(
            [
                Problem(
                    (),
                    "a model is a mapping with keys appliance, controls, "
                    "variables, actions, features",
                    "schema",
                    line=1,
                )
            ],
            source,
        )
    try:
        model = ApplianceModel.model_validate(data)
    except ValidationError as exc:
        raise ModelError(schema_problems(exc, text), source) from None
    if check:
        from apbot.model.validate import check_model

        problems = check_model(model)
        if any(p.severity == "error" for p in problems):
            located = [
                Problem(p.path, p.message, p.check, p.severity, line_of(text, p.path))
                for p in capped(problems)
            ]
            raise ModelError(located, source)
    return model


def load_model(source: str | Path, check: bool = True) -> ApplianceModel:
    """Load a model file (YAML or JSON). See :func:`parse_model`."""
    path = Path(source)
    text = read_text(path)
    return parse_model(read_yaml(text, str(path)), str(path), text, check=check)


def loads_model(text: str, check: bool = True, source: str | None = None) -> ApplianceModel:
    """Load a model from YAML (or JSON) text."""
    return parse_model(read_yaml(text, source), source, text, check=check)


def model_to_yaml(model: ApplianceModel) -> str:
    """The model as YAML text, without defaults, ready to be loaded again."""
    data = model.model_dump(mode="json", exclude_defaults=True)
    return dump_yaml(data)
