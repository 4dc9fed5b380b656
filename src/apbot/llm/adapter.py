"""How each kind of server is asked for JSON that fits a schema — the one place they differ.

- ``json_schema``: OpenAI's strict structured outputs (also vLLM, Ollama): the schema is sent
  in strict form (every property required, no extra keys; optional ones become nullable; a
  tagged union's ``oneOf`` becomes the ``anyOf`` strict mode takes — its alternatives exclude
  each other by their tag, so the two mean the same).
- ``json_object``: llama.cpp's server rejects ``json_schema`` but takes
  ``{"type": "json_object", "schema": …}`` and constrains the output by a grammar.
- ``prompt``: servers with neither: the schema goes into the prompt and the text is parsed.

A server that rejects the requested format is stepped down to the next mode once
(:meth:`Adapter.step_down`), so a generic URL works without being told what it runs.

>>> from pydantic import BaseModel
>>> class Pick(BaseModel):
...     action: str
...     times: int = 1
>>> strict_schema(Pick.model_json_schema())["required"]
['action', 'times']
"""

from __future__ import annotations

import copy
import json
from collections.abc import Callable
from typing import Any

from apbot.llm.config import SCHEMA_MODES, SchemaMode


def strict_schema(schema: dict[str, Any]) -> dict[str, Any]:
    """The schema as OpenAI's strict mode wants it (a copy; the input is left alone)."""
    out = copy.deepcopy(schema)

    def tighten(node: dict[str, Any]) -> None:
        node.pop("default", None)
        if "oneOf" in node and node.pop("discriminator", None) is not None:
            node["anyOf"] = node.pop("oneOf")
        if node.get("type") == "object" or "properties" in node:
            node["additionalProperties"] = False
            node["required"] = list(node.get("properties", {}))

    _each_object(out, tighten)
    return out


def grammar_schema(schema: dict[str, Any]) -> dict[str, Any]:
    """The schema for a grammar-constraining server (llama.cpp): every property required, so
    the grammar is one fixed sequence instead of every order and subset of the optional ones
    (seen: 0.3 tokens/s against 5–7 for the same model), and no regex patterns (the answer is
    validated after anyway)."""
    out = strict_schema(schema)
    _each_object(out, lambda node: node.pop("pattern", None))
    return out


def _each_object(node: Any, change: Callable[[dict[str, Any]], object]) -> None:
    """Apply ``change`` to every JSON object in a schema, outermost first."""
    if isinstance(node, dict):
        change(node)
        for value in node.values():
            _each_object(value, change)
    elif isinstance(node, list):
        for value in node:
            _each_object(value, change)


class Adapter:
    """The request parameters that ask one server for JSON of a given schema."""

    def __init__(self, mode: SchemaMode) -> None:
        self.mode: SchemaMode = mode

    def response_format(self, name: str, schema: dict[str, Any]) -> dict[str, Any] | None:
        if self.mode == "json_schema":
            return {
                "type": "json_schema",
                "json_schema": {"name": name, "schema": strict_schema(schema), "strict": True},
            }
        if self.mode == "json_object":
            return {"type": "json_object", "schema": grammar_schema(schema)}
        return None

    def instructions(self, schema: dict[str, Any]) -> str:
        """Text for the prompt: the schema itself only where the server cannot take it."""
        if self.mode == "prompt":
            compact = json.dumps(schema, separators=(",", ":"))
            return (
                f"Reply with one JSON object, nothing else, that fits this JSON schema: {compact}"
            )
        return "Reply with one JSON object, nothing else."

    def step_down(self) -> bool:
        """Use the next, less demanding mode; False when there is none."""
        index = SCHEMA_MODES.index(self.mode)
        if index + 1 >= len(SCHEMA_MODES):
            return False
        self.mode = SCHEMA_MODES[index + 1]
        return True


def extract_json(text: str) -> str:
    """The JSON object in an answer (inside a code fence, or between the outer braces)."""
    stripped = text.strip()
    if stripped.startswith("```"):
        stripped = stripped.split("\n", 1)[1] if "\n" in stripped else ""
        stripped = stripped.rsplit("```", 1)[0]
    start, end = stripped.find("{"), stripped.rfind("}")
    if start >= 0 and end > start:
        return stripped[start : end + 1]
    return stripped
