"""The one exception the reader raises: input it cannot read at all (not text, far too long)."""


class ReaderError(ValueError):
    """The manual or the action list cannot be read; the message names the problem."""
