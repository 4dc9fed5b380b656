"""Reading: manual text into a model, an instruction into a goal (offline parsers)."""
