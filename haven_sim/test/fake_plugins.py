"""A plugin's entry point as a test makes one (no package installed)."""

from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any


@dataclass
class Entry:
    """An entry point as importlib.metadata gives it (name, value, dist, load)."""

    name: str
    value: str
    package: str
    loads: Any = None

    @property
    def dist(self) -> Any:
        return SimpleNamespace(metadata={"Name": self.package})

    def load(self) -> Any:
        if isinstance(self.loads, Exception):
            raise self.loads
        return self.loads
