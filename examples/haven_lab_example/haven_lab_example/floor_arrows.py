"""A cue: arrows projected on the floor ahead of the robot, pointing the way it will go.

Projected floor arrows are one of the intent cues HRI studies compare with a projected path line:
Han, Parrillo, Wilkinson, Yanco and Williams, "Projecting Robot Navigation Paths: Hardware and
Software for Projected AR", HRI 2022 (arrows and lines projected ahead of a mobile robot), and
Shrestha, Onchi, Xu and Li, "Exploring the Use of Light and Display Indicators for Communicating
Directional Intent", AIM 2018. The spacing and size here are this example's choice, not theirs.

What it shows goes on /haven/cue_state under `floor_arrows` (the number of arrows down), its time
on show is the metric `floor_arrows_shown_s`, and the simulated participants read its arrows as the
robot's way when they can see them (line of sight, field of view), as they read the projected path.
"""

from __future__ import annotations

import math

from haven_viz.builtin_cues import SCHEMES, CueParams
from haven_viz.cue_kind import CueContext, Shown
from haven_viz.markers import MarkerSpec, Shape

AHEAD_M = (0.6, 1.2, 1.8)  # where the arrows lie, along the path ahead of the robot
ARROW_SIZE = (0.35, 0.15, 0.02)  # length, width, thickness (m): flat on the floor


class FloorArrows:
    key, hidden, exposure, rank = "floor_arrows", 0, "floor_arrows_shown_s", 10

    def __init__(self, params: CueParams) -> None:
        self.params = params

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        ahead = ctx.path.ahead(AHEAD_M)
        if not ahead:
            return None
        color = SCHEMES[self.params.scheme]
        half = ARROW_SIZE[0] / 2.0  # (an arrow marker starts at its position: centred on the point)
        specs = [
            MarkerSpec(
                "floor_arrows",
                i,
                Shape.ARROW,
                (x - half * math.cos(h), y - half * math.sin(h), 0.01),
                h,
                ARROW_SIZE,
                color,
            )
            for i, (x, y, h) in enumerate(ahead)
        ]
        return Shown(len(ahead), specs if markers else [], tuple((x, y) for x, y, _ in ahead), on_robot=False)
