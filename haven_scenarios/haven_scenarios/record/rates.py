"""Message rate statistics for `haven hz` (what `ros2 topic hz` prints), on plain arrival times."""

from __future__ import annotations

import itertools
import statistics
from collections.abc import Sequence
from dataclasses import dataclass


@dataclass(frozen=True)
class RateStats:
    rate_hz: float
    min_s: float
    max_s: float
    std_s: float
    window: int

    def line(self) -> str:
        return (
            f"average rate: {self.rate_hz:.3f}\n"
            f"\tmin: {self.min_s:.3f}s max: {self.max_s:.3f}s std dev: {self.std_s:.5f}s window: {self.window}"
        )


def rate_stats(arrivals: Sequence[float]) -> RateStats | None:
    """Statistics of the gaps between consecutive arrival times (seconds); None below 2 messages."""
    if len(arrivals) < 2:
        return None
    gaps = [b - a for a, b in itertools.pairwise(arrivals)]
    mean = sum(gaps) / len(gaps)
    return RateStats(
        1.0 / mean if mean > 0 else float("inf"), min(gaps), max(gaps), statistics.pstdev(gaps), len(arrivals)
    )
