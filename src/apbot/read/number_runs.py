"""Numbers printed in a row after a cue: a dial's or a lamp row's marks ("marked 20 30 40 60 90",
"positions OFF 400 600 800", "the lamps show 1 2 3 4"), read as the setting's values in their
order (split from ``value_lists``, which reads lists joined by arrows, commas and "or")."""

from __future__ import annotations

import re

_RUN_CUE = re.compile(  # a lookahead: every cue is tried
    r"(?=\b(?:printed|marked|markings?|labell?ed|reads?|positions?|settings?|scale|steps?|values?"
    r"|levels?|(?:lamps?|leds?|indicators?|lights?)\s+(?:show|read|mark))\b[^:.;]{0,30}?:?\s*(.*))",
    re.IGNORECASE,
)


def find_number_run(text: str) -> list[str] | None:
    """Numbers printed in a row after a cue ("marked 20 30 40 60 90"), in their order; a leading
    OFF reads as 0, another leading word (a named end position) is skipped."""
    for m in _RUN_CUE.finditer(text):
        # a mark's gloss is no break in the row: "0 (no spin)  400  600", "COLD (cold)  20  30"
        row = re.sub(r"(?<=\S)\s*\([^()]{1,20}\)(?=\s)", " ", m.group(1))
        tokens = [t.strip(".*:") for t in re.findall(r"[^\s,;]+", row)][:40]
        for start in range(min(8, len(tokens))):
            run: list[str] = []
            rest = tokens[start:]
            if rest and re.fullmatch(r"[A-Z][A-Z-]{1,9}", rest[0]):
                if rest[0].lower() == "off":
                    run.append("0")
                elif rest[0].lower() in ("cold", "cool"):  # a wash knob's first mark: a value
                    run.append(rest[0].lower())
                rest = rest[1:]
            for k, token in enumerate(rest):
                if re.fullmatch(r"\d+(?:[.,]\d+)?", token):
                    run.append(token)
                    continue
                if token.lower() in ("cold", "cool") and k >= 3 and not {"cold", "cool"} & set(run):
                    run.append(token.lower())  # "printed 90 60 40 30 20 ❄": the last mark, cold
                break
            if len(run) >= 3:
                return run
    return None
