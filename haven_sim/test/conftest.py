import pytest


@pytest.fixture
def ros():
    """A ROS harness on a domain of its own; stops every process it started."""
    from haven_sim.nodes.testing import RosHarness

    harness = RosHarness()
    try:
        yield harness
    finally:
        harness.close()
