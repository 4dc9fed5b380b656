"""Structured answers: a pydantic model in, a validated instance out, errors fed back.

The pydantic model is the one source of the schema. An answer that is not JSON, does not fit
the schema, or fails the caller's semantic check goes back to the model with the errors, at
most ``feedback`` times (three by default); an answer cut off by the token limit is asked again
with twice the room and a request to be brief — unless it was cut off because it kept repeating
itself (a small model writing ``"," ,`` until the limit): more room only buys a longer loop, so
the room stays, the loop is shown to the model cut short and named in the feedback. A refusal
ends the question at once. Usage is summed over every attempt. The answer is data — parsed,
validated, never executed.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Generic, TypeVar

from pydantic import BaseModel, ValidationError

from apbot.llm.adapter import Adapter, extract_json
from apbot.llm.client import FormatRejected, LLMClient, LLMError
from apbot.llm.usage import Usage

T = TypeVar("T", bound=BaseModel)

MAX_FEEDBACK = 3
MAX_ERRORS_SHOWN = 8
MAX_TOKENS_CAP = 8192
LOOP_UNIT = 60  # the longest repeated piece looked for at the end of a cut-off answer
LOOP_SPAN = 240  # a tail this long (and at least LOOP_COPIES copies) made of one piece is a loop
LOOP_COPIES = 8


class StructuredError(LLMError):
    """No valid answer after the allowed attempts (or a refusal); keeps what was spent."""

    def __init__(self, message: str, usage: Usage, errors: list[str], last: str = "") -> None:
        super().__init__(message)
        self.usage = usage
        self.errors = errors
        self.last = last


@dataclass
class Answer(Generic[T]):
    """A valid answer, its usage over all attempts, and the errors fed back on the way."""

    value: T
    usage: Usage
    attempts: int
    feedback: list[list[str]] = field(default_factory=list)


def validation_errors(exc: ValidationError) -> list[str]:
    """Short, located messages (``steps.0.effect: Input should be 'next' or 'prev'``)."""
    out = []
    for error in exc.errors()[:MAX_ERRORS_SHOWN]:
        where = ".".join(str(part) for part in error["loc"]) or "(answer)"
        out.append(f"{where}: {error['msg']}")
    return out


def ask(
    client: LLMClient,
    messages: list[dict[str, Any]],
    schema: type[T],
    *,
    check: Callable[[T], list[str]] | None = None,
    feedback: int = MAX_FEEDBACK,
    max_tokens: int | None = None,
    repeat: int | None = None,
    adapter: Adapter | None = None,
) -> Answer[T]:
    """Ask until the answer validates and passes ``check`` (which returns error messages)."""
    adapter = adapter or Adapter(client.config.schema_mode)
    json_schema = schema.model_json_schema()
    conversation = _with_instructions(messages, adapter.instructions(json_schema))
    usage = Usage()
    tokens = max_tokens or client.config.max_tokens
    history: list[list[str]] = []
    last = ""
    attempt = 0
    while True:
        attempt += 1
        try:
            answer = client.complete(
                conversation,
                max_tokens=tokens,
                response_format=adapter.response_format(schema.__name__.lower(), json_schema),
                repeat=repeat,
            )
        except FormatRejected:
            if not adapter.step_down():
                raise
            conversation = _with_instructions(messages, adapter.instructions(json_schema))
            attempt -= 1
            continue
        usage.add(answer.usage)
        last = answer.text
        if answer.refusal:
            raise StructuredError(f"the model refused: {answer.refusal[:200]}", usage, [], last)
        errors: list[str]
        shown = answer.text[:4000]
        if answer.finish_reason == "length":
            loop = repeated_tail(answer.text)
            if loop is None:
                errors = [
                    f"the answer was cut off at {tokens} tokens: give a shorter, complete one"
                ]
                tokens = min(tokens * 2, MAX_TOKENS_CAP)
            else:
                start, unit = loop
                errors = [
                    f"the answer was cut off at {tokens} tokens because it repeated "
                    f"{unit.strip()!r} over and over: give a complete answer without repeating"
                ]
                shown = answer.text[: min(start + 3 * len(unit), 4000)] + " …"
        else:
            errors = _problems(answer.text, schema, check)
            if not errors:
                value = schema.model_validate_json(extract_json(answer.text))
                return Answer(value, usage, attempt, history)
        history.append(errors)
        if attempt > feedback:
            raise StructuredError(
                f"no valid answer after {attempt} attempt(s): {'; '.join(errors[:3])}",
                usage,
                errors,
                last,
            )
        conversation = [
            *conversation,
            {"role": "assistant", "content": shown},
            {"role": "user", "content": _feedback_text(errors)},
        ]


def repeated_tail(text: str) -> tuple[int, str] | None:
    """Where a cut-off answer starts repeating one short piece to its end, and the piece
    (None when its end is not such a loop)."""
    best: tuple[int, str] | None = None
    for size in range(1, LOOP_UNIT + 1):
        if size * LOOP_COPIES > len(text):
            break
        unit = text[-size:]
        start = len(text) - size
        while start >= size and text[start - size : start] == unit:
            start -= size
        looped = (len(text) - start) // size >= LOOP_COPIES and len(text) - start >= LOOP_SPAN
        if looped and (best is None or start < best[0]):
            best = (start, unit)
    return best


def _problems(text: str, schema: type[T], check: Callable[[T], list[str]] | None) -> list[str]:
    raw = extract_json(text)
    try:
        json.loads(raw)
    except json.JSONDecodeError as exc:
        return [f"the answer is not valid JSON ({exc.msg} at character {exc.pos})"]
    try:
        value = schema.model_validate_json(raw)
    except ValidationError as exc:
        return validation_errors(exc)
    if check is None:
        return []
    return [str(e) for e in check(value)][:MAX_ERRORS_SHOWN]


def _feedback_text(errors: list[str]) -> str:
    listed = "\n".join(f"- {e}" for e in errors)
    return f"That answer has problems:\n{listed}\nGive the whole answer again, corrected, as JSON."


def _with_instructions(messages: list[dict[str, Any]], text: str) -> list[dict[str, Any]]:
    """The messages with the format instruction at the end of the last user message, so the
    long shared prefix (the manual) stays first and the server's prompt cache can reuse it."""
    out = [dict(m) for m in messages]
    for message in reversed(out):
        if message.get("role") == "user" and isinstance(message.get("content"), str):
            message["content"] = f"{message['content']}\n\n{text}"
            break
    return out
