"""Keys that choose what the one stepping pair changes (roles_pairafter, roles_raised,
roles_fixed, text), each rule on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual

# a pool pump timer: three keys choose what the one arrow pair changes, told by the steps
POOL = """# Pool pump timer

## The keys

| Key | What it does |
|---|---|
| ▲ | Raise the value shown |
| ▼ | Lower the value shown |
| START TIME | Set the hour the pump starts |
| FILTER TIME | Set how long the pump runs |
| BOOST | Run the pump now / stop |

## Start time

1. Press START TIME. The display shows ON and the start hour.
2. Press ▲ or ▼. Each press moves the start by one hour, 00:00 to 23:00.

## Filter time

1. Press FILTER TIME. The display shows the filter time, 1 h, 2 h, 4 h or 8 h.
2. Press ▲ or ▼ to change it.
"""
POOL_ACTIONS = ["press_up", "press_down", "press_start_time", "press_filter_time", "press_boost"]

# a seed warmer: the arrows set the temperature by themselves; TIME is set with them after it
LAMP = """# Seed warmer

## Keys

| Key | Use |
|---|---|
| ▲ / ▼ | Change the temperature, 20 to 35 °C. |
| TIME | Shows the switch-off time. |

## Switch-off time

1. Touch TIME. The display shows the hours left.
2. Use ▲ / ▼ to change it, from 1 to 12 hours.
"""
LAMP_ACTIONS = ["press_up", "press_down", "press_time"]

# a fish feeder: the arrows change "the value being set" — no quantity of their own
FEEDER = """# Fish feeder

## Keys

| Key | Press | Hold |
|---|---|---|
| PORTION | portion per feed | - |
| INTERVAL | hours between feeds | - |
| ▲ | increase the value being set | 2 s: increase by 10 steps |
| ▼ | decrease the value being set | 2 s: decrease by 10 steps |

## Portion

1. Press PORTION.
2. Press ▲ or ▼ to set 1 to 5 turns.

## Interval

1. Press INTERVAL.
2. Press ▲ or ▼ to set 4 to 24 hours.
"""
FEEDER_ACTIONS = [
    "press_portion",
    "press_interval",
    "press_up",
    "press_down",
    "hold_up",
    "hold_down",
]

# a heater's legend printed as a list of numbered callouts, one line each
HEATER = """# Panel heater

## Touch keys

   (1) ON/OFF  touch: on / off (standby)
   (2) MODE    next operating mode
   (3) ▲       warmer
   (4) ▼       cooler

## Operating modes

  Touch MODE to change the mode. The order is:

       COMFORT  →  ECO  →  FROST  →  COMFORT …
"""
HEATER_ACTIONS = ["press_on_off", "press_mode", "press_up", "press_down"]


def _steps(model: object, variable: str) -> list[list[str]]:
    feats = model.features  # type: ignore[attr-defined]
    for steps in feats.values():
        if any(s.variable == variable for s in steps):
            return [list(s.actions) for s in steps]
    return []


def test_a_key_whose_step_is_followed_by_the_pair_is_its_entry_key() -> None:
    model = read_manual(POOL, POOL_ACTIONS).model
    assert "start_time" in model.variables and "filter_time" in model.variables
    for name, key in (("start_time", "press_start_time"), ("filter_time", "press_filter_time")):
        steps = _steps(model, name)
        assert steps[0] == [key] and "press_up" in steps[1] and "press_down" in steps[1]
    # START TIME sets when the pump starts: it is no START key of the running state
    assert not any(
        "press_start_time" in s.actions and s.variable == "running"
        for steps in model.features.values()
        for s in steps
    )


def test_a_key_used_before_the_pairs_own_setting_still_takes_the_pair() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    (time,) = [v for v in model.variables if "time" in v]
    steps = _steps(model, time)
    assert steps[0] == ["press_time"] and set(steps[1]) >= {"press_up", "press_down"}


def test_the_value_being_set_is_no_quantity_of_the_pair() -> None:
    model = read_manual(FEEDER, FEEDER_ACTIONS).model
    assert not any("being" in v for v in model.variables)
    steps = _steps(model, "portion")
    assert steps and steps[0] == ["press_portion"] and "press_up" in steps[1]


def test_numbered_callouts_are_items_of_their_own() -> None:
    model = read_manual(HEATER, HEATER_ACTIONS).model
    # MODE's legend does not take ON/OFF's "on / off": its list is read
    assert model.variables["mode"].values == ["comfort", "eco", "frost"]


def test_current_after_a_noun_is_the_quantity_not_a_stop() -> None:
    """ "the current value" names no quantity, but "the charging current" is one: the pair
    sets the charging current, not a "charging"."""
    manual = """# Battery charger

## Keys

| Key | Use |
|---|---|
| ▲ / ▼ | Raise or lower the charging current, 1 A to 10 A |
"""
    model = read_manual(manual, ["press_up", "press_down"]).model
    assert "charging_current" in model.variables


# a bread maker: MENU walks the programme table by itself before the pair sets the time
BREAD = """# Bread maker

## Control panel

| Key | Use |
|---|---|
| MENU | Chooses the programme |
| + | Adds time |
| − | Takes time off |
| START/STOP | Starts or stops the programme |

## Programmes

| No. | Programme | Time |
|---|---|---|
| 1 | BASIC | 3:00 |
| 2 | FRENCH | 3:50 |
| 3 | DOUGH | 1:30 |

## Delayed baking

1. Press MENU repeatedly to choose a programme from the table.
2. Press + or − to set when the bread should be ready, up to 13 hours.
3. Press START/STOP.
"""


def test_a_key_pressed_repeatedly_before_the_pair_keeps_its_own_list() -> None:
    model = read_manual(BREAD, ["press_menu", "press_plus", "press_minus", "press_start_stop"])
    assert model.model.variables["menu"].values == ["basic", "french", "dough"]  # type: ignore[union-attr]


def test_a_start_key_that_also_adds_a_minute_still_starts() -> None:
    """START/+1 MIN starts cooking; only a START TIME names a time of its own."""
    manual = """# Microwave

| Key | Use |
|---|---|
| TIME | Sets the cooking time |
| START/+1 MIN | Starts cooking; each further press adds one minute |
"""
    model = read_manual(manual, ["press_time", "press_start_1_min"]).model
    assert any(
        "press_start_1_min" in s.actions and s.variable == "running"
        for steps in model.features.values()
        for s in steps
    )
