"""A list setting whose walk showed, in words the belief cannot read, the value the user said.

A reader can take a STYLE or BOWL key for a switch (off/on), or get only some of a MODE key's
modes. The goal parser then keeps the user's word as said (``apbot.read.goal_listed``), the
agent walks the setting's key, and the display shows one word per press — MOZZARELLA,
RICOTTA, FETA — none of which the belief reads. When the word the user said is among them, the
display has named the setting's real choices: they become its values (each shown as printed),
so the walk can learn their order and the planner reach the one asked for. When it is not
among them, nothing is learnt here and the loop stops on the missing value, as before.
"""

from __future__ import annotations

from collections.abc import Sequence

from apbot.agent.repair import RepairError, name_values
from apbot.agent.worded import WORDS
from apbot.model.schema import ApplianceModel, DiscreteVariable


def said_choices(
    model: ApplianceModel, name: str, texts: Sequence[str], said: str
) -> ApplianceModel | None:
    """``name`` with the words ``texts`` showed as its values, when one of them is ``said``
    (None: not a plain list setting, a text that is no word, or ``said`` not shown).

    >>> from apbot.model.schema import ApplianceModel
    >>> model = ApplianceModel.model_validate({
    ...     "appliance": {"id": "m", "category": "c", "name": "m"},
    ...     "variables": {"style": {"type": "discrete", "values": ["off", "on"], "label": "STYLE"}},
    ...     "controls": [{"id": "style", "kind": "button", "label": "STYLE"}],
    ...     "actions": {"press_style": {"control": "style"}},
    ...     "features": {"style": [
    ...         {"actions": ["press_style"], "variable": "style", "effect": "toggle"}]},
    ... })
    >>> new = said_choices(model, "style", ["FETA", "BRIE", "FETA"], "brie")
    >>> new.variables["style"].values, new.features["style"][0].effect
    (['off', 'on', 'feta', 'brie'], 'next')
    >>> said_choices(model, "style", ["FETA", "BRIE"], "gouda") is None
    True
    >>> said_choices(model, "style", ["L", "R"], "right") is None
    True
    >>> said_choices(model, "style", ["STYLE FETA", "STYLE BRIE"], "brie") is not None
    True
    """
    spec = model.variables[name]
    if not isinstance(spec, DiscreteVariable) or spec.cases:
        return None
    words: dict[str, str] = {}  # value -> the text as shown
    label = (spec.label or "").strip().casefold()
    for text in texts:
        shown = word = text.strip()
        if label and word.casefold().startswith(label + " "):
            word = word[len(label) :].strip()  # STYLE FETA: the setting's label, then its value
        if not WORDS.fullmatch(word):
            return None  # a text with numbers or marks: not a list of names
        words.setdefault(word.casefold(), shown)
    if len(words) < 2 or said.strip().casefold() not in words:
        return None  # (R for RIGHT is left alone: a letter may stand for more than one word)
    try:
        return name_values(model, name, words)
    except RepairError:
        return None
