"""A key printed as an abbreviation, its setting named by the noun its legend spells out.

"DISP – display lighting", "ILLUM – illumination level": the legend line of a key printed short
glosses what the key sets. Read key by key the setting was named after the key ("disp"), a name
no user says ("dim the display lights"). Here a setting still named after its key's token, whose
key has a legend line "LABEL – noun phrase" of two or three lower-case words whose first word
the label abbreviates (DISP → display), takes the phrase as its name.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder


def _rename(b: Builder, old: str, new: str) -> None:
    b.variables[new] = b.variables.pop(old)
    for steps in b.features.values():
        for step in steps:
            if step.get("variable") == old:
                step["variable"] = new
    b.indicators = [new if v == old else v for v in b.indicators]
    for guard in b.guards:
        when = guard.get("when") or {}
        if old in when:
            when[new] = when.pop(old)


def read_legend_nouns(b: Builder) -> None:
    """Name each key-named setting by the noun phrase its abbreviated key's legend gives."""
    for info in b.infos:
        if info.skill != "press" or len(info.controls) != 1:
            continue
        token = info.controls[0]
        lab = b.labels.get(token)
        if token not in b.variables or lab is None or lab.line is None:
            continue
        short = lab.text.lower()
        if not re.fullmatch(r"[a-z]{2,5}", short):
            continue
        pattern = re.compile(
            rf"^{re.escape(lab.text)}\s*[–—:-]\s*((?:[a-z]+)(?:\s+[a-z]+){{1,2}})\s*$"
        )
        for at, unit in enumerate(b.manual.units):
            m = pattern.match(unit.text.strip())
            if m is None:
                continue
            phrase = m.group(1).split()
            if not phrase[0].startswith(short) or phrase[0] == short:
                break
            new = "_".join(phrase)
            if new in b.variables:
                break
            _rename(b, token, new)
            b.note(f"variables.{new}", f"{lab.text} glossed as {' '.join(phrase)}", at)
            break
