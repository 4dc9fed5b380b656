"""Walks of like fields shown by display codes (`walk_like.py`): "shows P1 and its time",
the rest set "in the same way" ("then PROG for P3"), and the pair's own time from the keys'
legend folded into the walk."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.walk_like import code_name, its_code

# a heating thermostat (our own words): PROG walks three switching periods, each a time
THERMOSTAT = """HEATWISE T-3 room thermostat

KEYS
  PROG      Shows the period times one after the other.
  +         later: +10 minutes (held 2 s: +1 hour).
  -         earlier: -10 minutes (held 2 s: -1 hour).
  ECO       Economy mode on / off.

SETTING THE PERIOD TIMES
  1. Press PROG. The display shows P1 and its time, e.g. P1 06:30.
  2. Press + or -. Each press moves the time by 10 minutes. After 23:50 comes 00:00.
  3. Press PROG. The display shows P2 and its time.
  4. Set P2 in the same way, then PROG for P3.
  5. After P3, PROG shows P1 again.

ECO
  Press ECO to switch the economy mode on or off.
"""
THERMOSTAT_ACTIONS = [
    "press_prog",
    "press_plus",
    "press_minus",
    "hold_plus",
    "hold_minus",
    "press_eco",
]

# a sprinkler timer (our own words): two named times, the second "in the same way"
SPRINKLER = """RAINKEEP S2 sprinkler timer

KEYS
  CLOCK     Opens the watering times (WATER ON, then WATER OFF).
  ▲         later: +30 minutes (held 2 s: +3 hours).
  ▼         earlier: -30 minutes (held 2 s: -3 hours).

WATERING TIMES
  1. Press CLOCK. The display shows WATER ON and its time.
  2. Press ▲ or ▼: 30 minutes per press. After 23:30 comes 00:00.
  3. Press CLOCK. The display shows WATER OFF and its time.
  4. Set it with ▲ and ▼ in the same way.
  5. Press CLOCK to come back, or any other key to finish.
"""
SPRINKLER_ACTIONS = ["press_clock", "press_up", "press_down", "hold_up", "hold_down"]


def _walk(model, opener: str):  # type: ignore[no-untyped-def]
    walks = [
        steps
        for steps in model.features.values()
        if len(steps) > 2 and [s.actions for s in steps][:1] == [[opener]]
    ]
    assert len(walks) == 1
    return walks[0]


def test_like_fields_go_on_by_their_codes() -> None:
    model = read_manual(THERMOSTAT, THERMOSTAT_ACTIONS).model
    walk = _walk(model, "press_prog")
    names = [s.variable for s in walk if s.variable]
    assert names == ["period_1", "period_2", "period_3"]
    assert [model.variables[n].label for n in names] == ["P1", "P2", "P3"]
    assert all(model.variables[n].type == "time" for n in names)


def test_the_pairs_own_time_is_the_walks_and_its_holds_step_the_fields() -> None:
    model = read_manual(SPRINKLER, SPRINKLER_ACTIONS).model
    walk = _walk(model, "press_clock")
    timed = [s for s in walk if s.variable]
    assert all({"hold_up", "hold_down"} <= set(s.actions) for s in timed)
    alone = [
        s.variable
        for steps in model.features.values()
        if steps is not walk
        for s in steps
        if s.variable and model.variables[s.variable].type == "time"
    ]
    assert alone == []


def test_named_codes_name_the_fields() -> None:
    model = read_manual(SPRINKLER, SPRINKLER_ACTIONS).model
    walk = _walk(model, "press_clock")
    names = [s.variable for s in walk if s.variable]
    assert names == ["water_on", "water_off"]
    assert model.variables["water_off"].label == "WATER OFF"


def test_code_names() -> None:
    assert its_code("Press SET. The display shows A2 and its time.") == "A2"
    assert its_code("Press SET. The display shows the time.") == ""
    assert code_name("A2", "SETTING THE ALARM TIMES") == "alarm_2"
    assert code_name("LOCK AT", "CURFEW") == "lock_at"
    assert code_name("Z3", "SETTING THE ALARM TIMES") == "z3"


# a bread machine (our own words): SET walks the baking temperature, then the rising time;
# only the chart gives their values, per programme
BREAD = """LOAFY B-2 bread machine

KEYS
  MENU      chooses the programme: BASIC, WHOLE or QUICK.
  SET       opens the programme's settings; moves on.
  +         higher.
  -         lower.

PROGRAMME CHART

  | Programme | Baking temperature | Rising time          |
  |-----------|--------------------|----------------------|
  | BASIC     | 150 - 190 °C       | 30 - 90 min, 10 min  |
  | WHOLE     | 160 - 200 °C       | 40 - 120 min, 10 min |
  | QUICK     | 170 - 210 °C       | 10 - 30 min, 10 min  |

  All temperatures in steps of 10 °C.

SETTINGS

  1. Touch SET. The baking temperature flashes, e.g. 180 °C.
  2. Change it with + / -.
  3. Touch SET. The rising time flashes, e.g. 60 min.
  4. Change it with + / -.
  5. Touch SET to store.
"""
BREAD_ACTIONS = ["press_menu", "press_set", "press_plus", "press_minus"]


def test_flashing_fields_take_the_charts_values() -> None:
    model = read_manual(BREAD, BREAD_ACTIONS).model
    walk = _walk(model, "press_set")
    names = [s.variable for s in walk if s.variable]
    assert names[-1] == "rising_time"
    rising = model.variables["rising_time"]
    assert rising.depends_on is not None and len(rising.cases or {}) == 3
