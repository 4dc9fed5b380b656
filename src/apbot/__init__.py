"""apbot: operate home appliances you have never seen by reading their user manuals."""

__version__ = "0.1.0"
