"""Reading with no LLM: a manual into an appliance model, an instruction into a goal.

>>> from apbot.read import read_manual
>>> text = "Press FAN to switch between HIGH and LOW. Press POWER to switch on or off."
>>> reading = read_manual(text, ["press_power", "press_fan"])
>>> reading.model.variables["fan"].values
['high', 'low']
"""

from apbot.read.errors import ReaderError
from apbot.read.reader import Reading, read_manual
from apbot.read.report import Note, Report

__all__ = ["Note", "ReaderError", "Reading", "Report", "read_manual"]
