"""Image mode: rendered panels, grounding action names on a photo, reading the display."""
