"""The docs' Python examples run as tests (Sybil): each ```python block of a page, in order, in one
namespace per page, in a folder of its own. Hidden check blocks (`% invisible-code-block: python`,
a MyST comment) hold each plugin example to its kind's contract; an example that needs what a test
here cannot have (a ROS suite, a lab's own scenario file, a finished study) is marked
`% skip: next` where it stands. They run in the integration tier (conftest.py)."""

import pytest
from sybil import Sybil
from sybil.parsers.myst import PythonCodeBlockParser, SkipParser


@pytest.fixture
def in_tmp(tmp_path, monkeypatch):
    """Each page's examples run in an empty folder of their own (a picture they draw lands there)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


pytest_collect_file = Sybil(
    parsers=[PythonCodeBlockParser(), SkipParser()],
    patterns=["*.md"],
    excludes=["_build/*", "_generated/*"],
    fixtures=["in_tmp"],
).pytest()
