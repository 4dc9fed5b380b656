"""Action names → skill and control words; words → labels."""

from __future__ import annotations

from apbot.vision.vocabulary import label_tokens, name_parts, words_score


def test_name_parts() -> None:
    assert name_parts("press_time_cook") == ("press", ["time", "cook"])
    assert name_parts("hold_up_down") == ("hold", ["up", "down"])
    assert name_parts("turn_function_ccw") == ("turn_ccw", ["function"])
    assert name_parts("press_hold") == ("press", ["hold"])  # a key named HOLD
    assert name_parts("flip_power") == ("press", ["power"])
    assert name_parts("wait_5s")[0] == "wait"


def test_words_match_labels_through_synonyms_and_symbols() -> None:
    assert words_score(["power"], label_tokens("ON/OFF"), []) > 0.85
    assert words_score(["up"], [], ["▲"]) > 0.9
    assert words_score(["temp"], label_tokens("TEMPERATURE"), []) > 0.8
    assert words_score(["add30"], label_tokens("+30 SEC"), []) > 0.8
    assert words_score(["clock"], [], ["🔒"]) == 0.0  # a symbol is never matched by spelling
    assert words_score(["menu"], label_tokens("START"), []) == 0.0


def test_ocr_look_alikes_and_joined_words() -> None:
    assert words_score(["power"], label_tokens("1/0"), []) > 0.85  # I/O read as 1/0
    assert words_score(["power"], label_tokens("10 MIN"), []) == 0.0  # a number is no switch
    assert words_score(["zone"], label_tokens("IntensiveZone"), []) > 0.8
    assert words_score(["cancel"], label_tokens("×"), ["×"]) > 0.9
