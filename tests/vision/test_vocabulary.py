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


def test_a_zone_sign_key_matches_its_name_and_not_the_other_zone() -> None:
    from apbot.vision.vocabulary import label_symbols

    assert label_symbols("+1") == ["+"] and label_symbols("-2") == ["−"]
    assert "1" in label_tokens("+1")
    plus1 = words_score(["plus1"], label_tokens("+1"), label_symbols("+1"))
    assert plus1 > 0.9
    assert words_score(["plus1"], label_tokens("+2"), label_symbols("+2")) < 0.6
    assert words_score(["minus2"], label_tokens("-2"), label_symbols("-2")) > 0.9
    # two zones' TEMP/TIME keys: the digit decides, not the shared prefix
    one = words_score(["temptime1"], label_tokens("TEMP/TIME 1"), [])
    assert one > words_score(["temptime1"], label_tokens("TEMP/TIME 2"), []) + 0.05


def test_units_and_spin_speed() -> None:
    from apbot.vision.vocabulary import label_symbols

    assert "°" in label_symbols("℃")  # OCR's one-character unit
    assert words_score(["temp"], label_tokens("℃"), label_symbols("℃")) > 0.9
    assert words_score(["spin"], label_tokens("RPM"), []) > 0.9


def test_a_printed_half() -> None:
    from apbot.vision.vocabulary import label_symbols

    assert "½" in label_tokens("1/2")
    assert words_score(["half"], label_tokens("1/2"), label_symbols("1/2")) > 0.9
    assert "½" not in label_tokens("11/20")
