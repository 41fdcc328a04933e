"""HAVEN study scenarios, participants, sessions and the `haven` command."""

from importlib.metadata import version as _version

# (from package.xml, through setup.py; the rest of the metadata in pyproject.toml)
__version__ = _version("haven_scenarios")
