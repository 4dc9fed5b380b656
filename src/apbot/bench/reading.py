"""Beliefs read from the manual, once per appliance, cached on disk; and how they differ from
the truth.

Reading a manual is deterministic: the same manual text, the same action names and the same
reader give the same model. A read model is therefore kept in a small cache directory under a
key made of exactly those three things — the manual, the action list (and the appliance id and
category the model is labelled with) and the reader's version, a digest of the reader's own
source files and of the model package it builds with — so a benchmark reads each appliance
once, every worker and every later run reuses it, and a changed reader reads again. Cached
models are data: they are validated and checked on the way back in, and a damaged entry is read
afresh.

``APBOT_CACHE_DIR`` moves the cache (default ``~/.cache/apbot``; ``off`` disables it).
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

from apbot.model.schema import ApplianceModel

CACHE_ENV = "APBOT_CACHE_DIR"
MAX_DIFFERENCES = 40
"""Lines of :func:`belief_differences` kept (the rest are counted)."""


@dataclass(frozen=True)
class ReadBelief:
    """A model read from a manual, its content hash (``sha256:…``) and the reader's notes."""

    model: ApplianceModel
    digest: str
    guesses: int = 0


@dataclass(frozen=True)
class BeliefFacts:
    """What records keep about the belief a task ran on: its hash, and (read beliefs) how it
    differs from the truth."""

    digest: str
    differences: tuple[str, ...] = ()


@lru_cache(maxsize=1)
def reader_version() -> str:
    """A digest of the reader's source: all of ``apbot.read`` — the reader's own rules borrow the
    goal parser's stemmer and unit words, so a goal module's edit may change a read model — and
    ``apbot.model``, whose unit table, value helpers and checks shape every read model. An edit
    anywhere there reads the manuals again (6 s for 75) rather than serve what the old code read."""
    import apbot.model
    import apbot.read

    reader = Path(apbot.read.__file__).resolve().parent
    model = Path(apbot.model.__file__).resolve().parent
    digest = hashlib.sha256()
    for path in sorted(reader.glob("*.py")) + sorted(model.rglob("*.py")):
        digest.update(path.relative_to(reader.parent).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def model_digest(model: ApplianceModel) -> str:
    """``sha256:…`` of a model's content (what records keep to say which belief was used)."""
    text = json.dumps(model.model_dump(mode="json"), sort_keys=True, ensure_ascii=False)
    return "sha256:" + hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def cache_dir() -> Path | None:
    """Where read models are kept, or None when caching is off."""
    setting = os.environ.get(CACHE_ENV, "").strip()
    if setting.lower() == "off":
        return None
    return Path(setting).expanduser() if setting else Path.home() / ".cache" / "apbot"


def cache_key(manual: str, actions: list[str], appliance_id: str, category: str) -> str:
    """The key of one reading: manual, action list, labels and the reader's version."""
    payload = json.dumps(
        {
            "manual": manual,
            "actions": list(actions),
            "id": appliance_id,
            "category": category,
            "reader": reader_version(),
        },
        sort_keys=True,
        ensure_ascii=False,
    )
    return hashlib.sha256(payload.encode("utf-8")).hexdigest()


def read_belief(
    manual: str, actions: list[str], appliance_id: str = "appliance", category: str = "appliance"
) -> ReadBelief:
    """The model the configured LLM reads (seeded by the offline reading), else the model
    :func:`apbot.read.read_manual` reads, from the cache when it holds it.

    Raises :class:`apbot.read.ReaderError` for a text that is not a manual at all.
    """
    from apbot.llm.client import configured_client

    client = configured_client()
    if client is not None:  # the LLM's answers sit in its own response cache
        from apbot.read.llm_reader import llm_read_manual

        answer = llm_read_manual(manual, list(actions), client, appliance_id, category)
        return ReadBelief(answer.model, model_digest(answer.model), len(answer.report.guesses))
    key = cache_key(manual, actions, appliance_id, category)
    folder = cache_dir()
    path = folder / "read" / f"{key}.json" if folder is not None else None
    cached = _load(path) if path is not None else None
    if cached is not None:
        return cached
    from apbot.read import read_manual

    reading = read_manual(manual, list(actions), appliance_id, category)
    guesses = len(reading.report.guesses)
    belief = ReadBelief(reading.model, model_digest(reading.model), guesses)
    if path is not None:
        _store(path, belief)
    return belief


def _load(path: Path) -> ReadBelief | None:
    """A cached reading, or None when missing or damaged (it is then read again)."""
    from apbot.model.validate import check_model

    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        model = ApplianceModel.model_validate(data["model"])
    except (OSError, ValueError, KeyError, TypeError):
        return None
    if any(issue.severity == "error" for issue in check_model(model)):
        return None
    return ReadBelief(model, model_digest(model), int(data.get("guesses", 0)))


def _store(path: Path, belief: ReadBelief) -> None:
    """Write atomically (workers may read the same appliance at once); a cache that cannot be
    written is no error — the reading is simply not kept."""
    data = {"model": belief.model.model_dump(mode="json"), "guesses": belief.guesses}
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        with os.fdopen(handle, "w", encoding="utf-8") as file:
            json.dump(data, file, ensure_ascii=False)
        os.replace(temporary, path)
    except OSError:
        return


def belief_differences(read: ApplianceModel, true: ApplianceModel) -> list[str]:
    """How a read belief differs from the truth, under the reader's evaluation alignment
    (:mod:`apbot.read.evaluate`): settings missing or extra, values missing or extra, and
    procedures missing. For judging and reports only — never for a method."""
    from apbot.read.evaluate import align_features, align_variables, value_set

    lines: list[str] = []
    aligned = align_variables(read, true)
    back = {t: r for r, t in aligned.items()}
    for name in true.variables:
        partner = back.get(name)
        if partner is None:
            lines.append(f"missing setting {name}")
            continue
        label = name if partner == name else f"{name} (read as {partner})"
        want, got = value_set(true, name), value_set(read, partner)
        missing, extra = sorted(want - got), sorted(got - want)
        if missing:
            lines.append(f"{label}: missing values {_few(missing)}")
        if extra:
            lines.append(f"{label}: extra values {_few(extra)}")
    lines += [f"extra setting {name}" for name in read.variables if name not in aligned]
    found = set(align_features(read, true).values())
    lines += [f"missing procedure {name}" for name in true.features if name not in found]
    if len(lines) > MAX_DIFFERENCES:
        more = len(lines) - MAX_DIFFERENCES
        lines = [*lines[:MAX_DIFFERENCES], f"… and {more} more"]
    return lines


def _few(values: list[Any], limit: int = 6) -> str:
    """A few values as text; times (``t3600`` in the alignment's notation) as h:mm:ss."""
    from apbot.model.values import format_hms

    def text(value: Any) -> str:
        raw = str(value)
        return format_hms(int(raw[1:])) if raw[:1] == "t" and raw[1:].isdigit() else raw

    shown = ", ".join(text(v) for v in values[:limit])
    return shown + (f", … ({len(values)} in all)" if len(values) > limit else "")
