"""An on-disk response cache that several processes can share.

One file per key, written to a temporary file in the same directory and moved into place with
``os.replace`` (atomic on POSIX): a reader sees a whole answer or none, two writers of the same
key leave one whole answer, and there is no shared index to lock (lm-eval's single SQLite file
locked up under several processes). A file that cannot be read as an answer counts as a miss.

The key covers what changes the answer — the messages, the model, the generation settings
(temperature, token limit, seed, response format), the base URL and the repeat index (without
it, k repeats of a task would be one answer k times) — and nothing that does not (timeouts,
retries, the key).

>>> import tempfile
>>> cache = ResponseCache(Path(tempfile.mkdtemp()), "write")
>>> key = cache_key([{"role": "user", "content": "hi"}], "m", {"temperature": 0}, None, 0)
>>> cache.get(key) is None
True
>>> cache.put(key, {"text": "hello"})
>>> cache.get(key)
{'text': 'hello'}
>>> key == cache_key([{"role": "user", "content": "hi"}], "m", {"temperature": 0}, None, 1)
False
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
from pathlib import Path
from typing import Any

from apbot.llm.config import CacheMode

KEY_VERSION = 1  # bump when the meaning of a stored answer changes


def cache_key(
    messages: list[dict[str, Any]],
    model: str,
    settings: dict[str, Any],
    base_url: str | None,
    repeat: int,
) -> str:
    """The hex digest that names one answer (see the module docstring for what is in it)."""
    payload = {
        "v": KEY_VERSION,
        "messages": messages,
        "model": model,
        "settings": settings,
        "base_url": (base_url or "").rstrip("/"),
        "repeat": repeat,
    }
    text = json.dumps(payload, sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


class ResponseCache:
    """Answers by key under ``directory``; ``mode``: ``off`` (neither reads nor writes),
    ``read`` (uses stored answers, stores none), ``write`` (both; the default)."""

    def __init__(self, directory: Path, mode: CacheMode = "write") -> None:
        self.directory = Path(directory)
        self.mode = mode

    def _path(self, key: str) -> Path:
        return self.directory / key[:2] / f"{key}.json"

    def get(self, key: str) -> dict[str, Any] | None:
        if self.mode == "off":
            return None
        try:
            data = json.loads(self._path(key).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        return data if isinstance(data, dict) else None

    def put(self, key: str, answer: dict[str, Any]) -> None:
        if self.mode != "write":
            return
        path = self._path(key)
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=".tmp-", dir=path.parent)
        try:
            with os.fdopen(handle, "w", encoding="utf-8") as stream:
                json.dump(answer, stream, ensure_ascii=False)
            os.replace(temporary, path)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise
