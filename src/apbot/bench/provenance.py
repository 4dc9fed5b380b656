"""What produced a run: the code's version and a digest of the suite, kept in ``run.json``.

Records are only comparable when the same code ran the same suite, so a run directory
resumes only with both unchanged. The code is the package version, a digest of the package's own
Python source, and the git revision of the repository that tracks it, when there is one (an
installed copy has none; a missing ``git`` is no error). The source digest is what is
compared: a revision alone misses an edited working tree and a copy made with
``git archive``, and results of two states of the code must not mix in one directory.
The suite digest covers what decides a result: every appliance's model, tasks and manual,
as loaded (so reformatting a YAML file does not change it; editing a goal, an optimum or a
manual does).
"""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
from functools import lru_cache
from pathlib import Path
from typing import Any

import apbot
from apbot.bench.suite import Suite

COMPARED = ("apbot", "source", "git")  # what must match; "git_dirty" is recorded, not compared


def _git(directory: Path, *arguments: str) -> str | None:
    """``git -C directory ARGS``'s output, or None when git, the repository or time fails."""
    environment = {k: v for k, v in os.environ.items() if not k.startswith("GIT_")}
    try:
        done = subprocess.run(
            ["git", "-C", str(directory), *arguments],
            capture_output=True,
            text=True,
            timeout=5,
            env=environment,
        )
    except (OSError, subprocess.SubprocessError):
        return None
    return done.stdout.strip() if done.returncode == 0 else None


@lru_cache(maxsize=4)
def code_version(package: Path | None = None) -> dict[str, Any]:
    """``{"apbot": version, "source": digest, "git": revision or None, "git_dirty": bool or
    None}``."""
    package = package or Path(apbot.__file__).resolve().parent
    version: dict[str, Any] = {
        "apbot": apbot.__version__,
        "source": source_digest(package),
        "git": None,
        "git_dirty": None,
    }
    tracked = _git(package, "ls-files", "--error-unmatch", "--", "__init__.py")
    revision = _git(package, "rev-parse", "HEAD") if tracked else None
    if revision:
        changes = _git(package, "status", "--porcelain", "--untracked-files=no", "--", ".")
        version.update(git=revision, git_dirty=bool(changes) if changes is not None else None)
    return version


def source_digest(package: Path) -> str:
    """``sha256:…`` over the package's ``.py`` files (relative path and bytes, in path order)."""
    digest = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        digest.update(path.relative_to(package).as_posix().encode("utf-8") + b"\0")
        digest.update(path.read_bytes() + b"\0")
    return f"sha256:{digest.hexdigest()[:16]}"


def describe_code(version: Any) -> str:
    """``apbot 0.1.0 (git 5ce0bf4)`` — or what is known of an older run.json."""
    if not isinstance(version, dict):
        return "an unrecorded version of apbot"
    git, source = version.get("git"), version.get("source")
    where = f"git {str(git)[:12]}" if git else f"source {str(source)[7:19]}" if source else ""
    return f"apbot {version.get('apbot')}" + (f" ({where})" if where else "")


def same_code(a: Any, b: Any) -> bool:
    return (
        isinstance(a, dict) and isinstance(b, dict) and all(a.get(k) == b.get(k) for k in COMPARED)
    )


def suite_digest(suite: Suite) -> str:
    """``sha256:…`` over every appliance's model, tasks and manual, in the suite's order."""
    digest = hashlib.sha256()
    for appliance in suite.appliances:
        part = {
            "id": appliance.id,
            "model": appliance.model.model_dump(mode="json"),
            "tasks": [task.model_dump(mode="json") for task in appliance.tasks],
            "manual": appliance.manual,
        }
        digest.update(json.dumps(part, sort_keys=True, ensure_ascii=False).encode("utf-8"))
        digest.update(b"\0")
    return f"sha256:{digest.hexdigest()}"
