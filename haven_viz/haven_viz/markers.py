"""Markers as plain data, and the diff that keeps publishing incremental.

A `MarkerSpec` mirrors what visualization_msgs/Marker needs (namespace, id, type, pose, scale,
colour, text, points) without depending on ROS; `haven_viz.nodes.conversions` makes the message.
`MarkerDiff` remembers what a viewer was last sent, so each cycle only new or changed markers go
out, plus an explicit DELETE for every marker that disappeared (no reliance on lifetimes, which
viewers render differently). A full refresh re-sends every current marker and a DELETE for every
marker ever sent that is gone, so a viewer that missed a message (or joined late) is repaired.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum

Color = tuple[float, float, float, float]
Point3 = tuple[float, float, float]


class Shape(Enum):
    """The visualization_msgs/Marker type constants."""

    ARROW = 0
    CUBE = 1
    SPHERE = 2
    CYLINDER = 3
    LINE_STRIP = 4
    LINE_LIST = 5
    CUBE_LIST = 6
    SPHERE_LIST = 7
    POINTS = 8
    TEXT_VIEW_FACING = 9
    MESH_RESOURCE = 10
    TRIANGLE_LIST = 11


@dataclass(frozen=True)
class MarkerSpec:
    ns: str
    id: int
    shape: Shape
    position: Point3 = (0.0, 0.0, 0.0)
    yaw: float = 0.0
    scale: Point3 = (1.0, 1.0, 1.0)
    color: Color = (1.0, 1.0, 1.0, 1.0)
    text: str = ""
    points: tuple[Point3, ...] = field(default=())

    @property
    def key(self) -> tuple[str, int]:
        return (self.ns, self.id)

    def rounded(self) -> MarkerSpec:
        """Positions to the millimetre and angles to the milliradian: changes smaller than that are
        not worth a message."""
        return MarkerSpec(
            self.ns,
            self.id,
            self.shape,
            tuple(round(v, 3) for v in self.position),  # type: ignore[arg-type]
            round(self.yaw, 3),
            tuple(round(v, 3) for v in self.scale),  # type: ignore[arg-type]
            tuple(round(v, 3) for v in self.color),  # type: ignore[arg-type]
            self.text,
            tuple(tuple(round(v, 3) for v in p) for p in self.points),  # type: ignore[misc]
        )


@dataclass(frozen=True)
class Update:
    """What to send: markers to add or modify, and the (ns, id) of markers to delete."""

    upsert: list[MarkerSpec]
    delete: list[tuple[str, int]]

    def __bool__(self) -> bool:
        return bool(self.upsert or self.delete)


class MarkerDiff:
    def __init__(self) -> None:
        self.sent: dict[tuple[str, int], MarkerSpec] = {}
        self._ever: set[tuple[str, int]] = set()  # every key ever sent (bounded by the ids in use)

    def update(self, markers: list[MarkerSpec], resend_all: bool = False) -> Update:
        """The changes since the last update; with `resend_all`, every current marker and a DELETE
        for every marker ever sent that is not current."""
        current = {m.key: m.rounded() for m in markers}
        upsert = [m for k, m in current.items() if resend_all or self.sent.get(k) != m]
        gone = self._ever if resend_all else self.sent.keys()
        delete = sorted(k for k in gone if k not in current)
        self._ever.update(current)
        self.sent = current
        return Update(upsert, delete)
