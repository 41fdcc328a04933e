import pytest

from haven_scenarios.record.rates import rate_stats


def test_rate_statistics_of_arrival_times():
    stats = rate_stats([0.0, 0.02, 0.04, 0.07, 0.08])
    assert stats.rate_hz == pytest.approx(50.0)
    assert (stats.min_s, stats.max_s, stats.window) == pytest.approx((0.01, 0.03, 5))
    assert "average rate: 50.000" in stats.line()
    assert rate_stats([1.0]) is None
