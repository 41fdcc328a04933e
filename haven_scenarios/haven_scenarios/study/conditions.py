"""A trial's condition (which AR cues it shows) and its seed, as a study, a scenario's command line
and a recording name them."""

from __future__ import annotations

import operator
from collections.abc import Sequence
from typing import Any

from haven_sim.robots.description import RobotDescription
from haven_viz.cues import CUES, DEFAULT_ON, CueToggles, Toggles, unfit, unknown_cue

SEED_MAX = 2**31 - 1  # a trial's seed: 0..this (a ROS integer parameter of the nodes, numpy's seed)


def check_seed(value: Any, where: str = "seed") -> int:
    """A trial's seed as an int (a numpy integer too); ValueError in one line for anything else."""
    try:
        seed = operator.index(value) if not isinstance(value, bool) else None
    except TypeError:
        seed = None
    if seed is None or not 0 <= seed <= SEED_MAX:
        raise ValueError(f"{where}: must be an integer 0..{SEED_MAX}, got {repr(value)[:40]}")
    return seed


def parse_condition(names: Sequence[str]) -> CueToggles:
    """`all`, `none`, or the cues to show (the others are off)."""
    if not names or list(names) == ["all"]:
        return Toggles()
    if list(names) == ["none"]:
        return Toggles.none()
    unknown = [n for n in names if n not in CUES]
    if unknown:
        raise ValueError(unknown_cue(unknown[0]))
    return Toggles(**{c: c in names for c in CUES})


def condition_name(t: CueToggles) -> str:
    on = t.names_on()
    return "all" if tuple(on) == DEFAULT_ON else ("none" if not on else "+".join(on))


def check_fit(toggles: CueToggles, robot: RobotDescription) -> None:
    """ValueError (one line) when the condition names a cue the robot cannot show."""
    why = unfit(toggles.names_on(), robot)
    if why is not None:
        raise ValueError(why)
