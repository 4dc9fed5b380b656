"""Which setting an end of a scale is said of, when the words say it by the setting's own stem
rather than its name: "the dimmest setting" is the lowest BRIGHTNESS (whose words include DIM),
"the most sensitive collision setting" the top of SENSITIVITY ("sensitive" is the adjective of
the noun). An adjective and its noun share their stem; a superlative carries it.
"""

from __future__ import annotations

from apbot.read.goal_text import Text
from apbot.read.goal_vocab import concept, stem

_MIN_STEM = 5
"""Letters an adjective and a setting's noun must share ("sensitiv", "intens"): fewer would
join unrelated words."""


def _bases(word: str) -> set[str]:
    """ "dimmest" -> dim(m), "hottest" -> hot(t), "heaviest" -> "heavy", "fullest" -> full(l):
    a doubled last letter may be the superlative's doubling (dim) or the word's own (full,
    small), so both forms are tried."""
    base = word[:-3]
    bases = {base}
    if len(base) > 2 and base[-1] == base[-2]:
        bases.add(base[:-1])
    return {b[:-1] + "y" if b.endswith("i") else b for b in bases}


def superlative_stem_setting(
    text: Text, k: int, candidates: dict[str, dict[str, float]]
) -> str | None:
    """The one candidate setting (name -> vocab) the superlative at ``k`` is made of ("the
    dimmest"), or whose noun the adjective after "most" / "least" shares a stem with ("the most
    sensitive"); None when none or more than one is."""
    word = text.word(k)
    keys: set[str] = set()
    if word.endswith("est") and len(word) >= 6 and word.isalpha():
        keys = {concept(form) for base in _bases(word) for form in (base, base + "e")}
    found = [
        name for name, vocab in candidates.items() if any(vocab.get(x, 0) >= 0.8 for x in keys)
    ]
    if not found and word in ("most", "least") and k + 1 < len(text.tokens):
        adjective = stem(text.word(k + 1))
        if len(adjective) >= _MIN_STEM and text.word(k + 1).isalpha():
            found = [
                name
                for name, vocab in candidates.items()
                if any(
                    weight >= 0.8
                    and key != adjective
                    and key.startswith(adjective[:-1])
                    and len(adjective) - 1 >= _MIN_STEM
                    for key, weight in vocab.items()
                )
            ]
    return found[0] if len(found) == 1 else None
