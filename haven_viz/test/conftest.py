import pytest


@pytest.fixture
def ros():
    """A ROS harness on a domain of its own; stops every process it started. (rclpy is imported
    only here, so the core tests also run where ROS is not installed.)"""
    from haven_sim.nodes.testing import harness

    yield from harness()
