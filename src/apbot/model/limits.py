"""How large a model (and any YAML file apbot reads) may be: one place, documented and enforced.

Every limit leaves a wide margin over real appliances (the largest bundled model has 880 YAML
nodes, 23 actions and a 6,000-value cook time) and keeps ``apbot check`` within a few seconds
at the limit itself; ``docs/model-format.md`` ("Size limits") gives the measured times. Past a
limit the loader or the checker reports one clear problem instead of working for minutes.
"""

from __future__ import annotations

MAX_FILE_BYTES = 4_000_000
"""A model, panel, task or manual file larger than this is refused before it is read."""

MAX_YAML_NODES = 200_000
"""Nodes (every key, value and list item) one YAML document may have, aliases expanded."""

MAX_YAML_DEPTH = 50
"""Collections nested deeper than this are refused (bundled files nest at most seven levels)."""

MAX_VALUES = 100_000
"""Values of one domain: a variable, or one case of a programme-dependent one."""

MAX_MODEL_VALUES = 1_000_000
"""Values of all domains of a model together, every case counted."""

MAX_PARTS = 1_000
"""Controls, actions, variables, features and guards: at most this many of each."""

MAX_STEPS = 1_000
"""Steps of all features together (the simulator keeps a table of steps × actions)."""

SIZE_LIMITS_DOC = "docs/model-format.md, Size limits"
