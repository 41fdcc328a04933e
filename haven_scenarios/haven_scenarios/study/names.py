"""The rule for the names that become part of a folder's name (participant ids, scenario and study
names): never a path; and the folder a study's sessions go to."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Protocol

NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,63}")  # participant ids and scenario names: part of a folder name
NAME_RULE = "1 to 64 ASCII letters, digits, '_', '.' or '-', starting with a letter or digit, without '..'"


def check_name(value: object, what: str) -> str:
    """`value` if it is a safe name for a session folder (NAME, no '..': never a path); else
    ValueError naming `what` (the option or the key it came from), in one line."""
    if isinstance(value, str) and NAME.fullmatch(value) and ".." not in value:
        return value
    shown = repr(value) if len(repr(value)) <= 40 else repr(value)[:37] + "..."
    raise ValueError(f"{what}: must be {NAME_RULE}, got {shown}")


class Named(Protocol):
    @property
    def name(self) -> str: ...


def study_dir(folder: Path | None, study: Named) -> Path:
    """The study's folder: `folder` if given, else studies/<name> here."""
    return folder if folder is not None else Path("studies") / study.name
