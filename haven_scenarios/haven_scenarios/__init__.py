"""HAVEN study scenarios, participants, sessions and the `haven` command."""

from importlib.metadata import version as _version

__version__ = _version("haven_scenarios")  # (from package.xml, through setup.py; the rest of the metadata in pyproject.toml)
