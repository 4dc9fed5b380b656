"""The newcats development set: complete appliances of new categories, none of the held-out six."""

from __future__ import annotations

from pathlib import Path

from apbot.bench.newcats_goal_sizes import DEVELOPMENT_GOAL_VARIABLES
from apbot.bench.suite import (
    CATEGORIES,
    HELD_OUT_CATEGORIES,
    load_suite,
)
from apbot.bench.suite_check import check_appliance

NEWCATS = Path(__file__).resolve().parents[2] / "benchmarks" / "data" / "newcats"
HELD_OUT = HELD_OUT_CATEGORIES
# Close relatives of the held-out six, which the set must not contain either.
RELATIVES = {"oven", "coffee", "espresso", "tea", "blender", "juicer", "slow", "pressure"}
RELATIVES |= {"dishwasher", "conditioner", "fan", "heat", "pump"}
RELATIVES |= {"toaster", "processor", "multi", "purifier"}


def test_every_newcats_appliance_passes_the_checker() -> None:
    suite = load_suite(NEWCATS)  # a directory is loaded with the model checks
    assert (
        len(suite.appliances) >= 150
    )  # the first set of five and the second to thirtieth blind sets
    for appliance in suite.appliances:
        errors = [p.render() for p in check_appliance(appliance) if p.severity == "error"]
        assert errors == [], appliance.id
        assert len(appliance.tasks) == 10, appliance.id
        assert 1500 <= appliance.manual_words <= 3000, appliance.id


def test_the_set_holds_new_categories_only_and_no_held_out_one() -> None:
    categories = [a.category for a in load_suite(NEWCATS).appliances]
    assert len(set(categories)) == len(categories)  # each appliance a different category
    for category in categories:
        assert category in DEVELOPMENT_GOAL_VARIABLES and category not in CATEGORIES
        assert category not in HELD_OUT
        assert not set(category.split("_")) & RELATIVES, category
    assert (NEWCATS / "README.md").is_file()
