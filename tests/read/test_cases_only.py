"""A number a key sets in one mode only ("(NIGHT + TIMER mode only)"), on a small manual written
in our own words: it becomes that mode's case, starting where the manual says the mode puts it;
and a lamp legend whose word has the panel's icon before it still names the off word."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

LANTERN = """GLOWMATE GL-2 GARDEN LANTERN
Instructions

KEYS
   ①  ⏻       Power - switches the lantern on and off.
   ②  MODE    Chooses the lighting mode; each press moves to the next mode.
   ③  TIME    Chooses the burn time (NIGHT + TIMER mode only).
   ④  GLOW    Press and hold 3 seconds: switches the glow ring off or on again.

   Lamps
   ☀ STEADY        steady mode
   ⚡̸ GLOW OFF      glow off          the glow ring is off; only the lantern shines

MODES
   Press MODE to move to the next mode:

        STEADY  ->  NIGHT  ->  NIGHT + TIMER  ->  STEADY ...

BURN TIME
   The burn time applies only to the NIGHT + TIMER mode.
   Press TIME. Each press moves the burn time to the next value:

          1 h -> 3 h -> 5 h -> 1 h ...

   Each time NIGHT + TIMER is selected with MODE, the burn time starts again at 3 h.
"""
ACTIONS = ["press_power", "press_mode", "press_time", "hold_glow"]


def _time(text: str) -> tuple[object, dict[str, object]]:
    model = read_manual(text, ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    feature = next(f for f, steps in model.features.items() if steps[0].actions == ["press_time"])
    var = model.variables[model.features[feature][0].variable]
    return var, model.variables  # type: ignore[return-value]


def test_a_number_set_in_one_mode_only_is_that_modes_case() -> None:
    var, _ = _time(LANTERN)
    assert var.depends_on == "mode"  # type: ignore[attr-defined]
    cases = var.cases  # type: ignore[attr-defined]
    assert list(cases) == ["night + timer"]
    assert cases["night + timer"].initial == 3


def test_without_the_only_the_number_stays_free() -> None:
    text = LANTERN.replace(" (NIGHT + TIMER mode only)", "").replace(
        "The burn time applies only to the NIGHT + TIMER mode.", ""
    )
    var, _ = _time(text)
    assert var.depends_on is None  # type: ignore[attr-defined]


def test_a_lamp_legend_word_after_its_icon_is_the_off_word() -> None:
    model = read_manual(LANTERN, ACTIONS).model
    feature = next(f for f, steps in model.features.items() if steps[0].actions == ["hold_glow"])
    glow = model.variables[model.features[feature][0].variable]
    assert glow.show == {"on": "", "off": "GLOW OFF"}  # type: ignore[union-attr]


MISTER = """AIRLY H-3 HUMIDIFIER
Instructions

KEYS
  MODE          SMART -> HAND -> NIGHT -> SMART ...
  TARGET        target moisture (SMART mode only)

Touch POWER. The humidifier starts in SMART mode with a target moisture of 55 %, no timer.

Touch TARGET to change the target: each touch raises it by 5 %,

      45% -> 50% -> 55% -> 60% -> 65% -> 45% ...
"""


def test_the_start_sentence_gives_the_modes_start_value() -> None:
    model = read_manual(MISTER, ["press_power", "press_mode", "press_target"]).model
    feature = next(f for f, s in model.features.items() if s[0].actions == ["press_target"])
    var = model.variables[model.features[feature][0].variable]
    assert var.depends_on == "mode"  # type: ignore[union-attr]
    assert var.cases["smart"].initial == 55  # type: ignore[union-attr]
