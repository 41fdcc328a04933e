"""Message types the recording library does not know, taken from the installed interface packages.

rosbags ships the definitions of ROS 2 Jazzy's common packages; a topic of any other type (a lab's
own message, nav2_msgs, geographic_msgs, or one newer than its store such as nav_msgs/msg/Goals)
is recorded all the same when its package is installed here: its `.msg` file (and those of the
types it uses) are read from the package's share folder, in the prefixes the ament index searches,
and registered with the typestore, which writes the definition into the bag's schema. A type whose
package is not installed cannot be read here at all: `why_not` says so."""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

from rosbags.typesys import get_types_from_msg
from rosbags.typesys.store import Typestore


def _used(field: Any) -> list[str]:
    """The message types a field's rosbags descriptor names (nested in sequences and arrays)."""
    _kind, detail = field
    if isinstance(detail, str):
        return [detail] if "/" in detail else []
    if isinstance(detail, tuple) and detail and isinstance(detail[0], tuple):
        return _used(detail[0])
    return []


def prefixes() -> list[Path]:
    """Where interface packages are installed: the sourced workspaces (AMENT_PREFIX_PATH, as the
    ament index searches them) and this Python environment (where the ROS wheels put theirs)."""
    listed = [Path(p) for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    return [*listed, Path(sys.prefix)]


def definition_file(msgtype: str) -> Path:
    """The installed `.msg` definition of `pkg/msg/Name`; LookupError (one line) if there is none."""
    package, kind, name = msgtype.split("/")
    for prefix in prefixes():
        if (prefix / "share" / package).is_dir():
            path = prefix / "share" / package / kind / f"{name}.msg"
            if not path.is_file():
                raise LookupError(f"{package} has no {kind}/{name}.msg")
            return path
    raise LookupError(f"package {package} is not installed here")


def why_not(typestore: Typestore, msgtype: str) -> str | None:
    """Register `msgtype` and what it uses from the installed packages: None once the typestore
    knows it, else why it cannot (one line)."""
    if msgtype in typestore.types:
        return None
    if msgtype.count("/") != 2:
        return f"{msgtype!r} is not a message type name"
    found: dict[str, Any] = {}
    todo = [msgtype]
    while todo:
        name = todo.pop()
        if name in typestore.types or name in found:
            continue
        try:
            types = get_types_from_msg(definition_file(name).read_text(), name)
        except (LookupError, OSError, ValueError) as e:  # (rosbags' parse errors are ValueErrors)
            return f"{name}: {e}"
        found.update(types)
        todo += [t for _, (_, fields) in types.items() for _, field in fields for t in _used(field)]
    typestore.register(found)
    return None
