"""What a key's cycle prints, read as the values a user names.

* "PER 1 → PER 2 → PER 3 → PER 4 → PER OT": every value starts with the same word, the setting's
  own name cut short (PER for PERIOD, CH for CHANNEL, PROG for PROGRAM). The values are what
  follows it ("1" … "OT"); the display prints the whole word.
* "(no arrow) → ◄POSS (home) → POSS► (guest) → (no arrow)": the cycle's items carry their
  meaning in brackets, and one item is only a bracket — nothing shown. The values are the
  meanings ("none", "home", "guest"); the display prints the signs, and nothing for the bare
  one. Read by its signs alone, the setting had no value a user says, and no "none".
* "⚡H ........ high-speed sync" / "2nd ........ rear-curtain (second-curtain) sync": a legend
  of signs with dotted leaders glosses two or more of a setting's values. Each glossed value is
  named by its gloss, less the setting's own name and any bracket ("high-speed", "rear-curtain");
  the display prints the sign.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder

_ARROW = re.compile(r"\s*(?:→|->|⇒|>)\s*")
# a bracket alone: the state that shows nothing ("(no arrow)", "(none)", "(blank)")
_BARE = re.compile(r"\(\s*([^()]{2,30}?)\s*\)")
# a sign and its meaning: "◄POSS (home)", "L (low)"
_GLOSSED = re.compile(r"(\S(?:.{0,14}?\S)?)\s+\(\s*([a-z][a-z -]{1,20}?)\s*\)", re.IGNORECASE)
_EMPTY_WORDS = re.compile(r"^(?:no\b.*|none|blank|nothing|off|empty)$", re.IGNORECASE)


def read_cycle_words(b: Builder) -> None:
    """Both rules, for every discrete setting a key steps through."""
    for var, spec in list(b.variables.items()):
        values = spec.get("values")
        if spec.get("type") != "discrete" or not values or "show" in spec:
            continue
        if _named_prefix(b, var, spec, values):
            continue
        if _glossed(b, var, spec, values):
            continue
        _leader_glossed(b, var, spec, values)


def _named_prefix(b: Builder, var: str, spec: dict[str, Any], values: list[str]) -> bool:
    parts = [str(v).split(" ", 1) for v in values]
    if len(values) < 3 or not all(len(p) == 2 for p in parts):
        return False
    heads = {p[0] for p in parts}
    if len(heads) != 1:
        return False
    head = heads.pop()
    name = re.sub(r"[^a-z]", "", str(spec.get("label") or var).lower())
    if len(head) < 2 or not head.isalpha() or not name.startswith(head) or name == head:
        return False  # (the head must be the setting's own name cut short)
    tails = [p[1] for p in parts]
    if len(set(tails)) != len(tails):
        return False
    at = _printed_line(b, [str(v) for v in values])
    printed = b.manual.lines[at - 1] if at else ""
    show = {}
    for v, t in zip(values, tails, strict=True):
        m = re.search(rf"(?<![\w]){re.escape(str(v))}(?!\w)", printed, re.IGNORECASE)
        show[t] = m.group(0) if m else str(v).upper()
    _renamed(b, var, spec, dict(zip(values, tails, strict=True)))
    spec["show"] = show
    b.note(
        f"variables.{var}.values",
        f"{', '.join(tails)} (each shown after {head.upper()})",
        _unit_at(b, at),
    )
    return True


def _printed_line(b: Builder, values: list[str]) -> int | None:
    """The 1-based line printing every value, case aside (the cycle's own line)."""
    for n, line in enumerate(b.manual.glyph_lines or b.manual.lines, start=1):
        low = line.lower()
        if all(v.lower() in low for v in values):
            return n
    return None


def _unit_at(b: Builder, line: int | None) -> int | None:
    """The unit that starts at or holds the 1-based line (for the report's quote)."""
    if line is None:
        return None
    best = None
    for i, u in enumerate(b.manual.units):
        if u.line is not None and u.line <= line:
            best = i
    return best


def _glossed(b: Builder, var: str, spec: dict[str, Any], values: list[str]) -> bool:
    lines = b.manual.glyph_lines or b.manual.lines
    for n, line in enumerate(lines, start=1):
        items = [i.strip() for i in _ARROW.split(line.strip()) if i.strip()]
        items = [i for i in items if not re.fullmatch(r"\.{2,}|…", i)]
        if len(items) < 3:
            continue
        meanings: dict[str, str] = {}
        shows: dict[str, str] = {}
        for item in items:
            if (m := _BARE.fullmatch(item)) and _EMPTY_WORDS.match(m.group(1)):
                meanings.setdefault("", "none")
                continue
            m = _GLOSSED.fullmatch(item)
            if m is None:
                break
            meanings.setdefault(m.group(1).lower(), m.group(2).lower().strip())
            shows.setdefault(m.group(1).lower(), m.group(1))
        else:
            codes = [c for c in meanings if c]
            if sorted(codes) != sorted(str(v) for v in values) or len(codes) < 2:
                continue
            if any(re.fullmatch(r"[a-z]{3,}", c) for c in codes):
                continue  # ("ECO (saves energy)": a word the user says, described; review31)
            glosses = list(meanings.values())
            if len(set(glosses)) != len(glosses):
                continue
            order = list(meanings)  # (the cycle's order, the bare state where it stands)
            new_values = [meanings[c] for c in order]
            renames = {c: meanings[c] for c in codes}
            _renamed(b, var, spec, renames)
            spec["values"] = new_values
            spec["show"] = {meanings[c]: (shows[c] if c else "") for c in order}
            what = ", ".join(new_values) + " (the cycle's meanings)"
            b.note(f"variables.{var}.values", what, _unit_at(b, n))
            return True
    return False


# "⚡H .................... high-speed sync": a sign (glyphs before it allowed), dotted leaders
_LEADER = r"^\s*([^\w\s]{{0,2}}{value})\s*\.{{3,}}\s*(.+?)\s*$"


def _leader_glossed(b: Builder, var: str, spec: dict[str, Any], values: list[str]) -> None:
    own = set(re.findall(r"[a-z]+", var)) | set(
        re.findall(r"[a-z]+", str(spec.get("label", "")).lower())
    )
    lines = b.manual.glyph_lines or b.manual.lines
    names: dict[str, str] = {}
    shows: dict[str, str] = {}
    at = None
    for value in values:
        pattern = re.compile(_LEADER.format(value=re.escape(str(value))), re.IGNORECASE)
        for n, line in enumerate(lines, start=1):
            m = pattern.match(line)
            if m is None:
                continue
            if re.search(r"\d", m.group(2)):
                break  # ("Grill ..... Grilling meat 5", "Fan ..... 35 W": a page, a rating)
            gloss = re.sub(r"\([^)]*\)", " ", m.group(2).lower())
            words_ = [w for w in re.findall(r"[a-z][a-z-]*", gloss) if w not in own]
            if not 1 <= len(words_) <= 3:
                break
            if set(str(value).lower().split()) <= set(re.findall(r"[a-z]+", gloss)):
                break  # ("WHITE ..... everyday white rice": the name, described, stays)
            names[str(value)] = " ".join(words_)
            shows[str(value)] = m.group(1)
            at = at if at is not None else n
            break
    if len(names) < 2 or len(set(names.values())) != len(names):
        return
    if set(names.values()) & (set(values) - set(names)):
        return
    renamed = {str(v): names.get(str(v), str(v)) for v in values}
    _renamed(b, var, spec, renamed)
    spec["show"] = {renamed[c]: sign for c, sign in shows.items()}
    what = ", ".join(f"{shows[c]} {n}" for c, n in names.items()) + " (glossed in a legend)"
    b.note(f"variables.{var}.values", what, _unit_at(b, at))


def _renamed(b: Builder, var: str, spec: dict[str, Any], names: dict[str, str]) -> None:
    """Values renamed everywhere the builder keeps them: the spec, effects, guards, cases."""
    spec["values"] = [names.get(str(v), v) for v in spec["values"]]
    if spec.get("initial") is not None:
        spec["initial"] = names.get(str(spec["initial"]), spec["initial"])
    for steps in b.features.values():
        for st in steps:
            eff = st.get("effect")
            if st.get("variable") == var and isinstance(eff, dict):
                for k, e in list(eff.items()):
                    if isinstance(e, dict) and "to" in e:
                        eff[k] = {**e, "to": names.get(str(e["to"]), e["to"])}
            for key in ("set",):
                if isinstance(st.get(key), dict) and var in st[key]:
                    st[key][var] = names.get(str(st[key][var]), st[key][var])
    for g in b.guards:
        if var in (g.get("when") or {}):
            g["when"][var] = names.get(str(g["when"][var]), g["when"][var])
    for child in b.variables.values():
        if child.get("depends_on") == var and "cases" in child:
            child["cases"] = {names.get(str(k), k): c for k, c in child["cases"].items()}
