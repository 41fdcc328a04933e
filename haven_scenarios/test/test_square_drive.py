"""The demo's square driver, closed-loop on the simulator core (no ROS)."""

import pytest

from haven_scenarios.teleop.square_drive import SquareDriver
from haven_sim.sim.simulation import Simulation
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world


def test_square_returns_to_start_without_contact():
    sim = Simulation(load_world(packaged_world("small_test")))
    start = sim.robot_pose()
    driver = SquareDriver(side_m=1.5, laps=1)
    for _ in range(int(60 / sim.config.step_s)):
        if driver.done:
            break
        if round(sim.time / sim.config.step_s) % 2 == 0:  # a 25 Hz controller
            sim.command_robot(driver.command(sim.robot_pose()))
        sim.step()
    assert driver.done
    end = sim.robot_pose()
    assert end.distance_to(start) < 0.1
    assert driver.distance_m == pytest.approx(6.0, abs=0.2)
    assert not [e for e in sim.pop_events() if e.type == "contact_begin"]


def test_bad_square_is_refused():
    with pytest.raises(ValueError):
        SquareDriver(side_m=0)
