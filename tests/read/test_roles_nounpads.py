"""Keys whose legend rows each select a kind of one thing (``roles_nounpads``): one setting
named by the noun they share, on small manuals written in our own words."""

from __future__ import annotations

from apbot.read import read_manual

# a drinks fountain: three keys, each row selecting one kind of water
FOUNTAIN = """FONTA drinks fountain

The keys

| Key | Printed | What it does |
|-----|---------|--------------|
| STILL | still | selects still water straight from the filter |
| FIZZ | bubbles | selects sparkling water |
| ICE | snowflake | selects iced water – only after the cooler has run for an hour |
| POUR | large key | start / stop pouring |

Touch STILL, FIZZ or ICE, then POUR.
"""
FOUNTAIN_ACTIONS = ["press_still", "press_fizz", "press_ice", "press_pour"]

# a massage cushion: the keys each start one massage, nothing runs before
CUSHION = """RELAXA massage cushion

| Key | Name | Touch |
|-----|------|-------|
| NECK | neck | starts the neck massage |
| BACK | back | starts the back (lumbar) massage |
| HEAT | heat | warmth on / off |
"""
CUSHION_ACTIONS = ["press_neck", "press_back", "press_heat"]

# keys that pick which amount the pair adjusts, or which part: no choice of their own
ADJUSTERS = """CLEANA cabinet

| Key | Touch |
|-----|-------|
| WASH | Selects the washing time |
| RINSE | Selects the rinsing time |
| + | Lengthens the selected time |
| − | Shortens the selected time |

The washing time is 10 to 60 minutes, the rinsing time 5 to 20 minutes.
"""
ADJUSTERS_ACTIONS = ["press_wash", "press_rinse", "press_plus", "press_minus"]


def test_keys_selecting_kinds_of_one_thing_are_one_setting() -> None:
    model = read_manual(FOUNTAIN, FOUNTAIN_ACTIONS).model
    water = model.variables["water"]
    assert water.values == ["still", "fizz", "ice"]
    goes = {
        s[0].actions[0]: s[0].effect.to for s in model.features.values() if s[0].variable == "water"
    }
    assert goes == {"press_still": "still", "press_fizz": "fizz", "press_ice": "ice"}


def test_keys_that_each_start_one_begin_at_off() -> None:
    model = read_manual(CUSHION, CUSHION_ACTIONS).model
    massage = model.variables["massage"]
    assert massage.values == ["off", "neck", "back"]
    assert (massage.initial or massage.values[0]) == "off"  # (no initial: the first value)


def test_keys_selecting_an_amount_to_adjust_are_no_choice() -> None:
    model = read_manual(ADJUSTERS, ADJUSTERS_ACTIONS).model
    assert "time" not in model.variables


# a clock radio whose keys step through the stations: no choice of a kind of station
RADIO = """TUNA clock radio

| Key | Function |
|-----|----------|
| SKIP | Selects the next station |
| BACK | Selects the previous station |
| ALARM | Switches the alarm on or off |
"""


def test_keys_selecting_the_next_or_previous_one_are_no_choice() -> None:
    model = read_manual(RADIO, ["press_skip", "press_back", "press_alarm"]).model
    assert "station" not in model.variables


# a drinks machine whose rows share an adjective, not the noun of what they select
DRINKS = """BREWA drinks machine

| Key | Touch |
|-----|-------|
| ESPRESSO | Selects hot coffee |
| MILK | Selects hot milk |
| TEA | Selects hot water for tea |
"""


def test_rows_sharing_only_an_adjective_are_no_setting() -> None:
    model = read_manual(DRINKS, ["press_espresso", "press_milk", "press_tea"]).model
    assert "hot" not in model.variables
