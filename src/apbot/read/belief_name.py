"""The name the reader gives the appliance it reads, shared by the reader that writes it and the
goal parser that must not take its words for the appliance's."""

from __future__ import annotations

UNNAMED = "read from the manual"
"""The name the reader gives the appliance it reads: it names nothing, and its words ("manual",
"read") are no words for the appliance (a MANUAL mode is not "the appliance")."""
