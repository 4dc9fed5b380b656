"""The words that name the appliance itself ("it", "the machine", its own name, the manual's
title nouns): "switch the dispenser on" switches the appliance, not a setting. Split from
goal_view (the model as the parser sees it) so each job stays small."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from apbot.model.schema import ApplianceModel
from apbot.read.belief_name import UNNAMED
from apbot.read.goal_manual import title_nouns
from apbot.read.goal_values import name_words
from apbot.read.goal_vocab import concept, stem

if TYPE_CHECKING:
    from apbot.read.goal_view import VarInfo


def own_name(model: ApplianceModel) -> str:
    """The appliance's name, "" for a read belief's placeholder (:data:`UNNAMED`)."""
    return "" if model.appliance.name == UNNAMED else model.appliance.name


def appliance_said(model: ApplianceModel) -> str:
    """The appliance's name and category as a user may say them (casefolded; a read belief's
    placeholder name left out)."""
    return f"{own_name(model)} {model.appliance.category.replace('_', ' ')}".strip().casefold()


def appliance_words(
    model: ApplianceModel,
    manual: str,
    infos: dict[str, VarInfo],
    phrases: list[tuple[str, Any, tuple[str, ...], float]],
) -> set[str]:
    """The concepts of the words that name the appliance."""
    appliance = {concept(w) for w in name_words(appliance_said(model))}
    appliance |= {
        concept(w)
        for w in (
            "it",
            "machine",
            "appliance",
            "unit",
            "device",
            "washer",
            "cooker",
            "fryer",
            "oven",
            "kettle",
            "maker",
            "dehumidifier",
            "steriliser",
            "sterilizer",
            "hob",
            "ac",
            "aircon",
            "unit",
            "blender",
            "dishwasher",
            "toaster",
            "everything",
        )
    }
    category = frozenset(model.appliance.category.casefold().split("_"))
    said = {s for _var, _value, stems, _weight in phrases for s in stems}
    appliance |= {
        concept(tail)
        for tail in _tails(appliance_said(model))
        if stem(tail) not in said and not any(concept(tail) in i.vocab for i in infos.values())
    }  # "switch the chair on" for a wheelchair: a compound name said by its head noun
    appliance |= {
        concept(w)
        for w in title_nouns(manual, category)
        if stem(w) not in said and not any(concept(w) in i.vocab for i in infos.values())
    }  # "switch the dispenser on": not a setting's or a value's word
    return appliance


_MIN_TAIL = 5
"""Letters of a compound's head noun ("chair", "mower", "brush"); shorter tails are too
often other words ("hair" of "wheelchair")."""


def _tails(name: str) -> set[str]:
    """The head nouns a closed compound of the appliance's name ends in: "wheelchair" gives
    "chair" (and longer tails no one says, which do no harm)."""
    return {
        word[start:]
        for word in name_words(name)
        if word.isalpha()
        for start in range(2, len(word) - _MIN_TAIL + 1)
    }
