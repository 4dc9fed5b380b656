"""One client for any OpenAI-compatible server, on the official ``openai`` package.

Every request goes through :meth:`LLMClient.complete`: the response cache first, then the
run's budget, a concurrency slot, and the request itself with retries and exponential backoff
on rate limits (429), server errors (5xx), timeouts and dropped connections. The openai
package's own retries are off so that every attempt is counted here. Other errors (a bad
request, a wrong key, an unknown model) are not retried: they will not get better.

The key goes to the openai client and nowhere else: not into the cache key, a record, an
error message or a log line.
"""

from __future__ import annotations

import logging
import random
import time
from dataclasses import dataclass
from typing import Any

import openai

from apbot.llm.cache import ResponseCache, cache_key
from apbot.llm.config import LLMConfig
from apbot.llm.limits import Budget, Slots
from apbot.llm.usage import Usage

log = logging.getLogger("apbot.llm")

MAX_RETRY_AFTER = 60.0


class LLMError(RuntimeError):
    """A request that failed for good; the message says what happened (never the key)."""


class FormatRejected(LLMError):
    """The server refused the requested response format (the adapter steps down)."""


@dataclass
class Completion:
    """One answer: its text, why it ended, a refusal if any, and what it used."""

    text: str
    finish_reason: str
    refusal: str | None
    usage: Usage

    def to_cache(self) -> dict[str, Any]:
        return {
            "text": self.text,
            "finish_reason": self.finish_reason,
            "refusal": self.refusal,
            "prompt_tokens": self.usage.prompt_tokens,
            "completion_tokens": self.usage.completion_tokens,
        }

    @classmethod
    def from_cache(cls, data: dict[str, Any]) -> Completion:
        usage = Usage(
            int(data.get("prompt_tokens", 0)), int(data.get("completion_tokens", 0)), 1, 0, 1
        )
        refusal = data.get("refusal")
        return cls(
            str(data.get("text", "")),
            str(data.get("finish_reason", "stop")),
            None if refusal is None else str(refusal),
            usage,
        )


_RETRIED = (
    openai.RateLimitError,
    openai.InternalServerError,
    openai.APITimeoutError,
    openai.APIConnectionError,
)


def _why(exc: BaseException) -> str:
    if isinstance(exc, openai.APITimeoutError):
        return "timed out"
    if isinstance(exc, openai.APIConnectionError):
        return "connection failed"
    if isinstance(exc, openai.APIStatusError):
        return f"HTTP {exc.status_code}"
    return type(exc).__name__


def _status_message(exc: openai.APIStatusError) -> str:
    body = exc.body
    if isinstance(body, dict):
        inner = body.get("error", body)
        message = inner.get("message") if isinstance(inner, dict) else inner
        if message:
            return str(message)[:300]
    return str(exc.message)[:300]


class LLMClient:
    """Chat completions with cache, budget, concurrency limit and retries."""

    def __init__(self, config: LLMConfig, budget: Budget | None = None) -> None:
        self.config = config
        self.cache = ResponseCache(config.cache_dir, config.cache)
        self.budget = budget or Budget(
            config.max_requests, config.max_tokens_total, config.budget_file
        )
        self.slots = Slots(config.cache_dir / ".slots" / _slot_name(config), config.concurrency)
        self.usage = Usage()  # everything this client answered, for the run's report
        self._openai: openai.OpenAI | None = None

    def _client(self) -> openai.OpenAI:
        if self._openai is None:
            self._openai = openai.OpenAI(
                api_key=self.config.api_key(),
                base_url=self.config.base_url,
                timeout=self.config.timeout,
                max_retries=0,
            )
        return self._openai

    def settings(
        self, max_tokens: int | None, response_format: dict[str, Any] | None, repeat: int = 0
    ) -> dict[str, Any]:
        """The generation settings of a request (all of them are in the cache key); repeat i
        sends seed + i, so that a sampling server may answer each repeat differently."""
        out: dict[str, Any] = {
            "temperature": self.config.temperature,
            "max_tokens": max_tokens or self.config.max_tokens,
        }
        if self.config.seed is not None:
            out["seed"] = self.config.seed + repeat
        if response_format is not None:
            out["response_format"] = response_format
        return out

    def complete(
        self,
        messages: list[dict[str, Any]],
        *,
        max_tokens: int | None = None,
        response_format: dict[str, Any] | None = None,
        repeat: int | None = None,
    ) -> Completion:
        """One answer to ``messages``; ``repeat`` tells apart the k answers of k repeats
        (default: the configuration's, ``APBOT_LLM_REPEAT``)."""
        repeat = self.config.repeat if repeat is None else repeat
        settings = self.settings(max_tokens, response_format, repeat)
        key = cache_key(messages, self.config.model, settings, self.config.base_url, repeat)
        stored = self.cache.get(key)
        if stored is not None:
            answer = Completion.from_cache(stored)
            self.usage.add(answer.usage)
            return answer
        self.budget.check()
        answer = self._request(messages, settings)
        self.budget.charge(answer.usage.total_tokens)
        self.cache.put(key, answer.to_cache())
        self.usage.add(answer.usage)
        return answer

    def _request(self, messages: list[dict[str, Any]], settings: dict[str, Any]) -> Completion:
        attempts = self.config.retries + 1
        extra = {}
        params = dict(settings)
        if "response_format" in params and params["response_format"].get("type") == "json_object":
            extra["response_format"] = params.pop("response_format")  # carries a "schema"
        for attempt in range(1, attempts + 1):
            try:
                with self.slots.hold():
                    response = self._client().chat.completions.create(
                        model=self.config.model,
                        messages=messages,  # type: ignore[arg-type]
                        extra_body=extra or None,
                        **params,
                    )
            except _RETRIED as exc:
                if "response_format" in settings and _mentions_format(exc):
                    raise FormatRejected(
                        f"{self.config.describe()}: {_why(exc)}: the server refused the format"
                    ) from None
                if attempt == attempts:
                    raise LLMError(
                        f"{self.config.describe()}: {_why(exc)} after {attempts} attempt(s)"
                    ) from None
                delay = self._delay(exc, attempt)
                log.warning(
                    "%s: %s, retrying in %.2f s (attempt %d of %d)",
                    self.config.describe(),
                    _why(exc),
                    delay,
                    attempt + 1,
                    attempts,
                )
                time.sleep(delay)
                continue
            except openai.APIStatusError as exc:
                message = _status_message(exc)
                error = FormatRejected if "response_format" in settings else LLMError
                raise error(
                    f"{self.config.describe()}: HTTP {exc.status_code}: {message}"
                ) from None
            except openai.APIError as exc:
                raise LLMError(f"{self.config.describe()}: {type(exc).__name__}") from None
            return _completion(response)
        raise AssertionError("unreachable")

    def _delay(self, exc: BaseException, attempt: int) -> float:
        base = self.config.backoff * (2 ** (attempt - 1))
        if isinstance(exc, openai.APIStatusError):
            after = exc.response.headers.get("retry-after")
            try:
                if after is not None:
                    base = max(base, min(float(after), MAX_RETRY_AFTER))
            except ValueError:
                pass
        return base * (1 + 0.1 * random.random())


def _completion(response: Any) -> Completion:
    choice = response.choices[0] if response.choices else None
    if choice is None:
        raise LLMError("the server answered with no choices")
    message = choice.message
    usage = response.usage
    prompt = int(getattr(usage, "prompt_tokens", 0) or 0) if usage else 0
    completion = int(getattr(usage, "completion_tokens", 0) or 0) if usage else 0
    return Completion(
        message.content or "",
        str(choice.finish_reason or "stop"),
        getattr(message, "refusal", None),
        Usage(prompt, completion, 1, 1, 0),
    )


def _mentions_format(exc: BaseException) -> bool:
    if not isinstance(exc, openai.APIStatusError) or exc.status_code == 429:
        return False
    text = _status_message(exc).lower()
    return any(word in text for word in ("response_format", "json_schema", "response format"))


def _slot_name(config: LLMConfig) -> str:
    import hashlib

    return hashlib.sha256(config.describe().encode()).hexdigest()[:16]


_CLIENTS: dict[LLMConfig, LLMClient] = {}


def configured_client(config: LLMConfig | None = None) -> LLMClient | None:
    """The process's client for ``config`` (default: the environment's), or None when no LLM
    is configured. One client per configuration, so usage adds up across calls."""
    from apbot.llm.config import from_env

    chosen = config if config is not None else from_env()
    if chosen is None:
        return None
    if chosen not in _CLIENTS:
        _CLIENTS[chosen] = LLMClient(chosen)
    return _CLIENTS[chosen]
