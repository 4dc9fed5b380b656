"""Manual → model with an LLM, in stages like the paper: controls, variables, procedures.

1. **controls** — for every action name, the control's label in the manual and what it does;
2. **variables** — the settings, their kinds and values or ranges, checked one by one
   (a domain the model format cannot build goes back with its error);
3. **procedures** (features) — macro actions as steps of presses with their effects; the
   assembled model goes through the model's semantic checks and every error goes back.

Each stage is one structured answer (:mod:`apbot.llm.structured`), at most three rounds of
feedback. Seeded (the default), the offline reader's model and its guesses are given as a draft
to correct and complete — a small model corrects far better than it writes from nothing; a
variable or procedure the LLM leaves as drafted keeps the offline reader's full definition
(cases, display rules). From scratch, the LLM writes every stage itself. The action names, the
skills their verbs imply and the guards come from the offline reading; a stage that yields no
valid answer leaves that part of the offline reading in place, and the report says so.

The manual and the action names come first in every request (the same prefix for all stages)
so that a server's prompt cache reuses them. LLM output is data: parsed, validated, never run.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from typing import Any

from pydantic import BaseModel, ValidationError

from apbot.llm.client import LLMClient
from apbot.llm.structured import StructuredError, ask
from apbot.llm.usage import Usage
from apbot.model.schema import ApplianceModel
from apbot.read.llm_stages import (
    Controls,
    Features,
    Variables,
    draft_controls,
    draft_features,
    draft_variables,
    step_spec,
    variable_problems,
    variable_spec,
)
from apbot.read.reader import Reading, read_manual
from apbot.read.report import Note, Report

MAX_MANUAL_CHARS = 16_000
READER_VERSION = 1

SYSTEM = (
    "You read a home appliance's user manual and describe the appliance as data: its "
    "controls, its settings (variables) and the procedures (features) that change them. "
    "Use only what the manual says; keep names short, lowercase, with underscores."
)

ASK_CONTROLS = (
    "Stage 1 of 3, controls. For every action name above give the label of its control as "
    "the manual writes it, and what it does in a few words."
)
ASK_VARIABLES = (
    "Stage 2 of 3, settings. List every setting the panel changes or shows: kind 'switch' "
    "(off/on), 'choice' (values: the options in the order the key steps through them), "
    "'number' (low, high, step, unit) or 'time' (low and high as H:MM:SS, step in seconds). "
    "Include power, start/running and child lock when the appliance has them."
)
ASK_FEATURES = (
    "Stage 3 of 3, procedures. For each thing a user does (switch on, choose a programme, set "
    "a time, start…) give its steps in order. A step names the setting it adjusts and its "
    "presses: each action with its effect on that setting — next or prev value, toggle, set "
    "(a key that selects one value: give the value), or none (a key that only opens the "
    "step). 'sets' lists settings a step also sets (START sets running to on)."
)


@dataclass
class LLMReading:
    """The model, its report, what it cost, and which stages fell back to the offline reading."""

    model: ApplianceModel
    report: Report
    usage: Usage = field(default_factory=Usage)
    seeded: bool = True
    fallbacks: list[str] = field(default_factory=list)
    # the offline model with the LLM's variables in place (schema-valid, not checked as a
    # whole), so the variables stage can be scored where the assembled model fell back
    variables_read: ApplianceModel | None = None

    def as_reading(self) -> Reading:
        return Reading(self.model, self.report)


def _dump(value: BaseModel) -> str:
    return json.dumps(value.model_dump(exclude_defaults=True), ensure_ascii=False)


def _guesses(reading: Reading) -> str:
    lines = [f"- {n.subject}: {n.what}" for n in reading.report.guesses[:15]]
    return "\n".join(lines) if lines else "(none)"


class _Session:
    """One reading: the shared prefix, the running usage and the report's notes."""

    def __init__(
        self, client: LLMClient, manual: str, actions: list[str], seed: Reading, seeded: bool
    ) -> None:
        self.client = client
        self.actions = actions
        self.seed = seed
        self.seeded = seeded
        self.usage = Usage()
        self.notes: list[Note] = []
        self.fallbacks: list[str] = []
        self.prefix = (
            f"User manual:\n{manual[:MAX_MANUAL_CHARS]}\n\nThe panel's actions: "
            + ", ".join(actions)
        )

    def messages(self, question: str, context: str, draft: str | None) -> list[dict[str, Any]]:
        parts = [self.prefix, context, question]
        if draft is not None:
            parts.append(
                "A rule-based reader made this draft; it is often wrong or incomplete "
                f"(its guesses:\n{_guesses(self.seed)}). Correct and complete it:\n{draft}"
            )
        return [
            {"role": "system", "content": SYSTEM},
            {"role": "user", "content": "\n\n".join(p for p in parts if p)},
        ]

    def stage(
        self, name: str, messages: list[dict[str, Any]], schema: type[Any], check: Any, tokens: int
    ) -> Any | None:
        try:
            answer = ask(self.client, messages, schema, check=check, max_tokens=tokens)
        except StructuredError as exc:
            self.usage.add(exc.usage)
            self.fallbacks.append(name)
            self.notes.append(
                Note(
                    f"(llm {name})", f"no valid answer, the offline reading kept: {exc}", guess=True
                )
            )
            return None
        self.usage.add(answer.usage)
        rounds = len(answer.feedback)
        self.notes.append(Note(f"(llm {name})", f"read by the LLM ({rounds} round(s) of feedback)"))
        return answer.value


def llm_read_manual(
    text: str,
    actions: list[str],
    client: LLMClient,
    appliance_id: str = "read_appliance",
    category: str = "appliance",
    seeded: bool = True,
) -> LLMReading:
    """Read a manual with the LLM (see the module docstring); always returns a checked model."""
    seed = read_manual(text, actions, appliance_id, category)
    session = _Session(client, text, list(actions), seed, seeded)
    controls = _controls(session)
    labels = "Controls: " + _dump(controls) if controls else ""
    variables = _variables(session, labels)
    context = labels + ("\n\nSettings: " + _dump(variables) if variables else "")
    model = _features(session, context, controls, variables)
    notes = session.notes + seed.report.notes
    return LLMReading(
        model,
        Report(notes),
        session.usage,
        seeded,
        session.fallbacks,
        _with_variables(seed.model, controls, variables),
    )


def _with_variables(
    seed: ApplianceModel, controls: Controls | None, variables: Variables | None
) -> ApplianceModel | None:
    """The offline model with the LLM's controls and variables, for scoring that stage alone
    (None when the stage gave no answer or the result is not a valid model at all)."""
    if variables is None:
        return None
    base = seed.model_dump(mode="json", exclude_none=True)
    if controls is not None:
        _relabel(base, controls)
    base["variables"] = _merged_variables(seed, variables)
    try:
        return ApplianceModel.model_validate(base)
    except ValidationError:
        return None


def _controls(session: _Session) -> Controls | None:
    names = session.actions

    def check(answer: Controls) -> list[str]:
        given = [c.action for c in answer.controls]
        missing = [a for a in names if a not in given]
        unknown = [a for a in given if a not in names]
        out = []
        if missing:
            out.append(f"controls: no entry for {', '.join(missing)}")
        if unknown:
            out.append(f"controls: {', '.join(unknown)} are not action names; use only those")
        return out

    draft = _dump(draft_controls(session.seed.model)) if session.seeded else None
    messages = session.messages(ASK_CONTROLS, "", draft)
    result: Controls | None = session.stage(
        "controls", messages, Controls, check, 60 + 30 * len(names)
    )
    return result


def _variables(session: _Session, context: str) -> Variables | None:
    def check(answer: Variables) -> list[str]:
        out: list[str] = []
        names = [v.name for v in answer.variables]
        doubled = sorted({n for n in names if names.count(n) > 1})
        if doubled:
            out.append(f"variables: {', '.join(doubled)} given twice")
        if not answer.variables:
            out.append("variables: none given")
        for info in answer.variables:
            out += variable_problems(info)
        return out

    draft = _dump(draft_variables(session.seed.model)) if session.seeded else None
    messages = session.messages(ASK_VARIABLES, context, draft)
    result: Variables | None = session.stage("variables", messages, Variables, check, 900)
    return result


def _features(
    session: _Session, context: str, controls: Controls | None, variables: Variables | None
) -> ApplianceModel:
    seed = session.seed.model
    base = seed.model_dump(mode="json", exclude_none=True)
    if controls is not None:
        _relabel(base, controls)
    if variables is not None:
        base["variables"] = _merged_variables(seed, variables)
    draft = _dump(draft_features(seed)) if session.seeded else None
    messages = session.messages(ASK_FEATURES, context, draft)
    kept = draft_features(seed)

    def check(answer: Features) -> list[str]:
        problems, _ = _assemble(base, answer, kept, seed)
        return problems

    answer: Features | None = session.stage("features", messages, Features, check, 1500)
    if answer is not None:
        problems, model = _assemble(base, answer, kept, seed)
        if model is not None and not problems:
            return model
    # the features could not be read: keep the offline procedures over the new variables,
    # and if those do not fit together, the offline reading as it was
    problems, model = _assemble(base, kept, kept, seed)
    if model is not None and not problems:
        return model
    session.fallbacks.append("model")
    session.notes.append(
        Note(
            "(llm model)",
            "the LLM's parts did not fit together: the offline model kept",
            guess=True,
        )
    )
    return seed


def _relabel(base: dict[str, Any], controls: Controls) -> None:
    by_action = {c.action: c.label for c in controls.controls if c.label.strip()}
    for name, action in base["actions"].items():
        control = action.get("control")
        if control and name in by_action:
            for entry in base["controls"]:
                if entry["id"] == control:
                    entry["label"] = by_action[name].strip()[:40]


def _merged_variables(seed: ApplianceModel, answer: Variables) -> dict[str, Any]:
    """The answer's variables; one left as the draft had it keeps the offline definition."""
    drafted = {v.name: v for v in draft_variables(seed).variables}
    out: dict[str, Any] = {}
    for info in answer.variables:
        if drafted.get(info.name) == info:
            out[info.name] = seed.variables[info.name].model_dump(mode="json", exclude_none=True)
        else:
            out[info.name] = variable_spec(info)
    return out


def _assemble(
    base: dict[str, Any], answer: Features, kept: Features, seed: ApplianceModel
) -> tuple[list[str], ApplianceModel | None]:
    """The model with the answer's features, and the errors the checks find in it."""
    from apbot.sim.checks import check_model

    data = json.loads(json.dumps(base))
    drafted = {f.name: f for f in kept.features}
    features: dict[str, Any] = {}
    for feature in answer.features:
        if drafted.get(feature.name) == feature and feature.name in seed.features:
            features[feature.name] = [
                s.model_dump(mode="json", exclude_none=True, exclude_defaults=True)
                for s in seed.features[feature.name]
            ]
        else:
            features[feature.name] = [step_spec(s) for s in feature.steps]
    data["features"] = features
    variables = set(data["variables"])
    data["guards"] = [g for g in data.get("guards", []) if set(g.get("when", {})) <= variables]
    display = data.get("display", {})
    display["indicators"] = [v for v in display.get("indicators", []) if v in variables]
    if not _known(display.get("idle", ""), variables):
        display["idle"] = ""
    data["display"] = display
    for key in ("anywhere", "cycles"):
        if _stale(data.get(key), variables):
            data.pop(key)
    for spec in data["variables"].values():
        show = spec.get("show")
        if isinstance(show, str) and not _known(show, variables):
            spec.pop("show")
        elif isinstance(show, dict):
            spec["show"] = {k: v for k, v in show.items() if _known(v, variables)}
    try:
        model = ApplianceModel.model_validate(data)
    except ValidationError as exc:
        errors = [f"{'.'.join(str(p) for p in e['loc'])}: {e['msg']}" for e in exc.errors()[:8]]
        return errors, None
    problems = [f"{p.where}: {p.message}" for p in check_model(model) if p.severity == "error"]
    return problems[:8], model


def _stale(items: Any, variables: set[str]) -> bool:
    return bool(items) and any(
        (item.get("variable") and item["variable"] not in variables)
        or not set(item.get("when", {})) <= variables
        for item in items
    )


def _known(text: str, variables: set[str]) -> bool:
    """Every ``{name}`` the display text refers to is a variable of the model."""
    return all(name in variables for name in re.findall(r"\{([a-z][a-z0-9_]*)", text))


def read_belief(
    manual: str, actions: list[str], appliance_id: str, category: str
) -> tuple[ApplianceModel, list[str]]:
    """The belief a run reads from the manual: with the configured LLM (seeded by the offline
    reading), else the offline reader; and notes on how it was read. The LLM's answers are in
    the response cache, so an appliance is read once and a rerun reads it for free."""
    from apbot.llm.client import configured_client

    client = configured_client()
    if client is None:
        return read_manual(manual, actions, appliance_id, category).model, ["read offline"]
    reading = llm_read_manual(manual, actions, client, appliance_id, category)
    notes = [f"read by {client.config.describe()}"]
    notes += [f"{stage}: the offline reading kept" for stage in reading.fallbacks]
    return reading.model, notes
