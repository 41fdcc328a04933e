"""A simulated participant's perception and walking parameters, with the literature they come from.

`PersonParams` is what a scenario file sets per person (`humans: - {id: h1, params: {reaction_s: 1.0}}`)
and what a sweep varies (`dataclasses.replace(task.params, reaction_s=0.8)`): every field is a number.

Defaults and their sources:
  * `fov_deg` 110: the horizontal field in which a walker notices things without turning the head.
    The binocular field is about 120 deg of the ~200 deg total (Strasburger, Rentschler & Juttner
    2011, J. Vision 11(5):13), and HAVEN's participants saw the cues through a VR headset, whose field
    is about 100-110 deg.
  * `view_m` 8: cues and the robot are noticed within Hall's (1966) public distance (3.6-7.6 m); a
    0.2 m path marker subtends under 1.5 deg beyond it.
  * `reaction_s` 1.0, seeded +-`reaction_spread`: the perception-response time to a moving hazard
    (Green 2000, "How long does it take to stop?": about 0.7 s when expected, 1.25-1.5 s when not).
  * walking speed: the scenario's `speed_mps` (comfortable gait 1.3-1.4 m/s outdoors, Bohannon 1997;
    about 1.4 m/s over ground, Mohler et al. 2007; slower indoors with a task) varied by a
    seeded +-`speed_spread`.
  * `pass_gap_m` 0.5: the gap a person keeps between their body and the robot's shown path when
    passing; Pacchierotti, Christensen & Jensfelt (2006) found 0.4 m lateral distance the least
    subjects accepted in a corridor, more preferred.
  * `anticipate_m` 6: how far ahead along their way a shown path makes a person move aside (an
    oncoming pedestrian is avoided from about 4-8 m, the social-to-public distance of Hall 1966).
  * `hesitate_m` 3.6 and `hesitate_factor` 0.5: a robot closing in within Hall's social distance whose
    intent the person cannot read makes them slow to about half speed until it shows its side (walkers
    facing a crossing robot adapt by slowing, Vassallo et al. 2017, Gait & Posture 51; illegible robot
    motion lowers perceived safety, Lichtenthaler, Lorenz & Kirsch 2012).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

HALL_SOCIAL_M = 3.6  # Hall (1966): social distance ends here (the metrics' social zone, too)


@dataclass(frozen=True)
class PersonParams:
    fov_deg: float = 110.0
    view_m: float = 8.0
    reaction_s: float = 1.0
    reaction_spread: float = 0.3
    speed_spread: float = 0.15
    pass_gap_m: float = 0.5
    anticipate_m: float = 6.0
    hesitate_m: float = HALL_SOCIAL_M
    hesitate_factor: float = 0.5

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                raise ValueError(f"{f.name} must be a finite number, got {value!r}")
        if not 0 < self.fov_deg <= 360:
            raise ValueError(f"fov_deg must be within (0, 360], got {self.fov_deg:g}")
        for name in ("view_m", "anticipate_m", "hesitate_m"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name} must be positive, got {getattr(self, name):g}")
        for name in ("reaction_s", "pass_gap_m"):
            if getattr(self, name) < 0:
                raise ValueError(f"{name} must not be negative, got {getattr(self, name):g}")
        for name in ("reaction_spread", "speed_spread"):
            if not 0 <= getattr(self, name) < 1:
                raise ValueError(f"{name} must be within [0, 1), got {getattr(self, name):g}")
        if not 0 < self.hesitate_factor <= 1:
            raise ValueError(f"hesitate_factor must be within (0, 1], got {self.hesitate_factor:g}")
