"""Which LLM to use, and how: one spec string plus a few environment variables.

A spec names the server and the model:

- ``openai:gpt-4o`` — OpenAI's API; the key from ``OPENAI_API_KEY`` (or the variable named by
  ``APBOT_LLM_KEY_ENV``);
- ``http://127.0.0.1:8000/v1:qwen2.5-7b`` — any OpenAI-compatible server (vLLM, Ollama,
  llama.cpp…): the base URL, then ``:`` and the model (which may hold colons itself, as
  Ollama's ``llama3:8b`` does); a key only from the variable ``APBOT_LLM_KEY_ENV`` names — an
  OpenAI key is never sent to another server;
- ``local`` — the local model ``apbot llm serve`` starts (``APBOT_LLM_LOCAL_URL``).

The spec comes from ``--llm`` or ``APBOT_LLM``; the CLI writes its options into the
environment so that benchmark worker processes see the same configuration. The key itself is
read only when a client is made and is kept out of every ``repr``, record and log.

>>> c = parse_spec("http://127.0.0.1:11434/v1:llama3:8b")
>>> c.base_url, c.model, c.provider
('http://127.0.0.1:11434/v1', 'llama3:8b', 'server')
>>> parse_spec("openai:gpt-4o").describe()
'openai:gpt-4o'
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Literal

Provider = Literal["openai", "server", "local"]
CacheMode = Literal["off", "read", "write"]
SchemaMode = Literal["json_schema", "json_object", "prompt"]

CACHE_MODES: tuple[CacheMode, ...] = ("off", "read", "write")
SCHEMA_MODES: tuple[SchemaMode, ...] = ("json_schema", "json_object", "prompt")
LOCAL_URL = "http://127.0.0.1:8765/v1"
LOCAL_MODEL = "qwen2.5-coder-1.5b-instruct-q4_k_m"


class LLMConfigError(ValueError):
    """A spec or setting that cannot be used; the message names it and the accepted forms."""


@dataclass(frozen=True)
class LLMConfig:
    """Everything that says which server and model answer, and how requests are made.

    ``temperature``, ``max_tokens`` and ``seed`` change answers (they are in the cache key);
    ``timeout``, ``retries``, ``concurrency`` and the budget do not.
    """

    provider: Provider
    model: str
    base_url: str | None = None
    key_env: str | None = None
    temperature: float = 0.0
    max_tokens: int = 1024
    seed: int | None = 0
    timeout: float = 120.0
    retries: int = 4
    backoff: float = 1.0
    concurrency: int = 4
    cache: CacheMode = "write"
    cache_dir: Path = field(default_factory=lambda: default_cache_dir())
    schema_mode: SchemaMode = "json_schema"
    max_requests: int | None = None
    max_tokens_total: int | None = None
    budget_file: Path | None = None
    repeat: int = 0  # which of k repeats (APBOT_LLM_REPEAT): its own cache entries

    def describe(self) -> str:
        """The spec, without any secret (it never holds one)."""
        if self.provider == "openai":
            return f"openai:{self.model}"
        if self.provider == "local":
            return "local"
        return f"{self.base_url}:{self.model}"

    def api_key(self, environ: Mapping[str, str] | None = None) -> str:
        """The key from the named variable (``"none"`` for servers that take none)."""
        env = os.environ if environ is None else environ
        if self.key_env is None:
            return "none"
        value = env.get(self.key_env, "")
        if not value:
            raise LLMConfigError(
                f"{self.describe()} needs an API key: set {self.key_env} "
                "(or name another variable with APBOT_LLM_KEY_ENV)"
            )
        return value


def default_cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "apbot" / "llm"


def parse_spec(spec: str, key_env: str | None = None) -> LLMConfig:
    """An :class:`LLMConfig` with default settings from a spec string."""
    text = spec.strip()
    if text == "local":
        url = os.environ.get("APBOT_LLM_LOCAL_URL", LOCAL_URL)
        return LLMConfig(
            "local",
            LOCAL_MODEL,
            url,
            key_env,
            timeout=900.0,
            concurrency=1,
            schema_mode="json_object",
        )
    if text.startswith("openai:"):
        model = text.removeprefix("openai:").strip()
        if not model:
            raise LLMConfigError(f"--llm {spec!r}: name the model after 'openai:'")
        return LLMConfig("openai", model, None, key_env or "OPENAI_API_KEY")
    if text.startswith(("http://", "https://")):
        scheme, _, rest = text.partition("://")
        slash = rest.find("/")
        colon = rest.find(":", slash) if slash >= 0 else -1
        if slash < 0 or colon < 0 or not rest[colon + 1 :].strip():
            raise LLMConfigError(
                f"--llm {spec!r}: write the server's base URL with its path, then ':' and the "
                "model, e.g. http://127.0.0.1:8000/v1:qwen2.5-7b"
            )
        return LLMConfig("server", rest[colon + 1 :].strip(), f"{scheme}://{rest[:colon]}", key_env)
    raise LLMConfigError(
        f"--llm {spec!r}: not a spec; accepted: openai:MODEL, http(s)://HOST:PORT/PATH:MODEL, "
        "or local"
    )


def _number(env: Mapping[str, str], name: str, kind: type[float] | type[int]) -> float | None:
    text = env.get(name, "").strip()
    if not text:
        return None
    try:
        value = kind(text)
    except ValueError:
        raise LLMConfigError(f"{name}={text!r} is not a number") from None
    if value < 0:
        raise LLMConfigError(f"{name}={text!r} must not be negative")
    return value


def from_env(environ: Mapping[str, str] | None = None) -> LLMConfig | None:
    """The configuration the environment holds (``APBOT_LLM`` and friends), or None."""
    env = os.environ if environ is None else environ
    spec = env.get("APBOT_LLM", "").strip()
    if not spec:
        return None
    config = parse_spec(spec, env.get("APBOT_LLM_KEY_ENV") or None)
    cache = env.get("APBOT_LLM_CACHE", "").strip() or config.cache
    if cache not in CACHE_MODES:
        raise LLMConfigError(f"APBOT_LLM_CACHE={cache!r}: use one of {', '.join(CACHE_MODES)}")
    schema = env.get("APBOT_LLM_SCHEMA", "").strip() or config.schema_mode
    if schema not in SCHEMA_MODES:
        raise LLMConfigError(f"APBOT_LLM_SCHEMA={schema!r}: use one of {', '.join(SCHEMA_MODES)}")
    changes: dict[str, object] = {"cache": cache, "schema_mode": schema}
    if env.get("APBOT_LLM_CACHE_DIR"):
        changes["cache_dir"] = Path(env["APBOT_LLM_CACHE_DIR"])
    if env.get("APBOT_LLM_BUDGET_FILE"):
        changes["budget_file"] = Path(env["APBOT_LLM_BUDGET_FILE"])
    for name, attr, kind in (
        ("APBOT_LLM_TEMPERATURE", "temperature", float),
        ("APBOT_LLM_TIMEOUT", "timeout", float),
        ("APBOT_LLM_RETRIES", "retries", int),
        ("APBOT_LLM_BACKOFF", "backoff", float),
        ("APBOT_LLM_CONCURRENCY", "concurrency", int),
        ("APBOT_LLM_MAX_REQUESTS", "max_requests", int),
        ("APBOT_LLM_MAX_TOKENS_TOTAL", "max_tokens_total", int),
        ("APBOT_LLM_REPEAT", "repeat", int),
    ):
        value = _number(env, name, kind)
        if value is not None:
            changes[attr] = value
    if changes.get("concurrency") == 0:
        raise LLMConfigError("APBOT_LLM_CONCURRENCY must be at least 1")
    return replace(config, **changes)  # type: ignore[arg-type]


def configure_env(
    spec: str | None,
    cache: str | None = None,
    key_env: str | None = None,
    environ: dict[str, str] | None = None,
) -> LLMConfig | None:
    """Put command-line choices into the environment (workers inherit it); return the config.

    Raises :class:`LLMConfigError` for a bad spec or cache mode before anything runs.
    """
    env = os.environ if environ is None else environ
    if spec is not None:
        env["APBOT_LLM"] = spec
    if cache is not None:
        env["APBOT_LLM_CACHE"] = cache
    if key_env is not None:
        env["APBOT_LLM_KEY_ENV"] = key_env
    return from_env(env)
