"""A metric: how long anyone was within 2 m of the robot (a lab's own closeness measure)."""

from __future__ import annotations

from typing import Any

import numpy as np

NEAR_M = 2.0


def seconds_near(d: Any) -> dict[str, float]:
    """`d`: HAVEN's TrialData (haven_scenarios.record.metrics): the trial on one time grid."""
    near = np.zeros(len(d.tl.t), dtype=bool)
    for xy in d.tl.humans.values():
        near |= np.hypot(*(xy - d.tl.robot_xy).T) < NEAR_M
    return {"seconds_within_2m": round(float(d.tl.dt[near].sum()), 2)}


# The codebook's rows for its columns: (name, unit, definition, source).
seconds_near.columns = [  # type: ignore[attr-defined]
    (
        "seconds_within_2m",
        "s",
        f"time any person was within {NEAR_M:g} m of the robot, centre to centre",
        "haven_lab_example",
    )
]
