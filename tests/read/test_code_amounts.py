"""Display codes that carry an amount of time (code_amounts), on short manuals in our own
words: the values become the amounts the display legend counts, the codes what it shows."""

from __future__ import annotations

from apbot.read import read_manual

HEATER = """# WARMA FH-1 fan heater

## Keys

| Key | What it does |
|---|---|
| ⏻ | Switches the heater on and off. |
| TURBO | Turbo heating: each touch adds 15 minutes. |

## Display

    t15 … t60 ....... turbo minutes left

## Turbo

Touch TURBO. Each touch adds 15 minutes, up to one hour:

    off → t15 → t30 → t45 → t60 → off
"""


def test_codes_counting_minutes_become_the_minutes() -> None:
    model = read_manual(HEATER, ["press_power", "press_turbo"]).model
    turbo = model.variables["turbo"]
    assert turbo.values == ["off", "15 min", "30 min", "45 min", "60 min"]
    assert turbo.show == {"15 min": "t15", "30 min": "t30", "45 min": "t45", "60 min": "t60"}


RADIO = """# NOTA CR-2 clock radio

## Keys

| Key | What it does |
|---|---|
| SNOOZE | Silences the alarm for a while. |
| NAP | Nap timer. |

## Display

    NP 60 … NP 20 ....... nap timer minutes; NP OFF = no nap timer

## Nap timer

Press NAP repeatedly:

    NP OFF → NP 60 → NP 40 → NP 20 → NP OFF …
"""


def test_a_code_for_none_is_off() -> None:
    model = read_manual(RADIO, ["press_snooze", "press_nap"]).model
    nap = next(v for n, v in model.variables.items() if "nap" in n)
    assert nap.values == ["off", "60 min", "40 min", "20 min"]
    assert nap.show == {"60 min": "NP 60", "40 min": "NP 40", "20 min": "NP 20", "off": "NP OFF"}


PROGRAMMES = """BAKA BM-3 bread maker

KEYS
   MENU    next programme: P1 → P2 → P3 → P4 → P1
"""


def test_programme_codes_without_a_counting_legend_stay_codes() -> None:
    model = read_manual(PROGRAMMES, ["press_menu"]).model
    menu = next(v for n, v in model.variables.items() if "menu" in n)
    assert menu.values == ["p1", "p2", "p3", "p4"]


WASHER = """# KOKO WM-7 washer

## Keys

| Key | What it does |
|---|---|
| ⏻ | On and off. |
| PROG | Chooses the programme. |

## Display

    P1 … P4 ....... programmes (P4: 30 minutes quick wash)
    L1 … L3 ....... spin levels; the drum runs on 2 minutes after a stop

## Programmes

Press PROG: P1 → P2 → P3 → P4 → P1.
"""


def test_minutes_said_past_the_legends_first_clause_count_nothing() -> None:
    model = read_manual(WASHER, ["press_power", "press_prog"]).model
    prog = next(v for n, v in model.variables.items() if "prog" in n)
    assert prog.values == ["p1", "p2", "p3", "p4"]


SWING = """ROKKA BS-2 baby swing

THE KEYS

  Key      Function
  ⏻        Switches the unit on or off.
  TIMER    Swing timer: s OFF, s10, s20, s40 (minutes).

SETTING THE TIMER

  Press TIMER repeatedly:

        s OFF → s10 → s20 → s40 → s OFF → …

  s10 is ten minutes, s40 forty minutes.
"""


def test_a_unit_in_brackets_after_the_codes_counts_them() -> None:
    model = read_manual(SWING, ["press_power", "press_timer"]).model
    timer = next(v for n, v in model.variables.items() if "timer" in n)
    assert timer.values == ["off", "10 min", "20 min", "40 min"]
    assert timer.show == {"10 min": "s10", "20 min": "s20", "40 min": "s40", "off": "s OFF"}


FEEDER = """KIBA PF-1 plant feeder

THE KEYS

  Key      Function
  ⏻        Switches the unit on or off.
  REPEAT   Repeats the feed automatically (lamps r1, r2, r4).

DISPLAY

  r1 / r2 / r4        feed every 1 / 2 / 4 days (no lamp: no repeat)

REPEAT

  Press REPEAT to choose:

       no repeat → r1 → r2 → r4 → no repeat
"""


def test_codes_legend_may_repeat_their_numbers_and_none_said_in_words_is_off() -> None:
    model = read_manual(FEEDER, ["press_power", "press_repeat"]).model
    repeat = next(v for n, v in model.variables.items() if "repeat" in n)
    assert repeat.values == ["off", "1 d", "2 d", "4 d"]
    assert repeat.show == {"1 d": "r1", "2 d": "r2", "4 d": "r4"}


MISTER = """# NEBBI GM-3 greenhouse mister

## Keys

| Key | What it does |
|---|---|
| ⏻ | On and off. |
| MIST | How often it mists. |

## Misting

Touch MIST: M OFF → M 1d → M 2d → M 4d → M OFF …
"""


def test_codes_printing_their_unit_letter_count_it() -> None:
    model = read_manual(MISTER, ["press_power", "press_mist"]).model
    mist = next(v for n, v in model.variables.items() if "mist" in n)
    assert mist.values == ["off", "1 d", "2 d", "4 d"]
    assert mist.show == {"1 d": "M 1d", "2 d": "M 2d", "4 d": "M 4d", "off": "M OFF"}
