import math

import pytest
from helpers import box_world, robot_with

from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Twist2D
from haven_sim.sim.battery import Battery, BatteryParams, PowerStatus
from haven_sim.sim.simulation import SimConfig, Simulation


def test_drains_per_metre_radian_and_second():
    b = Battery(BatteryParams(capacity_m=50.0, drain_per_rad=0.01, idle_drain_per_s=0.001))
    b.update(dt=1.0, distance_m=5.0, rotation_rad=-2.0, speed_mps=5.0, distance_to_base_m=10.0)
    assert b.level == pytest.approx(1.0 - 0.1 - 0.02 - 0.001)
    r = b.reading()
    assert r.status is PowerStatus.DISCHARGING
    assert r.range_m == pytest.approx(b.level * 50.0)
    assert r.voltage_v == pytest.approx(13.2 + b.level * 3.6)
    assert r.charge_ah == pytest.approx(b.level * 2.2)


def test_never_below_zero():
    b = Battery(BatteryParams(capacity_m=1.0))
    b.update(1.0, 5.0, 0.0, 5.0, 10.0)
    assert b.level == 0.0 and b.empty


def test_charges_only_on_base_and_nearly_stopped_until_full():
    b = Battery(BatteryParams(initial_level=0.5, charge_rate_per_s=0.1, base_radius_m=0.5))
    b.update(1.0, 0.0, 0.0, 0.0, distance_to_base_m=0.6)  # off the base
    assert b.level == 0.5 and b.reading().status is PowerStatus.DISCHARGING
    b.update(1.0, 0.01, 0.0, 0.3, distance_to_base_m=0.2)  # on the base but moving
    assert b.level < 0.5
    b.update(1.0, 0.0, 0.0, 0.0, distance_to_base_m=0.2)
    assert b.reading().status is PowerStatus.CHARGING
    for _ in range(10):
        b.update(1.0, 0.0, 0.0, 0.0, distance_to_base_m=0.2)
    assert b.level == 1.0 and b.reading().status is PowerStatus.FULL


@pytest.mark.parametrize(
    "bad, said",
    [
        (dict(capacity_m=0.0), "capacity_m: must be positive, got 0.0"),
        (dict(initial_level=1.5), r"initial_level: must be within 0\.\.1, got 1\.5"),
        (dict(charge_rate_per_s=-1.0), "charge_rate_per_s: must not be negative, got -1.0"),
    ],
)
def test_invalid_params_are_refused(bad, said):
    with pytest.raises(ValueError, match=said):
        Battery(BatteryParams(**bad))


def test_empty_battery_stops_the_robot_in_the_simulation():
    fast = robot_with(max_linear_accel_mps2=1e6, max_angular_accel_rps2=1e6)
    sim = Simulation(box_world(20.0), SimConfig(robot=fast, battery=BatteryParams(capacity_m=2.0)))
    for _ in range(300):
        sim.command_robot(Twist2D(0.5, 0, 0))
        sim.step()
    assert sim.battery.empty
    assert sim.robot_pose().x - 10.0 == pytest.approx(2.0, abs=0.05)
    assert sim.robot_twist().vx == pytest.approx(0.0, abs=1e-6)
    assert [e.kind for e in sim.pop_events()].count(EventKind.BATTERY_EMPTY) == 1


def test_robot_recharges_on_the_base_in_the_simulation():
    world = box_world(10.0, charging_base={"position": [5.0, 5.0], "radius": 0.5})
    sim = Simulation(world, SimConfig(battery=BatteryParams(initial_level=0.2, charge_rate_per_s=0.1)))
    sim.run(4.0)
    assert sim.battery.level == pytest.approx(0.6, abs=1e-6)
    assert math.isclose(sim.battery_reading().level, sim.battery.level)
