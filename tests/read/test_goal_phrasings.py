"""Phrasings written for this parser on the development appliances (_1.._3), with the goal
each one means: a regression table for value names, units, times, negation and starting.

None of these sentences is a suite task; they vary what the tasks say in other words.
"""

from __future__ import annotations

from typing import Any

import pytest

from apbot.bench.suite import bundled_suite_dir, load_appliance
from apbot.read.goal import parse_instruction

CASES: list[tuple[str, str, dict[str, Any]]] = [
    (
        "microwave_1",
        "Defrost for ten minutes using time defrost",
        {"defrost_time": "00:10:00", "running": "on"},
    ),
    (
        "microwave_1",
        "Cook at power level five for three minutes, then start",
        {"power_level": 5, "cook_time": "00:03:00", "running": "on"},
    ),
    ("microwave_1", "Put a 90 second kitchen timer on", {"kitchen_timer": "00:01:30"}),
    (
        "washing_machine_1",
        "Cottons at 40 degrees, 1400 rpm, extra rinse on, start now",
        {
            "programme": "cottons",
            "temperature": "40",
            "spin_speed": 1400,
            "extra_rinse": "on",
            "running": "on",
        },
    ),
    (
        "washing_machine_1",
        "Run the synthetics programme at 30°C without prewash and with the child lock",
        {
            "programme": "synthetics",
            "temperature": "30",
            "prewash": "off",
            "child_lock": "on",
            "running": "on",
        },
    ),
    (
        "washing_machine_1",
        "Wool cycle, cold, spin 600, and have it end in 6 hours. Go!",
        {
            "programme": "wool",
            "temperature": "cold",
            "end_time": 6,
            "spin_speed": 600,
            "running": "on",
        },
    ),
    (
        "rice_cooker_2",
        "Cook rice with a 4 hour delay and start it",
        {"menu": "rice", "delay": "04:00:00", "running": "on"},
    ),
    (
        "rice_cooker_2",
        "Make yogurt for 8 hours, no keep warm",
        {"menu": "yogurt", "cook_time": "08:00:00", "keep_warm": "off", "running": "on"},
    ),
    (
        "rice_cooker_3",
        "Set the cooker to steam for 40 minutes and turn the buzzer off",
        {"menu": "steam", "cook_time": "00:40:00", "buzzer": "off"},
    ),
    (
        "kettle_1",
        "Boil the water and keep it warm",
        {"keep_warm": "on", "temperature": 100, "heating": "on"},
    ),
    ("kettle_1", "I need 95°C water, don't heat it yet", {"temperature": 95, "heating": "off"}),
    ("kettle_2", "Heat to 203°F", {"temperature": 95, "heating": "on"}),
    (
        "kettle_2",
        "Set 70 degrees and hold it for twenty minutes",
        {"temperature": 70, "hold_time": "00:20:00"},
    ),
    (
        "induction_cooker_1",
        "Soup function, 1600 W, 30 minute timer",
        {"function": "soup", "timer": "00:30:00", "heat_power": 1600},
    ),
    (
        "induction_cooker_3",
        "Simmer at 90 degrees for 45 minutes",
        {"programme": "simmer", "temperature": 90, "timer": "00:45:00"},
    ),
    (
        "air_fryer_1",
        "Bake at 180 °C for 25 minutes with the light on",
        {"function": "bake", "temperature": 350, "timer": "00:25:00", "light": "on"},
    ),
    (
        "air_fryer_1",
        "Toast for 3 minutes at 450 with airflow high",
        {"airflow": "high", "function": "toast", "temperature": 450, "timer": "00:03:00"},
    ),
    (
        "air_fryer_2",
        "Fries preset, 180 degrees, 15 minutes, shake reminder on, go",
        {
            "preset": "fries",
            "temperature": 180,
            "cook_time": "00:15:00",
            "shake": "on",
            "running": "on",
        },
    ),
    (
        "air_fryer_3",
        "Roast at 400 for 20 minutes, preheat on, start",
        {
            "program": "roast",
            "temperature": 400,
            "cook_time": "00:20:00",
            "preheat": "on",
            "running": "on",
        },
    ),
    ("bread_maker_2", "Jam, start it", {"menu": "jam", "running": "on"}),
    (
        "bread_maker_3",
        "Set the clock to 7:15 am and bake a medium French loaf with a dark crust now",
        {"crust": "dark", "size": "M", "cycle": "french", "clock": "07:15:00", "running": "on"},
    ),
    (
        "bottle_washer_1",
        "Sterilise and dry with 60 minutes of drying, start",
        {"mode": "sterilise + dry", "dry_time": 60, "running": "on"},
    ),
    (
        "bottle_washer_2",
        "Dry only for 40 minutes and turn the night light on",
        {"programme": "dry", "dry_time": 40, "night_light": "on"},
    ),
    (
        "dehumidifier_1",
        "Set humidity to 55 percent and the fan to high",
        {"fan_speed": "high", "humidity": 55},
    ),
    ("dehumidifier_1", "Sleep mode with a 6 hour off timer", {"mode": "sleep", "timer": 6}),
    (
        "dehumidifier_2",
        "Laundry on, fan medium, timer 4 hours",
        {"fan_speed": "medium", "timer": 4, "laundry": "on"},
    ),
    (
        "induction_cooker_2",
        "Temperature mode at 160 degrees for 10 minutes, start",
        {"heat_mode": "temperature", "temperature": 160, "timer": "00:10:00", "running": "on"},
    ),
    (
        "induction_cooker_2",
        "Power level 6, 30 minutes, go",
        {"power_level": 6, "timer": "00:30:00", "running": "on"},
    ),
    (
        "rice_cooker_1",
        "Brown rice, finished by 6 pm",
        {"menu": "brown", "finish_time": "18:00:00", "status": "timer"},
    ),
    ("rice_cooker_1", "Set the clock to 8:05 in the evening", {"clock": "20:05:00"}),
    (
        "rice_cooker_1",
        "Cook the sushi rice straight away with a harder texture",
        {"texture": "harder", "menu": "sushi", "status": "cooking"},
    ),
    (
        "rice_cooker_2",
        "Porridge for 1h30, start",
        {"menu": "porridge", "cook_time": "01:30:00", "running": "on"},
    ),
    (
        "rice_cooker_2",
        "Soup, 90-minute cook time, delay of 3 hours, start it",
        {"menu": "soup", "cook_time": "01:30:00", "delay": "03:00:00", "running": "on"},
    ),
    (
        "rice_cooker_3",
        "White rice, preset 10 hours, begin",
        {"menu": "white", "preset": "10:00:00", "running": "on"},
    ),
    (
        "microwave_1",
        "Microwave at 50% power for 2 min",
        {"power_level": 5, "cook_time": "00:02:00", "running": "on"},
    ),
    (
        "microwave_1",
        "Heat for 30 seconds on full power",
        {"cook_time": "00:00:30", "power_level": 10, "running": "on"},
    ),
    (
        "microwave_1",
        "Pop the 3.5 oz bag of popcorn and start",
        {"popcorn_size": "3.5 oz", "running": "on"},
    ),
    (
        "microwave_2",
        "Defrost 500 g of fish using auto defrost",
        {"defrost_food": "fish", "defrost_weight": 500, "running": "on"},
    ),
    (
        "microwave_2",
        "Cook for 5 minutes at medium power and start it",
        {"power_level": "medium", "cook_time": "00:05:00", "running": "on"},
    ),
    (
        "bread_maker_2",
        "French bread, 2 lb, medium crust, ready in 5 hours, start",
        {"menu": "french", "delay": "05:00:00", "loaf_size": 2, "crust": 2, "running": "on"},
    ),
    (
        "bread_maker_3",
        "Wholemeal, large, light crust, ready at 7 am, start",
        {
            "crust": "light",
            "cycle": "wholemeal",
            "size": "L",
            "ready_at": "07:00:00",
            "timer": "on",
            "running": "on",
        },
    ),
    (
        "washing_machine_3",
        "Cottons at 40 with 1200 spin and steam, delay 3 hours, start",
        {
            "programme": "cottons",
            "delay_start": "03:00:00",
            "spin": "1200",
            "temperature": "40",
            "steam": "on",
            "running": "on",
        },
    ),
    (
        "washing_machine_3",
        "Synthetics at 30, no spin, start it now",
        {"spin": "no spin", "programme": "synthetics", "temperature": "30", "running": "on"},
    ),
    (
        "washing_machine_1",
        "Mixed load 40°C 800 rpm and start",
        {"programme": "mixed load", "temperature": "40", "spin_speed": 800, "running": "on"},
    ),
    (
        "washing_machine_1",
        "Rinse only with extra rinse and lock the panel",
        {"programme": "rinse", "extra_rinse": "on", "child_lock": "on"},
    ),
    (
        "dehumidifier_1",
        "Continuous mode, fan low, lock it",
        {"mode": "continuous", "fan_speed": "low", "child_lock": "on"},
    ),
    ("dehumidifier_3", "Timer 4 hours and pump off", {"timer": 4, "pump": "off"}),
    (
        "kettle_3",
        "Set keep warm to 90 degrees and pour a cup",
        {"amount": "cup", "keep_warm_temp": 90, "dispensing": "on"},
    ),
    (
        "kettle_2",
        "Lock the kettle and heat to 100",
        {"temperature": 100, "child_lock": "on", "heating": "on"},
    ),
    (
        "induction_cooker_1",
        "Milk at 400 watts for 10 minutes",
        {"function": "milk", "heat_power": 400, "timer": "00:10:00"},
    ),
    (
        "induction_cooker_3",
        "Fry at 200 °C and lock the child lock",
        {"programme": "fry", "temperature": 200, "child_lock": "on"},
    ),
    (
        "bottle_washer_3",
        "Dry for 40 minutes and start",
        {"program": "dry", "cycle_time": "00:40:00", "running": "on"},
    ),
    (
        "air_fryer_2",
        "Cake preset at 160 degrees for 40 minutes, don't start yet",
        {"preset": "cake", "temperature": 160, "cook_time": "00:40:00", "running": "off"},
    ),
    (
        "air_fryer_3",
        "Dehydrate at 140°F for 6 hours",
        {"program": "dehydrate", "temperature": 140, "cook_time": "06:00:00", "running": "on"},
    ),
    (
        "air_fryer_1",
        "Broil for 10 min with the oven light off",
        {"function": "broil", "timer": "00:10:00", "light": "off"},
    ),
    (
        "bread_maker_2",
        "Make a basic loaf, 2 pound size, crust 2, and have it start in 2 hours",
        {"menu": "basic", "loaf_size": 2, "crust": 2, "delay": "02:00:00", "running": "on"},
    ),
    (
        "bread_maker_2",
        "Use the cake setting with the darkest crust colour; start immediately",
        {"menu": "cake", "crust": 3, "running": "on"},
    ),
    (
        "bread_maker_2",
        "Sweet bread with a 1.5 lb loaf and the middle crust, start in 4 hours",
        {"menu": "sweet", "loaf_size": 1.5, "delay": "04:00:00", "crust": 2, "running": "on"},
    ),
    (
        "bread_maker_2",
        "Bake for 70 minutes on the bake setting, light crust",
        {"menu": "bake", "bake_time": "01:10:00", "crust": 1, "running": "on"},
    ),
    (
        "bread_maker_3",
        "Set the clock to 18:45. Rapid cycle, small size, start now",
        {"cycle": "rapid", "size": "S", "clock": "18:45:00", "running": "on"},
    ),
    ("bread_maker_3", "Jam cycle please and switch the light on", {"cycle": "jam", "light": "on"}),
    (
        "air_fryer_1",
        "Warm the food at 150 degrees for 30 minutes",
        {"function": "warm", "temperature": 150, "timer": "00:30:00"},
    ),
    (
        "air_fryer_1",
        "Convection bake at 300°F for an hour, low fan",
        {"function": "convection bake", "airflow": "low", "temperature": 300, "timer": "01:00:00"},
    ),
    (
        "air_fryer_2",
        "Switch on the fryer and cook shrimp at 160 °C for 7 minutes",
        {
            "preset": "shrimp",
            "temperature": 160,
            "cook_time": "00:07:00",
            "power": "on",
            "running": "on",
        },
    ),
    (
        "air_fryer_2",
        "Manual mode, 185 degrees, 25 min, shake on, and start",
        {
            "preset": "manual",
            "temperature": 185,
            "cook_time": "00:25:00",
            "shake": "on",
            "running": "on",
        },
    ),
    (
        "air_fryer_3",
        "Turn on the air fryer, reheat at 350 for 10 minutes with no preheat",
        {
            "program": "reheat",
            "temperature": 350,
            "cook_time": "00:10:00",
            "preheat": "off",
            "power": "on",
            "running": "on",
        },
    ),
    (
        "air_fryer_3",
        "Bake at 375 for 35 minutes and press start",
        {"program": "bake", "temperature": 375, "cook_time": "00:35:00", "running": "on"},
    ),
    ("dehumidifier_1", "Turn it on and set the timer for 8 hours", {"timer": 8, "power": "on"}),
    ("dehumidifier_1", "Keep the humidity at 50%", {"humidity": 50}),
    ("dehumidifier_1", "Auto mode with the fan on high", {"mode": "auto", "fan_speed": "high"}),
    (
        "dehumidifier_2",
        "Set humidity to continuous and speed to medium",
        {"fan_speed": "medium", "humidity": "CO"},
    ),
    (
        "dehumidifier_2",
        "Switch the laundry mode off and set the fan to high",
        {"fan_speed": "high", "laundry": "off"},
    ),
    (
        "dehumidifier_3",
        "Set the knob to 4 and the fan high",
        {"fan_speed": "high", "humidistat": "4"},
    ),
    ("dehumidifier_3", "Run continuously with the pump on", {"humidistat": "cont", "pump": "on"}),
    (
        "washing_machine_1",
        "I'd like the sportswear programme with a spin of 1000 and prewash",
        {"programme": "sportswear", "spin_speed": 1000, "prewash": "on"},
    ),
    (
        "washing_machine_1",
        "Please power up the washer and run a quick 20 cycle",
        {"programme": "quick 20", "power": "on", "running": "on"},
    ),
    (
        "washing_machine_2",
        "Heavy course, water level 46, wash for 21 minutes, rinse 3 times, spin 9 min, start it",
        {
            "course": "heavy",
            "water_level": 46,
            "spin_time": 9,
            "rinses": 3,
            "wash_time": 21,
            "running": "on",
        },
    ),
    (
        "washing_machine_3",
        "Wool/silk at 20 degrees, no steam, spin 400",
        {"programme": "wool/silk", "spin": "400", "temperature": "20", "steam": "off"},
    ),
    (
        "washing_machine_3",
        "Set a delay of 2 hours for eco cottons at 40°C",
        {"programme": "eco cottons", "delay_start": "02:00:00", "temperature": "40"},
    ),
    (
        "rice_cooker_1",
        "Select brown rice with a softer texture and start cooking",
        {"texture": "softer", "menu": "brown", "status": "cooking"},
    ),
    ("rice_cooker_1", "Set the clock to 6:45 am", {"clock": "06:45:00"}),
    (
        "rice_cooker_3",
        "Steam for 20 minutes",
        {"menu": "steam", "cook_time": "00:20:00", "running": "on"},
    ),
    ("microwave_1", "Set the kitchen timer for 5 minutes", {"kitchen_timer": "00:05:00"}),
    ("microwave_1", "Defrost for 3 min 20 s", {"defrost_time": "00:03:20", "running": "on"}),
    (
        "microwave_1",
        "Cook for ninety seconds at power 6 and start",
        {"power_level": 6, "cook_time": "00:01:30", "running": "on"},
    ),
    (
        "microwave_2",
        "Set the clock to 18:30 and lock the child lock",
        {"clock": "18:30:00", "child_lock": "on"},
    ),
    (
        "microwave_2",
        "Cook for 4 minutes at low power, start",
        {"power_level": "low", "cook_time": "00:04:00", "running": "on"},
    ),
    (
        "kettle_2",
        "Warm water to 45 degrees and keep it warm for 1 hour",
        {"temperature": 45, "hold_time": "01:00:00", "heating": "on"},
    ),
    ("kettle_1", "Turn on keep warm", {"keep_warm": "on"}),
    (
        "kettle_3",
        "Set the amount to pot and pour slowly",
        {"pour_speed": "slow", "amount": "pot", "dispensing": "on"},
    ),
    (
        "bottle_washer_2",
        "Set the drying time to 60 minutes on dry only and lock it",
        {"programme": "dry", "dry_time": 60, "child_lock": "on"},
    ),
    ("bottle_washer_1", "Select auto mode and start it", {"mode": "auto", "running": "on"}),
    (
        "induction_cooker_1",
        "Turn on the cooker, hot pot at 1400 W",
        {"function": "hot pot", "heat_power": 1400, "power": "on"},
    ),
    (
        "induction_cooker_3",
        "Warm at 70 degrees for 2 hours",
        {"programme": "warm", "temperature": 70, "timer": "02:00:00"},
    ),
    (
        "air_fryer_2",
        "Vegetables preset at 190 °C for 18 minutes with shake reminder, start",
        {
            "preset": "vegetables",
            "temperature": 190,
            "cook_time": "00:18:00",
            "shake": "on",
            "running": "on",
        },
    ),
    (
        "air_fryer_1",
        "Air fry at 375°F for 15 min with high airflow",
        {"function": "air fry", "airflow": "high", "temperature": 375, "timer": "00:15:00"},
    ),
    (
        "dehumidifier_2",
        "Set the timer to 10 hours and the humidity to 55%",
        {"humidity": "55", "timer": 10},
    ),
    ("microwave_1", "Please set the time of day to 11:45", {"clock": "11:45:00"}),
]


@pytest.mark.parametrize(("appliance", "instruction", "goal"), CASES)
def test_phrasing(appliance: str, instruction: str, goal: dict[str, Any]) -> None:
    model = load_appliance(bundled_suite_dir() / appliance).model
    assert parse_instruction(model, instruction) == goal
