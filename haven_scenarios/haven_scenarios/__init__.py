"""HAVEN study scenarios, participants, sessions and the `haven` command."""

__version__ = "0.1.0"
