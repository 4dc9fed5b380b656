"""Instruction → goal with an LLM: a schema built from the belief, validated against it.

Two answer forms, both with the belief's allowed values as enums where there are few enough
(written as text: ``"80"``, ``"00:03:30"``), so a server with constrained decoding cannot name
a value the belief lacks:

- ``list`` (the default): the settings the request names, as ``{setting, value}`` pairs — one
  alternative per variable, so each value is checked against its own setting's domain. A
  grammar-constrained server (llama.cpp) makes every object property required; in this form
  that costs nothing, since a setting the request is silent on is simply not listed.
- ``object``: one property per variable, ``null`` for "not mentioned". Under a grammar every
  property must be written, and a small model asked for null often writes a value instead
  (most misses of the 1.5B local model in this form were such extra settings).

The prompt lists the settings, shows one worked example (a made-up fan heater, so that no
bundled appliance is in it), and gives the offline parser's reading as a hint. The answer is
then normalised by :func:`apbot.model.goal.parse_goal`; its errors go back to the model.

Prompt layout for the server's prompt cache: what is the same for every instruction to one
appliance (the settings, the example) comes first; the instruction and the hint last.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel, ConfigDict, Field, create_model

from apbot.llm.client import LLMClient
from apbot.llm.structured import ask
from apbot.llm.usage import Usage
from apbot.model.domain import all_values
from apbot.model.goal import Goal, GoalError, parse_goal
from apbot.model.schema import ApplianceModel

MAX_ENUM = 80  # more values than this: free text, checked after the answer

GoalForm = Literal["list", "object"]
GOAL_FORMS: tuple[GoalForm, ...] = ("list", "object")

_TASK = (
    "You turn what a user asks of a home appliance into the settings it must end in. "
    "Set only what the request asks for, explicitly or by clear implication (asking to start, "
    "cook, heat or run it now sets the start/running setting; 'don't start yet' sets it off). "
)
SYSTEM: dict[GoalForm, str] = {
    "object": _TASK
    + "Every other setting is null. Use only the allowed values, spelled as listed.",
    "list": _TASK
    + "List only those settings; leave every other one out. Use only the allowed values, "
    "spelled as listed.",
}

_EXAMPLE_HEAD = """Example (another appliance, a fan heater):
settings:
- power: "off" | "on"
- mode: "eco" | "comfort" | "boost"
- temperature (°C): "10" | "11" | … | "30"
- timer (h): "0" | "1" | … | "8"
- oscillation: "off" | "on"
- running: "off" | "on"
request: Warm the room to 22 degrees on eco for two hours and get it going.
"""
EXAMPLE: dict[GoalForm, str] = {
    "object": _EXAMPLE_HEAD
    + """answer: {"power": null, "mode": "eco", "temperature": "22", "timer": "2", \
"oscillation": null, "running": "on"}""",
    "list": _EXAMPLE_HEAD
    + """answer: {"settings": [{"setting": "mode", "value": "eco"}, \
{"setting": "temperature", "value": "22"}, {"setting": "timer", "value": "2"}, \
{"setting": "running", "value": "on"}]}
(power and oscillation are not listed: the request does not ask for them)""",
}

_CLOSING: dict[GoalForm, str] = {
    "object": "Give every setting of this appliance, null where the request does not ask for it.",
    "list": "List every setting the request asks for, each once, with what it implies (asking "
    "to start or run it now sets the running/start setting; switching it on sets power; a "
    "clock time or a delay it names sets that setting); leave the others out.",
}


@dataclass
class LLMGoal:
    """A goal read by the LLM (canonical values), what it cost, and the hint it was given."""

    goal: Goal
    usage: Usage
    attempts: int
    hint: str


def _text(value: Any) -> str:
    return str(value)


def _values(var: Any) -> list[Any]:
    """The variable's values (every case's, for a dependent one), in order."""
    values = all_values(var)
    if var.type != "discrete" and all(isinstance(v, int | float) for v in values):
        return sorted(values)
    if var.type == "time":
        return sorted(values, key=str)
    return values


def _shown(var: Any) -> str:
    values = _values(var)
    if len(values) > MAX_ENUM:
        return f'text, from "{_text(values[0])}" to "{_text(values[-1])}"'
    if len(values) > 12 and var.type != "discrete":
        head = " | ".join(f'"{_text(v)}"' for v in values[:3])
        return f'{head} | … | "{_text(values[-1])}"'
    return " | ".join(f'"{_text(v)}"' for v in values)


def describe_settings(model: ApplianceModel) -> list[str]:
    """One line per variable: its name, label, unit and allowed values (or their range)."""
    lines = []
    for name, var in model.variables.items():
        label = f" [{var.label}]" if var.label and var.label.lower() != name else ""
        unit = getattr(var, "unit", "")
        unit_text = f" ({unit})" if unit else ""
        if var.type == "time":
            unit_text = f" (time {var.format})"
        extra = f" (depends on {var.depends_on})" if var.depends_on else ""
        lines.append(f"- {name}{label}{unit_text}{extra}: {_shown(var)}")
    return lines


def _value_type(var: Any) -> Any:
    """The answer's type for one variable's value: an enum of its values, or free text."""
    values = _values(var)
    if len(values) <= MAX_ENUM:
        return Literal[tuple(dict.fromkeys(_text(v) for v in values))]
    return str


def goal_schema(model: ApplianceModel) -> type[BaseModel]:
    """The object form: one optional property per variable (its values as an enum)."""
    fields: dict[str, Any] = {}
    for index, (name, var) in enumerate(model.variables.items()):
        fields[f"v{index}"] = (_value_type(var) | None, Field(default=None, alias=name))
    return create_model(
        "Goal",
        __config__=ConfigDict(populate_by_name=False, extra="forbid"),
        **fields,
    )


def goal_list_schema(model: ApplianceModel) -> type[BaseModel]:
    """The list form: ``settings`` holds ``{setting, value}`` pairs, one alternative per
    variable (its name as a constant, its values as an enum), at most one pair per variable.
    The alternatives are told apart by ``setting``, so a wrong value is reported against its
    own setting's values only (the adapter sends the union as a plain ``anyOf``)."""
    pairs: list[Any] = []
    for index, (name, var) in enumerate(model.variables.items()):
        tag: Any = Literal[name]  # a name known only at run time: a Literal built from it
        pairs.append(
            create_model(
                f"Setting{index}",
                __config__=ConfigDict(extra="forbid"),
                setting=(tag, ...),
                value=(_value_type(var), ...),
            )
        )
    item: Any = pairs[0]
    if len(pairs) > 1:
        item = Annotated[Union[tuple(pairs)], Field(discriminator="setting")]  # noqa: UP007
    return create_model(
        "Goal",
        __config__=ConfigDict(extra="forbid"),
        settings=(list[item], Field(max_length=len(pairs))),
    )


def _answer_goal(answer: BaseModel) -> dict[str, Any]:
    pairs = getattr(answer, "settings", None)
    if isinstance(pairs, list):
        return {pair.setting: pair.value for pair in pairs}
    return {k: v for k, v in answer.model_dump(by_alias=True).items() if v is not None}


def _repeated(answer: BaseModel) -> list[str]:
    """Settings a list answer names more than once (the goal would keep only the last)."""
    pairs = getattr(answer, "settings", None)
    if not isinstance(pairs, list):
        return []
    seen: set[str] = set()
    twice: list[str] = []
    for pair in pairs:
        if pair.setting in seen and pair.setting not in twice:
            twice.append(pair.setting)
        seen.add(pair.setting)
    return twice


def _check(model: ApplianceModel) -> Any:
    def check(answer: BaseModel) -> list[str]:
        twice = _repeated(answer)
        if twice:
            return [f"settings: {name} is listed more than once; list it once" for name in twice]
        goal = _answer_goal(answer)
        if not goal:
            return ["no setting is set: the request asks for at least one"]
        try:
            parse_goal(model, goal)
        except GoalError as exc:
            return [f"{p.where}: {p.message}" for p in exc.problems]
        return []

    return check


def offline_hint(model: ApplianceModel, instruction: str, manual: str = "") -> str:
    """The offline parser's reading, as a line of the prompt (it may be wrong).

    With the manual, as the offline parser is used elsewhere: without it the hint lacks the
    values a panel shows only as codes (a bread maker's menu numbers).
    """
    from apbot.read.goal import GoalParseError, parse_instruction

    try:
        parsed = parse_instruction(model, instruction, manual)
    except GoalParseError as exc:
        return f"A rule-based parser could not read it ({exc}); it may be wrong."
    except Exception:  # a parser bug must not stop the LLM path
        return ""
    text = json.dumps({k: _text(v) for k, v in parsed.items()}, ensure_ascii=False)
    return f"A rule-based parser read (it may be wrong or miss things): {text}"


def goal_messages(
    model: ApplianceModel, instruction: str, hint: str, form: GoalForm = "list"
) -> list[dict[str, Any]]:
    settings = "\n".join(describe_settings(model))
    user = (
        f"{EXAMPLE[form]}\n\nThis appliance:\nsettings:\n{settings}\n"
        f"request: {instruction.strip()}\n" + (f"{hint}\n" if hint else "") + _CLOSING[form]
    )
    return [{"role": "system", "content": SYSTEM[form]}, {"role": "user", "content": user}]


def llm_parse_instruction(
    model: ApplianceModel,
    instruction: str,
    client: LLMClient,
    *,
    use_hint: bool = True,
    repeat: int | None = None,
    manual: str = "",
    form: GoalForm = "list",
) -> LLMGoal:
    """Read ``instruction`` into a goal over ``model``; raises ``StructuredError`` when no
    valid answer comes within the allowed attempts. ``manual`` goes to the offline hint;
    ``form`` picks the answer's shape (see the module's docstring)."""
    if form not in GOAL_FORMS:
        raise ValueError(f"goal form {form!r}: expected one of {', '.join(GOAL_FORMS)}")
    hint = offline_hint(model, instruction, manual) if use_hint else ""
    schema = goal_list_schema(model) if form == "list" else goal_schema(model)
    per_setting = 24 if form == "object" else 32
    answer = ask(
        client,
        goal_messages(model, instruction, hint, form),
        schema,
        check=_check(model),
        max_tokens=40 + per_setting * len(model.variables),
        repeat=repeat,
    )
    goal = parse_goal(model, _answer_goal(answer.value))
    return LLMGoal(goal, answer.usage, answer.attempts, hint)
