"""The noise benchmark's perturbations: deterministic, and every fact of the manual kept."""

from __future__ import annotations

import re

import pytest

from apbot.bench.suite import load_suite
from benchmarks.noise_perturb import KINDS, perturb

APPLIANCES = ("kettle_1", "rice_cooker_3", "washing_machine_2", "microwave_3")


def _whole(text: str) -> str:
    """A word broken by a hyphen at a line's end ("tempera-" / "ture") made whole."""
    return re.sub(r"([A-Za-z])-\s+([a-z])", r"\1\2", text)


def _words(text: str) -> list[str]:
    return re.findall(r"[A-Za-z0-9]+", _whole(text))


def _in_order(needle: list[str], hay: list[str]) -> bool:
    it = iter(hay)
    return all(word in it for word in needle)


@pytest.mark.parametrize("kind", KINDS)
def test_each_perturbation_is_deterministic_and_keeps_every_word_in_order(kind: str) -> None:
    suite = load_suite("bundled")
    for appliance_id in APPLIANCES:
        text = suite.get(appliance_id).manual
        noisy = perturb(text, kind, appliance_id)
        assert noisy == perturb(text, kind, appliance_id)
        assert (noisy != text) == (kind != "tables" or "|" in text), (kind, appliance_id)
        assert _in_order(_words(text), _words(noisy)), (kind, appliance_id)
        for line in _whole(text).splitlines():  # each line's words, too, still stand in the text
            assert set(_words(line)) <= set(_words(noisy)), (kind, appliance_id, line)


def test_the_seed_and_the_manual_change_the_noise() -> None:
    text = load_suite("bundled").get("kettle_1").manual
    assert perturb(text, "pages", "kettle_1", seed=0) != perturb(text, "pages", "kettle_1", 1)
    assert perturb(text, "sister", "kettle_1") != perturb(text, "sister", "kettle_2")


def test_boilerplate_is_long_and_the_sister_model_names_keys_the_manual_lacks() -> None:
    text = load_suite("bundled").get("kettle_1").manual
    added = len(perturb(text, "boilerplate", "kettle_1")) - len(text)
    assert 15_000 <= added <= 25_000
    sister = perturb(text, "sister", "kettle_1")
    line = next(x for x in sister.splitlines() if x.startswith("Model ") and " only: " in x)
    keys = set(re.findall(r"\b[A-Z]{3,}\b", line)) - {"LOW", "MEDIUM", "HIGH", "AUTO", "ON", "OFF"}
    assert keys and not any(re.search(rf"\b{k}\b", text, re.I) for k in keys)
    assert perturb(text, "all", "kettle_1") != text


def test_an_unknown_perturbation_is_refused() -> None:
    with pytest.raises(ValueError, match="unknown perturbation"):
        perturb("x", "smudges", "kettle_1")
