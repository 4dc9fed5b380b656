"""Walk rules of walk16: a walk told in running prose (`walk_steps.py`)."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.walk_flashed import flashed_field
from apbot.read.walk_steps import held_adds, moves_at_ends, prose_opener, walk_steps

# a towel-rail radiator (our own words): the clock walk told as prose, no numbered steps
RADIATOR = """TOWELWARM R5 towel rail

KEYS
  POWER     on / off.
  CLOCK     opens the clock.
  ▲         raises the flashing value.
  ▼         lowers the flashing value.

SETTING THE CLOCK
Press and hold CLOCK for 3 seconds. The hour flashes. Press ▲ or ▼ to set the hour.
Press CLOCK again and the minutes flash. Press ▲ or ▼ to set the minutes.
After 8 seconds without a key the clock is stored.
"""
RADIATOR_ACTIONS = ["press_power", "press_clock", "hold_clock", "press_up", "press_down"]

# a lift table (our own words): holding the stepping pair moves fast, it opens no walk
LIFT = """RAISO L1 lift table

MOVING THE TABLE

  Tap ▲ or ▼: the table moves 1 cm up or down and the display shows the new height.

  Hold ▲ or ▼ for 2 seconds: the table travels 5 cm in that direction and stops. Hold again
  for another 5 cm. From 50 cm a hold on ▲ gives 55 cm.

  The L1 travels between 40 cm (lowest) and 90 cm (highest).
"""
LIFT_ACTIONS = ["press_up", "press_down", "hold_up", "hold_down"]


def test_prose_sentences_that_work_a_key_begin_steps() -> None:
    units = parse_manual(RADIATOR).units
    at = next(i for i, u in enumerate(units) if u.text.startswith("Press and hold CLOCK"))
    steps = [t for _, t in walk_steps(units, at)]
    assert steps[0] == "Press and hold CLOCK for 3 seconds. The hour flashes."
    assert steps[2] == "Press CLOCK again and the minutes flash."
    assert steps[-1].endswith("the clock is stored.")
    assert len(steps) == 4


def test_a_clock_walk_told_in_prose_is_read() -> None:
    model = read_manual(RADIATOR, RADIATOR_ACTIONS).model
    walks = [s for s in model.features.values() if [x.actions for x in s][:1] == [["hold_clock"]]]
    assert len(walks) == 1
    timed = [s for s in walks[0] if s.variable]
    assert len(timed) == 2 and model.variables[timed[0].variable].type == "time"
    assert "press_clock" in walks[0][2].actions


def test_a_held_stepping_key_opens_no_prose_walk(monkeypatch: Any) -> None:
    # a hold of ▲ followed by prose that reads as one setting (a range, then the pair): the
    # walk reader must not open it, since holding a stepping key steps fast (a later rule would
    # hide such a walk from the model, so the walks the reader applies are recorded)
    import apbot.read.held_walks as held_walks

    manual = """RAISO L2 lift table

MOVING THE TABLE

  Hold ▲ for 2 seconds: the memory height flashes, 40 to 90 cm. Press ▲ or ▼ to set it.

  The display shows the height.
"""
    applied: list[str] = []
    apply = held_walks.apply_walk

    def recorded(b: Any, hold: str, *rest: Any) -> None:
        applied.append(hold)
        apply(b, hold, *rest)

    monkeypatch.setattr(held_walks, "apply_walk", recorded)
    read_manual(manual, LIFT_ACTIONS)
    assert "hold_up" not in applied
    model = read_manual(LIFT, LIFT_ACTIONS).model
    assert not any(
        [x.actions for x in s][:1] == [["hold_up"]] and len(s) > 2 for s in model.features.values()
    )


def test_a_held_stepping_key_is_no_prose_opener() -> None:
    units = parse_manual(LIFT).units
    hold = next(u for u in units if u.text.startswith("Hold ▲"))
    assert not prose_opener(hold, paired=True)
    assert prose_opener(hold, paired=False)


# a sports watch (our own words): one key (ADJ) changes every field, each step closed by SET;
# the fields named by what flashes, their ranges in the items table, the clock in two fields
WATCH = """RUNTIME W7 sports watch

KEYS
  SET       opens the settings; moves on.
  ADJ       changes the flashing value.
  LIGHT     lights the display.

SETTING THE WATCH

  | Item | Display    | ADJ pressed    | ADJ held 2 s |
  |------|------------|----------------|--------------|
  | 1    | EN, DE, FR | changes        | -            |
  | 2    | MON 1 … 12 | +1 month       | +5 months    |
  | 3    | DAY 1 … 31 | +1 day         | +5 days      |
  | 4    | hour       | +1 hour        | +5 hours     |
  | 5    | minutes    | +1 minute      | +5 minutes   |

  1. Hold SET for 3 seconds. The language flashes: EN, DE or FR.
  2. Press ADJ to change the language. Then press SET.
  3. MON and the month flash. Press ADJ until the month is right (ADJ held 2 s adds five
     months). Then press SET.
  4. DAY and the day flash. Press ADJ until the day is right. Then press SET.
  5. The hour flashes. Press ADJ until the hour is right (ADJ held 2 s adds five hours).
     Then press SET.
  6. The minutes flash. Press ADJ until the minutes are right (ADJ held 2 s adds five
     minutes). Then press SET.

Each press of ADJ adds one; after the last value the first comes again.

LIGHT
  Press LIGHT to light the display for 3 seconds.
"""
WATCH_ACTIONS = ["hold_set", "press_set", "press_adj", "hold_adj", "press_light"]


def _watch_walk():  # type: ignore[no-untyped-def]
    model = read_manual(WATCH, WATCH_ACTIONS).model
    walks = [s for s in model.features.values() if [x.actions for x in s][:1] == [["hold_set"]]]
    assert len(walks) == 1
    return model, walks[0]


def test_one_key_adjusting_each_field_walks_them() -> None:
    model, walk = _watch_walk()
    names = [s.variable for s in walk if s.variable]
    assert names[:3] == ["language", "mon", "day"]
    assert model.variables["language"].values == ["en", "de", "fr"]
    assert all("press_adj" in s.actions for s in walk if s.variable)


def test_a_field_range_from_the_items_table() -> None:
    model, _ = _watch_walk()
    assert model.variables["mon"].ranges[0][:2] == (1, 12)
    assert model.variables["day"].ranges[0][:2] == (1, 31)


def test_hours_then_minutes_join_into_one_time() -> None:
    model, walk = _watch_walk()
    timed = [s for s in walk if s.variable == "time"]
    assert len(timed) == 2 and model.variables["time"].type == "time"
    assert timed[0].effect["press_adj"].add == 3600
    assert timed[1].effect["press_adj"].add == 60
    assert timed[1].effect["hold_adj"].add == 300


def test_the_adjusters_hold_adds_what_its_step_says() -> None:
    _, walk = _watch_walk()
    month = next(s for s in walk if s.variable == "mon")
    assert month.effect["hold_adj"].add == 5
    assert "adj" not in read_manual(WATCH, WATCH_ACTIONS).model.variables


def test_moves_said_at_the_end_of_a_step_open_the_next() -> None:
    steps = [
        (1, "Hold SET. The unit flashes."),
        (2, "Press ADJ to change. Then press SET."),
        (3, "The age flashes. Press ADJ until it is right."),
    ]
    out = moves_at_ends(steps, "SET")
    assert out[1][1] == "Press ADJ to change."
    assert out[2][1].startswith("Press SET. The age flashes.")


def test_flashed_fields() -> None:
    assert flashed_field("Hold MODE. The scale flashes: C or F.") == {
        "name": "scale",
        "values": ["c", "f"],
        "own_name": True,
    }
    field = flashed_field("Press SET. The user flashes (U1 to U3).")
    assert field is not None and field["values"] == ["U1", "U2", "U3"]
    assert held_adds("(ADJ held 2 s adds ten minutes)") == (10, "minutes")


def test_a_held_amount_in_any_number_word() -> None:
    assert held_adds("(UP held 2 s adds fifteen minutes)") == (15, "minutes")
    assert held_adds("holding UP adds a lot at once") is None


def test_advice_in_prose_begins_no_step_but_a_key_after_use_does() -> None:
    text = (
        "## Timer\n\nPress and hold TIMER for 2 seconds. The hours flash.\n"
        "Keep in mind that the timer stops at a power cut.\nUse ▲ or ▼ to set the hours.\n"
    )
    units = parse_manual(text).units
    at = next(i for i, u in enumerate(units) if u.text.startswith("Press and hold TIMER"))
    steps = [t for _, t in walk_steps(units, at)]
    assert len(steps) == 2 and "Keep in mind" in steps[0] and steps[1].startswith("Use ▲")


def test_flashed_codes_in_two_digits_and_unit_signs() -> None:
    field = flashed_field("Press SET. The user flashes (U3 to U12).")
    assert field is not None and field["values"][-1] == "U12" and len(field["values"]) == 10
    field = flashed_field("Hold UNIT. The scale flashes: °C or °F.")
    assert field is not None and field["values"] == ["°c", "°f"]


def test_a_held_amount_on_a_time_counts_its_unit_in_seconds() -> None:
    from types import SimpleNamespace

    from apbot.read.actions import ActionInfo
    from apbot.read.walk_flashed import held_steps

    infos = [ActionInfo("press_adj", "press", ("adj",)), ActionInfo("hold_adj", "hold", ("adj",))]
    b: Any = SimpleNamespace(infos=infos, variables={"delay": {"type": "time"}})
    steps: list[dict[str, Any]] = [
        {"actions": ["press_adj"], "variable": "delay", "effect": {"press_adj": {"add": 60}}}
    ]
    held_steps(b, ["press_adj"], steps, {"said": "(ADJ held 2 s adds ten minutes)"})
    assert steps[0]["effect"]["hold_adj"] == {"add": 600}


def test_a_joined_clock_is_named_by_its_owner_and_steps_as_said() -> None:
    from apbot.read.walk_flashed import CLOCK_SPEC, clock_field, clock_steps

    field = clock_field("The alarm hours flash.", "Each press moves 5 minutes.", set())
    assert field["name"] == "alarm time" and field["minute"] == 300
    assert field["spec"]["ranges"] == [["00:00:00", "23:55:00", 300]]
    assert CLOCK_SPEC["ranges"] == [["00:00:00", "23:59:00", 60]]  # the shared spec untouched
    assert clock_field("The hours flash.", "", {"time"})["name"] == "time 2"
    steps = clock_steps("alarm_time", ["press_up"], ["press_down"], "press_set", 300)
    assert steps[2]["effect"] == {"press_up": {"add": 300}, "press_down": {"add": -300}}
