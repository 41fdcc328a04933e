"""The one point-to-polyline projection: the plain-float loop gives, to the last bit, what the numpy
array form gives (the form it replaced for speed), on random paths with rotations in place."""

import math

import numpy as np
import pytest

from haven_sim.common.polyline import Polyline


def array_projection(line, x, y, lo, hi):
    """The closest point over segments lo..hi-1, all at once with numpy."""
    a, b = line.points[lo:hi], line.points[lo + 1 : hi + 1]
    d = b - a
    ln2 = np.einsum("ij,ij->i", d, d)
    t = np.clip(np.einsum("ij,ij->i", np.array([x, y]) - a, d) / np.where(ln2 > 0, ln2, 1.0), 0.0, 1.0)
    closest = a + d * t[:, None]
    dist = np.hypot(closest[:, 0] - x, closest[:, 1] - y)
    k = int(np.argmin(dist))
    return (
        float(dist[k]),
        lo + k,
        float(line.cumulative[lo + k] + t[k] * math.sqrt(ln2[k])),
        (float(closest[k, 0]), float(closest[k, 1])),
    )


@pytest.mark.parametrize("seed", range(5))
def test_projection_matches_the_array_form_bit_for_bit(seed):
    rng = np.random.default_rng(seed)
    pts = np.cumsum(rng.uniform(-0.4, 0.6, (40, 2)), axis=0)
    pts[10] = pts[9]  # a rotation in place: a zero-length segment
    pts = np.round(pts, 1) if seed % 2 else pts  # grid-aligned paths make exact ties between segments
    line = Polyline(pts)
    for x, y, s in zip(
        rng.uniform(-2, 12, 300), rng.uniform(-2, 12, 300), rng.uniform(0, line.length, 300), strict=True
    ):
        for s_from, s_to in ((0.0, math.inf), (s, s + 2.0)):
            p = line.project(float(x), float(y), s_from, s_to)
            lo = line._segment_at(s_from)
            hi = len(pts) - 1 if math.isinf(s_to) else max(lo + 1, min(len(pts) - 1, line._segment_at(s_to) + 1))
            assert (p.distance, p.segment, p.s, p.point) == array_projection(line, float(x), float(y), lo, hi)


def test_a_point_on_the_path_projects_onto_itself():
    line = Polyline([(0.0, 0.0), (2.0, 0.0), (2.0, 0.0), (2.0, 3.0)])
    p = line.project(2.0, 1.0)
    assert (p.distance, p.segment, p.s, p.point) == (0.0, 2, 3.0, (2.0, 1.0))
