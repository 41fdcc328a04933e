"""Shared pytest setup for the three packages' tests: the ROS test harness lives beside the tests
(haven_sim/test/ros_harness.py), not in an installed package."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent / "haven_sim" / "test"))


@pytest.fixture
def ros():
    """A ROS harness on a domain of its own; stops every process it started. (rclpy is imported
    only here, so the core tests also run where ROS is not installed.)"""
    from ros_harness import harness

    yield from harness()
