"""pymunk world: the robot (its footprint from its robot file), circular humans and static walls.

Bodies are driven through joints (pymunk's "tank" pattern): a kinematic control body carries the
commanded velocity and a pivot joint plus a gear joint with bounded force and torque drag the real
body along. Walls therefore stop a body instead of letting it tunnel, which setting `body.velocity`
directly would allow.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import pymunk

from haven_sim.common.bodies import HUMAN_BODY, BodySpec
from haven_sim.common.events import EventKind
from haven_sim.common.geometry import FloatArray, Pose2D, Twist2D

ROBOT, HUMAN, WALL = 1, 2, 3
# The property setters themselves: pymunk's attribute-name guard on Body.__setattr__ costs more
# than the update in this per-step path.
_set_velocity: Callable[[pymunk.Body, tuple[float, float]], None] = vars(pymunk.Body)["velocity"].fset
_set_angular_velocity: Callable[[pymunk.Body, float], None] = vars(pymunk.Body)["angular_velocity"].fset


@dataclass(frozen=True)
class ContactEvent:
    """A robot contact starting or ending; `other` is 'wall' or 'human:<id>'."""

    kind: EventKind  # CONTACT_BEGIN | CONTACT_END
    other: str


class _DrivenBody:
    def __init__(self, space: pymunk.Space, spec: BodySpec, pose: Pose2D, collision_type: int) -> None:
        self.spec = spec
        if spec.polygon:
            self.body = pymunk.Body(spec.mass_kg, pymunk.moment_for_poly(spec.mass_kg, spec.polygon))
            self.shape: pymunk.Shape = pymunk.Poly(self.body, spec.polygon)
        else:
            self.body = pymunk.Body(spec.mass_kg, pymunk.moment_for_circle(spec.mass_kg, 0.0, spec.radius_m))
            self.shape = pymunk.Circle(self.body, spec.radius_m)
        self.shape.collision_type = collision_type
        self.shape.friction = 0.3
        self.control = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        self._dt = 0.0
        self._last_cmd: Twist2D | None = None
        self._last_heading = math.nan
        pivot = pymunk.PivotJoint(self.control, self.body, (0, 0), (0, 0))
        pivot.max_bias = 0.0
        pivot.max_force = spec.max_force_n
        gear = pymunk.GearJoint(self.control, self.body, 0.0, 1.0)
        gear.max_bias = 0.0
        gear.max_force = spec.max_torque_nm
        space.add(self.body, self.shape, self.control, pivot, gear)
        self.place(pose)

    def place(self, pose: Pose2D) -> None:
        self._last_cmd = None
        for b in (self.body, self.control):
            b.position = (pose.x, pose.y)
            b.angle = pose.yaw
            b.velocity = (0.0, 0.0)
            b.angular_velocity = 0.0

    def drive(self, cmd: Twist2D, dt: float) -> None:
        self._dt = dt
        # Chipmunk moves bodies with the velocity solved in the previous step, so this velocity is
        # integrated from angle + w*dt to angle + 2*w*dt: aim along the middle of that (the arc's chord).
        heading = self.body.angle + 1.5 * cmd.wz * dt
        if cmd == self._last_cmd and heading == self._last_heading:
            return  # the control body already moves exactly so
        self._last_cmd, self._last_heading = cmd, heading
        c, s = math.cos(heading), math.sin(heading)
        _set_velocity(self.control, (c * cmd.vx - s * cmd.vy, s * cmd.vx + c * cmd.vy))
        _set_angular_velocity(self.control, cmd.wz)

    def pose(self) -> Pose2D:
        x, y = self.body.position
        return Pose2D(x, y, self.body.angle)

    def body_twist(self) -> Twist2D:
        """Velocity in the body frame (relative to the heading it will be integrated about)."""
        body = self.body
        vx, vy = body.velocity
        w = body.angular_velocity
        heading = body.angle + 0.5 * w * self._dt
        c, s = math.cos(heading), math.sin(heading)
        return Twist2D(c * vx + s * vy, -s * vx + c * vy, w)


class Physics:
    def __init__(
        self, edges: FloatArray, robot_start: Pose2D, human_starts: dict[str, Pose2D], robot: BodySpec
    ) -> None:
        self.space = pymunk.Space()
        self.space.gravity = (0.0, 0.0)
        self.space.iterations = 10
        self._obstruction_shapes: dict[str, list[pymunk.Shape]] = {}
        self._add_edges(edges)
        self.robot = _DrivenBody(self.space, robot, robot_start, ROBOT)
        self.humans = {hid: _DrivenBody(self.space, HUMAN_BODY, p, HUMAN) for hid, p in human_starts.items()}
        self._human_of_shape = {id(h.shape): hid for hid, h in self.humans.items()}
        self._touching: dict[str, int] = {}
        self.events: list[ContactEvent] = []
        self.space.on_collision(ROBOT, WALL, begin=self._begin, separate=self._separate)
        self.space.on_collision(ROBOT, HUMAN, begin=self._begin, separate=self._separate)

    def _add_edges(self, edges: FloatArray, key: str | None = None) -> None:
        shapes: list[pymunk.Shape] = []
        for x0, y0, x1, y1 in edges:
            seg = pymunk.Segment(self.space.static_body, (x0, y0), (x1, y1), 0.0)
            seg.collision_type = WALL
            seg.friction = 0.3
            shapes.append(seg)
        self.space.add(*shapes)
        if key is not None:
            self._obstruction_shapes[key] = shapes

    def add_obstruction(self, key: str, edges: FloatArray) -> None:
        self._add_edges(edges, key)

    def remove_obstruction(self, key: str) -> None:
        shapes = self._obstruction_shapes.pop(key, [])
        if shapes:
            self.space.remove(*shapes)

    def _other(self, arbiter: pymunk.Arbiter) -> str:
        for shape in arbiter.shapes:
            if shape.collision_type == HUMAN:
                return f"human:{self._human_of_shape[id(shape)]}"
        return "wall"

    def _begin(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        other = self._other(arbiter)
        n = self._touching.get(other, 0)
        self._touching[other] = n + 1
        if n == 0:
            self.events.append(ContactEvent(EventKind.CONTACT_BEGIN, other))

    def _separate(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: Any) -> None:
        other = self._other(arbiter)
        n = self._touching.get(other, 0) - 1
        if n <= 0:
            self._touching.pop(other, None)
            if n == 0:
                self.events.append(ContactEvent(EventKind.CONTACT_END, other))
        else:
            self._touching[other] = n

    def in_contact(self) -> list[str]:
        return sorted(self._touching)

    def step(self, robot_cmd: Twist2D, human_cmds: dict[str, Twist2D], dt: float) -> None:
        self.robot.drive(robot_cmd, dt)
        for hid, body in self.humans.items():
            body.drive(human_cmds.get(hid, Twist2D()), dt)
        self.space.step(dt)

    def human_poses(self) -> dict[str, Pose2D]:
        return {hid: h.pose() for hid, h in self.humans.items()}
