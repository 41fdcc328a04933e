from haven_scenarios.tools.keys import KeyMapper
from haven_sim.common.geometry import Twist2D


def test_held_keys_combine_and_release_after_the_auto_repeat_stops():
    k = KeyMapper(speed_mps=1.0, turn_rps=1.5, hold_s=0.35)
    assert k.command(0.0) == Twist2D()
    k.press("w", 0.0)
    k.press("q", 0.1)
    assert k.command(0.2) == Twist2D(1.0, 0.0, 1.5)
    k.press("w", 0.3)  # auto-repeat of w only
    assert k.command(0.5) == Twist2D(1.0, 0.0, 0.0)
    assert k.command(0.7) == Twist2D()
    k.press("a", 1.0)
    k.press("s", 1.0)
    assert k.command(1.1) == Twist2D(-1.0, 1.0, 0.0)
    k.press(" ", 1.2)
    assert k.command(1.2) == Twist2D()
