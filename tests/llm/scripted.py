"""A scripted OpenAI-compatible HTTP server on 127.0.0.1 for tests: answers from a table.

Each request to ``/v1/chat/completions`` takes the next entry of the script (or, with a
``router``, whatever it returns for the request body): an answer text, an HTTP error status, or
a delay longer than the client's timeout. It records every request (body and headers), so a
test can count requests and see exactly what was sent.
"""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any


@dataclass
class Reply:
    """One scripted reply: ``text`` with ``finish``, or an error ``status``; ``delay`` first."""

    text: str = ""
    status: int = 200
    delay: float = 0.0
    finish: str = "stop"
    refusal: str | None = None
    error: str = "scripted error"
    prompt_tokens: int = 11
    completion_tokens: int = 7


@dataclass
class Script:
    replies: list[Reply] = field(default_factory=list)
    router: Callable[[dict[str, Any]], Reply] | None = None
    requests: list[dict[str, Any]] = field(default_factory=list)
    headers: list[dict[str, str]] = field(default_factory=list)
    lock: threading.Lock = field(default_factory=threading.Lock)

    def next(self, body: dict[str, Any]) -> Reply:
        with self.lock:
            self.requests.append(body)
            if self.router is not None:
                return self.router(body)
            if not self.replies:
                return Reply(status=500, error="the script has no more replies")
            return self.replies.pop(0)

    @property
    def count(self) -> int:
        return len(self.requests)


def _handler(script: Script) -> type[BaseHTTPRequestHandler]:
    class Handler(BaseHTTPRequestHandler):
        def log_message(self, format: str, *args: Any) -> None:  # quiet
            return

        def do_POST(self) -> None:
            length = int(self.headers.get("content-length", 0))
            body = json.loads(self.rfile.read(length) or b"{}")
            with script.lock:
                script.headers.append({k.lower(): v for k, v in self.headers.items()})
            reply = script.next(body)
            if reply.delay:
                time.sleep(reply.delay)
            if reply.status != 200:
                payload = {"error": {"message": reply.error, "type": "scripted"}}
                self._send(reply.status, payload)
                return
            message: dict[str, Any] = {"role": "assistant", "content": reply.text}
            if reply.refusal is not None:
                message = {"role": "assistant", "content": None, "refusal": reply.refusal}
            self._send(
                200,
                {
                    "id": "chatcmpl-scripted",
                    "object": "chat.completion",
                    "created": 0,
                    "model": body.get("model", "scripted"),
                    "choices": [{"index": 0, "message": message, "finish_reason": reply.finish}],
                    "usage": {
                        "prompt_tokens": reply.prompt_tokens,
                        "completion_tokens": reply.completion_tokens,
                        "total_tokens": reply.prompt_tokens + reply.completion_tokens,
                    },
                },
            )

        def _send(self, status: int, payload: dict[str, Any]) -> None:
            data = json.dumps(payload).encode()
            try:
                self.send_response(status)
                self.send_header("content-type", "application/json")
                self.send_header("content-length", str(len(data)))
                if status == 429:
                    self.send_header("retry-after", "0")
                self.end_headers()
                self.wfile.write(data)
            except (BrokenPipeError, ConnectionResetError):  # the client timed out first
                pass

    return Handler


@contextmanager
def serving(script: Script) -> Iterator[str]:
    """Serve ``script`` on a free port of 127.0.0.1; yield the base URL (``…/v1``)."""
    server = ThreadingHTTPServer(("127.0.0.1", 0), _handler(script))
    server.daemon_threads = True
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/v1"
    finally:
        server.shutdown()
        server.server_close()
