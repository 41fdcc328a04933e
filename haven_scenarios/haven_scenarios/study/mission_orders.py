"""Mission behaviours: how the robot picks its next target, the plugin kind `haven.missions`
(haven_sim/common/plugins.py). A scenario file names one (`robot: {order: nearest}`; the hallway's
route is always `fixed`).

A behaviour is a class whose objects answer two questions of the mission executive (study/mission.py):

    class Farthest:
        def arrange(self, targets, seed):            # the targets' order at the start (seeded)
            return list(targets)

        def pick(self, candidates, robot, path_length):   # the next target, of those left
            return max(candidates, key=lambda t: path_length((robot.x, robot.y), t.xy))

`candidates` are the targets left, in the arranged order (those a charged battery serves one way
only come last, by themselves); `path_length(a, b)` is the planned length on the map (math.inf when
unreachable). The executive keeps the battery rules, the charging and the thought text, whatever
the behaviour.
"""

from __future__ import annotations

import inspect
import random
from collections.abc import Callable, Sequence
from typing import Any, Protocol, cast

from haven_sim.common.geometry import Point, Pose2D

PathLength = Callable[[Point, Point], float]  # planned length, math.inf when unreachable


class MissionBehaviour(Protocol):
    def arrange(self, targets: Sequence[Any], seed: int) -> list[Any]: ...

    def pick(self, candidates: Sequence[Any], robot: Pose2D, path_length: PathLength) -> Any: ...


class Fixed:
    """The given order (the hallway's route)."""

    def arrange(self, targets: Sequence[Any], seed: int) -> list[Any]:
        return list(targets)

    def pick(self, candidates: Sequence[Any], robot: Pose2D, path_length: PathLength) -> Any:
        return candidates[0]


class Nearest(Fixed):
    """The nearest target by planned path length."""

    def pick(self, candidates: Sequence[Any], robot: Pose2D, path_length: PathLength) -> Any:
        return min(candidates, key=lambda t: path_length((robot.x, robot.y), t.xy))


class Random(Fixed):
    """A seeded order, uniform over the permutations (HAVEN's own shuffle was biased)."""

    def arrange(self, targets: Sequence[Any], seed: int) -> list[Any]:
        out = list(targets)
        random.Random(seed).shuffle(out)
        return out


MissionFactory = Callable[[], MissionBehaviour]  # a `haven.missions` plugin: the class


def accept_plugin(name: str, value: Any) -> MissionFactory:
    """A `haven.missions` plugin: a class whose objects arrange(targets, seed) and pick(candidates, robot,
    path_length)."""
    if not inspect.isclass(value) or not all(callable(getattr(value, m, None)) for m in ("arrange", "pick")):
        raise ValueError(
            "is not a mission behaviour: a class with arrange(targets, seed) and pick(candidates, robot, path_length)"
        )
    return cast(MissionFactory, value)
