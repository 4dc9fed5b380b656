"""Seeded perturbations of a manual the way real commercial manuals arrive (used by
``manual_noise.py``): long boilerplate, page furniture, hard wraps, tables drawn with spaces, a
sister model's paragraph.

Each perturbation only adds text or moves line breaks: every word of the manual stays, in order
(a hyphenated break aside), so a drop in the reader's score is the noise's, not lost facts.
Each is deterministic for a given seed.
"""

from __future__ import annotations

import random
import re
import textwrap
import zlib
from collections.abc import Callable
from pathlib import Path

NOISE_DIR = Path(__file__).resolve().parent / "data" / "noise"
KINDS = ("boilerplate", "pages", "wraps", "tables", "sister", "all")


def rng_for(name: str, kind: str, seed: int = 0) -> random.Random:
    """A random source fixed by the manual's name, the perturbation and the seed."""
    return random.Random(zlib.crc32(f"{name}|{kind}|{seed}".encode()))


def _sections(path: Path) -> list[str]:
    """A boilerplate file cut at its "## " headings."""
    text = path.read_text(encoding="utf-8")
    parts = re.split(r"(?m)^(?=## )", text)
    return [p.strip("\n") + "\n" for p in parts if p.strip()]


def boilerplate(text: str, rng: random.Random, directory: Path = NOISE_DIR) -> str:
    """(a) Safety, installation and conformity text before the manual's body (after its title
    line), cleaning, troubleshooting, guarantee and disposal text after it; the sections in a
    seeded order."""
    front, back = _sections(directory / "front.md"), _sections(directory / "back.md")
    rng.shuffle(front)
    rng.shuffle(back)
    lines = text.split("\n")
    cut = 0
    if lines and lines[0].startswith("# "):
        cut = 1
    head, body = "\n".join(lines[:cut]), "\n".join(lines[cut:])
    pieces = [head, "\n".join(front), body.strip("\n") + "\n", "\n".join(back)]
    return "\n\n".join(p.strip("\n") for p in pieces if p.strip()) + "\n"


def _fenced(lines: list[str]) -> list[bool]:
    out, inside = [], False
    for line in lines:
        if line.strip().startswith("```"):
            out.append(True)
            inside = not inside
            continue
        out.append(inside)
    return out


_TITLES = (
    "{brand} {model}   Instruction manual",
    "OPERATING INSTRUCTIONS  {model}",
    "{brand} · User guide",
    "{model} EN",
)
_FOOTERS = ("- {n} -", "{n}", "Page {n}", "EN · {n}", "{n} / {total}")
_BRANDS = ("NORDVIK", "Kelsa", "HOMEWELL", "Tavio", "BRIXHAM")
_MODELS = ("ZR-2000", "KT-1750", "HX-220 / HX-230", "AX-450", "QM 41")


def pages(text: str, rng: random.Random) -> str:
    """(b) A running header and a page-number footer every 40-50 lines, as text flattened out
    of a PDF: wherever the page ends, in a paragraph or a table."""
    lines = text.split("\n")
    fenced = _fenced(lines)
    title = rng.choice(_TITLES).format(brand=rng.choice(_BRANDS), model=rng.choice(_MODELS))
    footer = rng.choice(_FOOTERS)
    length = rng.randint(40, 50)
    total = len(lines) // length + 1
    out: list[str] = []
    page, count = 1, 0
    for i, line in enumerate(lines):
        out.append(line)
        count += 1
        if count >= length and i + 1 < len(lines) and not fenced[i + 1]:
            out += ["", footer.format(n=page, total=total), "", title, ""]
            page, count = page + 1, 0
            length = rng.randint(40, 50)
    out += ["", footer.format(n=page, total=total)]
    return "\n".join(out) + "\n"


_BULLET = re.compile(r"^(\s*(?:[-*•]|\d{1,2}[.)])\s+)")


def _prose(line: str) -> bool:
    s = line.strip()
    if not s or s.startswith(("#", "|", "```", ">")) or re.fullmatch(r"[-=*_]{3,}", s):
        return False
    return not re.search(r"\S {2,}\S", s)  # columns drawn with spaces are a table's row


def _hyphenate(lines: list[str], rng: random.Random, width: int) -> list[str]:
    """Some breaks move the front of the next line's first long word up, ending in "-"."""
    for k in range(len(lines) - 1):
        nxt = lines[k + 1]
        m = re.match(r"(\s*)([A-Za-z]{8,})(?=[\s.,;:]|$)", nxt)
        if not m or rng.random() >= 0.3:
            continue
        word = m.group(2)
        cut = rng.randint(3, len(word) - 4)
        if len(lines[k]) + 1 + cut + 1 > width + 4:
            continue
        lines[k] = f"{lines[k]} {word[:cut]}-"
        lines[k + 1] = m.group(1) + word[cut:] + nxt[m.end() :]
    return lines


def _caps(line: str) -> bool:
    letters = [c for c in line if c.isalpha()]
    return bool(letters) and all(c.isupper() for c in letters)


def wraps(text: str, rng: random.Random) -> str:
    """(c) Running text set again at 60-75 characters (a width per manual): a paragraph's lines
    joined and broken anew, a bullet's next lines hung under its text, some breaks inside a
    word with a hyphen. Tables, headings, drawings, lines in capitals (a plain-text heading)
    and lines with columns are left as they are, and no paragraph runs into them."""
    width = rng.randint(60, 75)
    lines = text.split("\n")
    fenced = _fenced(lines)
    out: list[str] = []
    para: list[str] = []
    lead = hang = ""

    def flush() -> None:
        nonlocal para
        if para:
            wrapped = textwrap.wrap(
                " ".join(p.strip() for p in para),
                width=width,
                initial_indent=lead,
                subsequent_indent=hang,
                break_long_words=False,
                break_on_hyphens=False,
            )
            out.extend(_hyphenate(wrapped, rng, width))
        para = []

    for i, line in enumerate(lines):
        if fenced[i] or not _prose(line) or _caps(line):
            flush()
            out.append(line)
            continue
        bullet = _BULLET.match(line)
        ended = bool(para) and bool(re.search(r"[.!?:]$", para[-1])) and len(para[-1]) < 60
        if bullet or not para or ended:  # (a short line ending a sentence ends a paragraph)
            flush()
            lead = line[: len(line) - len(line.lstrip())]
            hang = " " * len(bullet.group(1)) if bullet else lead
        para.append(line[bullet.end() :] if bullet else line)
        if bullet:
            lead = bullet.group(1)
    flush()
    return "\n".join(out)


_RULE = re.compile(r"^\s*\|?\s*:?-{2,}:?\s*(\|\s*:?-{2,}:?\s*)*\|?\s*$")


def tables(text: str, rng: random.Random) -> str:
    """(d) Pipe tables drawn again as columns of text aligned with spaces (the rule row gone,
    bold marks dropped), as a converter that does not know Markdown writes them."""
    gap = rng.randint(2, 4)
    lines = text.split("\n")
    out: list[str] = []
    i = 0
    while i < len(lines):
        if not lines[i].strip().startswith("|"):
            out.append(lines[i])
            i += 1
            continue
        j = i
        while j < len(lines) and lines[j].strip().startswith("|"):
            j += 1
        rows = [
            [c.strip().replace("**", "") for c in line.strip().strip("|").split("|")]
            for line in lines[i:j]
            if not _RULE.match(line)
        ]
        ncols = max(len(r) for r in rows)
        widths = [max((len(r[c]) for r in rows if c < len(r)), default=0) for c in range(ncols)]
        for row in rows:
            cells = [cell.ljust(widths[c]) for c, cell in enumerate(row)]
            out.append((" " * gap).join(cells).rstrip())
        i = j
    return "\n".join(out)


_SISTER_KEYS = (
    "TURBO",
    "BOOST",
    "ECO",
    "SILENT",
    "AROMA",
    "NIGHT",
    "PULSE",
    "FRESH",
    "VAPOUR",
    "CRISP",
    "HYGIENE",
    "EXTRA",
    "JET",
    "ZONE",
)
_SISTER_MODELS = ("XY-300", "ZR-2000W", "KT-1900", "HX-230", "AX-450 Plus")
_SISTER_TEXTS = (
    "Model {m} only: a {k1} key sits beside the display. Press {k1} to switch between "
    "LOW, MEDIUM and HIGH; the {k1} lamp shows the level. Press and hold {k2} for 3 seconds "
    "to switch the {k2} function on or off (the display shows {k2} ON / {k2} OFF).",
    "Model {m} only: this model has two extra keys, {k1} and {k2}. Each press of {k1} raises "
    "the setting by 5, from 10 to 60; {k2} selects AUTO, 1, 2 or 3. The other models of the "
    "range do not have these keys; on them, skip this paragraph.",
    "Model {m} only: press {k1} to choose the {k1} programme (P9). Press and hold {k1} and "
    "{k2} together for 5 seconds to lock the keys; the {k2} symbol lights. Times of 0:30 to "
    "2:00 can then be set with {k2}.",
)


def sister(text: str, rng: random.Random) -> str:
    """(e) A paragraph for another model of the range ("Model XY-300 only: …") naming keys this
    manual never names, put before one of the body's second-level headings."""
    absent = [k for k in _SISTER_KEYS if not re.search(rf"\b{k}\b", text, re.I)]
    k1, k2 = rng.sample(absent, 2)
    para = rng.choice(_SISTER_TEXTS).format(m=rng.choice(_SISTER_MODELS), k1=k1, k2=k2)
    lines = text.split("\n")
    fenced = _fenced(lines)
    heads = [i for i, line in enumerate(lines) if line.startswith("## ") and not fenced[i]]
    middle = heads[1:-1] or heads or [len(lines)]
    at = rng.choice(middle)
    return "\n".join([*lines[:at], para, "", *lines[at:]])


def perturb(text: str, kind: str, name: str, seed: int = 0) -> str:
    """The manual ``text`` (of appliance ``name``) under one perturbation, or all of them."""
    steps: dict[str, Callable[[str, random.Random], str]] = {
        "boilerplate": boilerplate,
        "sister": sister,
        "tables": tables,
        "wraps": wraps,
        "pages": pages,
    }
    if kind == "all":
        for step in ("boilerplate", "sister", "tables", "wraps", "pages"):
            text = steps[step](text, rng_for(name, step, seed))
        return text
    if kind not in steps:
        raise ValueError(f"unknown perturbation {kind!r} (one of {', '.join(KINDS)})")
    return steps[kind](text, rng_for(name, kind, seed))
