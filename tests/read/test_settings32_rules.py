"""Rules of the settings32 session, each on a small manual of our own words: a stepping pair
whose legend prints its noun before "up / down" keeps that setting of its own, and a key made
the pair's entry key only by default gives it back (``up_down_nouns``, ``roles_amounts``)."""

from __future__ import annotations

from apbot.read import read_manual

# a pond aerator: the pair's legend names the airflow, a PURGE key stands beside it
AERATOR = """
Brisa PA-40 pond aerator

THE KEYS

  (1) ⏻ ........ on / standby
  (2) PURGE .... starts a purge; pressed again, ends it
  (3) +  (4) − . airflow up / down

AIRFLOW

Press + or −. Each press moves the airflow by 10 % and the screen shows AIR and the new
percentage, from 10 % to 100 %.

PURGE

PURGE blows at full airflow whatever the setting, to clear the hose.
"""

AERATOR_ACTIONS = ["press_power", "press_purge", "press_plus", "press_minus"]


def test_a_pair_legend_noun_before_up_down_is_the_pairs_own_setting() -> None:
    model = read_manual(AERATOR, AERATOR_ACTIONS).model
    stepped = {
        s.variable
        for f in model.features.values()
        for s in f
        if set(s.actions or []) == {"press_plus", "press_minus"} and s.variable
    }
    assert stepped == {"airflow"}
    # the other key is no entry key of the pair: the purge is no amount the pair steps
    assert not any(len(f) > 1 and f[0].actions == ["press_purge"] for f in model.features.values())


# the same shape where the noun is a part that moves: no setting of that name
BED = """
Rela B-2 bed remote

THE KEYS

  (1) +  (2) − . headrest up / down
  (3) FLAT ..... back to flat
"""


def test_a_moving_part_before_up_down_names_no_amount() -> None:
    model = read_manual(BED, ["press_plus", "press_minus", "press_flat"]).model
    assert "headrest" not in model.variables
