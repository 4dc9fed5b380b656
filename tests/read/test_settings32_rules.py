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


# a kettle base whose pair's legend is only a noun phrase; the keys beside it use the pair too
KETTLE = """
Vapo K-9 kettle base

THE KEYS

  ⓐ ⏻    Hold 2 s: base on / off.
  ⓑ ▲ ▼  Beeper volume; inside a setting, change the value.
  ⓒ KEEP  Press: keep-warm temperature.

KEEP WARM

  1. Press KEEP briefly. The screen shows KW 80°C.
  2. Press ▲ / ▼ to change it by 5 °C, from 60 °C to 90 °C.

  Note: while the keep-warm temperature is shown, ▲ and ▼ change that temperature instead.

BEEPER

  With the normal screen showing, press ▲ for louder and ▼ for softer. The volume stops at 0
  and at 3.
"""

KETTLE_ACTIONS = ["hold_power", "press_up", "press_down", "press_keep"]


def test_a_pair_legend_of_a_bare_noun_phrase_names_the_pairs_own_setting() -> None:
    model = read_manual(KETTLE, KETTLE_ACTIONS).model
    alone = [
        f[0].variable
        for f in model.features.values()
        if len(f) == 1 and set(f[0].actions or []) == {"press_up", "press_down"}
    ]
    assert alone == ["volume"]
    # its range is the volume's, not the keep-warm temperature's in °C
    assert getattr(model.variables["volume"], "unit", None) != "°C"


# a fish-tank heater: its factory line lists several settings' starts; SET opens the target
AQUARIUM = """
Neri H-3 aquarium heater

THE KEYS

  ⓐ ⏻    Hold 3 s: heater on / off.
  ⓑ ▲ ▼  Display brightness; inside a setting, change the value.
  ⓒ SET  Press: target temperature.

  As delivered: BRT 3, SET 25 °C, ALM 2 °C.

TARGET TEMPERATURE

  1. Press SET. The screen shows SET 25°C.
  2. Press ▲ / ▼ to change it by 0.5 °C, from 18 °C to 32 °C.
"""

AQUARIUM_ACTIONS = ["hold_power", "press_up", "press_down", "press_set"]


def test_a_line_of_factory_values_is_no_keys_list() -> None:
    model = read_manual(AQUARIUM, AQUARIUM_ACTIONS).model
    entered = [
        f[1].variable
        for f in model.features.values()
        if len(f) == 2 and f[0].actions == ["press_set"]
    ]
    # SET opens a temperature the pair sets, not a choice among "brt 3, set 25 °c, alm 2 °c"
    assert len(entered) == 1
    assert getattr(model.variables[entered[0]], "unit", None) == "°C"


# the same aerator whose legend's noun is one roles_raised reads too ("intensity up / down")
AERATOR_INTENSITY = """
Brisa PA-40 pond aerator

THE KEYS

  (1) ⏻ ........ on / standby
  (2) PURGE .... starts a purge; pressed again, ends it
  (3) +  (4) − . bubble intensity up / down

INTENSITY

Press + or −. Each press moves the intensity by 10 % and the screen shows INT and the new
percentage, from 10 % to 100 %.

PURGE

PURGE blows at full intensity whatever the setting, to clear the hose.
"""


def test_a_pair_legend_noun_read_by_both_rules_still_keeps_its_setting() -> None:
    """Both roles_raised ("X up and down") and up_down_nouns read this legend; when the first
    did, the keys guessed as entry keys were no longer given back, and PURGE took the pair
    as a 0–10 amount of its own (the merge of set28b and settings32 lost it)."""
    model = read_manual(AERATOR_INTENSITY, AERATOR_ACTIONS).model
    assert model.variables["bubble_intensity"].ranges == [(10, 100, 10)]
    assert model.variables["purge"].values == ["off", "on"]
