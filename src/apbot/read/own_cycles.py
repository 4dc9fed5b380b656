"""A key's own list stated in a sentence naming that key alone ("To change the air temperature,
press DRY again while the dryer is running: LOW -> MID -> HIGH -> LOW -> ...").

roles.py drops a key's list when another key's list holds every one of its values (a menu's
names read near COOK TIME are FUNCTION's). Panels with several level keys break that: the water
and seat keys step OFF -> LOW -> MID -> HIGH while the dryer key steps LOW -> MID -> HIGH, a
subset, and losing it left the dryer key an on/off guess. A list read in a sentence that names
this key and no other key, stepping round back to its first value, was stated for this key,
whatever the other lists hold ("For PORRIDGE, STEAM and CAKE you can choose the cooking time"
names menus near COOK TIME, no cycle: still dropped).
"""

from __future__ import annotations

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.shapes import Evidence, comes_round


def stated_for_key(b: Builder, key: ActionInfo, ev: Evidence) -> bool:
    """Whether the key's list was read from a unit naming the key and no other control, as a
    cycle coming round to its first value."""
    at = ev.values_at
    if at is None or not ev.values or not comes_round(ev.values, b.manual.units[at].text):
        return False
    own = any(at in b.labels[c].mentions for c in key.controls if c in b.labels)
    others = any(at in lab.mentions for t, lab in b.labels.items() if t not in key.controls)
    return own and not others
