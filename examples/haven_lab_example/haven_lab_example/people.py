"""A participant in a hurry: walks a third faster than asked, and otherwise as HAVEN's
`Walker`, which walks its task round walls and people by the social-force model."""

from __future__ import annotations

from collections.abc import Sequence

from haven_scenarios.study.participants import Stop, Walker
from haven_scenarios.study.person import PersonParams
from haven_sim.nav.planner import Planner

HURRY = 4.0 / 3.0  # a third faster than the scenario's walking speed


class Hurried(Walker):
    def __init__(
        self,
        human_id: str,
        stops: Sequence[Stop],
        planner: Planner,
        speed_mps: float = 1.0,
        seed: int = 0,
        params: PersonParams | None = None,
    ) -> None:
        super().__init__(human_id, stops, planner, speed_mps * HURRY, seed, params)
