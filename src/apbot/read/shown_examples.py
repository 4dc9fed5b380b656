"""The words a display prints before a setting's figure, read from an example of it.

"Press DISC. The display shows the level, e.g. DISC LV 10.": the key is printed DISC, but the
display prints "DISC LV" before the figure. Reading the display by the key's name alone, the
figure after LV was never found, and a loop that could not read the level claimed the goal on
its belief. An example introduced by "e.g." or "for example" that starts with the setting's
label and runs on in capitals to a figure gives the display's own label.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.report import Note


def read_shown_examples(b: Builder) -> None:
    """Lengthen a numeric setting's label to the capitals an example prints before its figure."""
    lines = b.manual.lines
    for var, spec in b.variables.items():
        label = str(spec.get("label") or "")
        if spec.get("type") != "numeric" or not label or label.upper() != label:
            continue
        example = re.compile(
            r"\b(?:e\.\s?g\.|for example|for instance),?\s+"
            rf"({re.escape(label)}(?:\s+[A-Z]{{2,4}})+)\s+-?\d"
        )
        found = {m.group(1) for line in lines for m in example.finditer(line)}
        if len(found) == 1:
            shown = found.pop()
            spec["label"] = shown
            at = next(n for n, line in enumerate(lines, start=1) if shown in line)
            what = f"the display prints {shown} before it"
            b.notes.append(Note(f"variables.{var}.label", what, at, lines[at - 1].strip()[:160]))
