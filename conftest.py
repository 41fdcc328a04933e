"""Shared pytest setup for the three packages' tests: the test tiers, and the ROS test harness,
which lives beside the tests (haven_sim/test/ros_harness.py), not in an installed package.

The tiers (markers; `make test-unit` and the others select one):
- unit: everything not marked otherwise (given the marker here): in one process, without ROS 2
  installed, in seconds;
- integration: several parts together, through processes, sockets, whole batch trials, the ROS
  Python libraries in-process or the colcon build;
- ros: starts ROS 2 node processes;
- browser: drives headless Chromium.
Where rclpy cannot be imported, a test file that imports ROS at its top is not collected (one line
says how many), so the unit tier runs in a venv without ROS.
"""

import ast
import importlib.util
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent / "haven_sim" / "test"))

TIERS = ("integration", "ros", "browser")
ROS_AVAILABLE = importlib.util.find_spec("rclpy") is not None
_left_out: list[str] = []


def needs_ros(path: Path) -> bool:
    """Whether a test file imports ROS at its top: rclpy, message packages, the harness, our nodes."""
    for node in ast.parse(path.read_text(), str(path)).body:
        names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""] if isinstance(node, ast.ImportFrom) else []
        for name in names:
            top = name.partition(".")[0]
            if top in ("rclpy", "ros_harness") or top.endswith(("_msgs", "_srvs")) or ".nodes" in name:
                return True
    return False


def pytest_ignore_collect(collection_path: Path) -> bool | None:
    if not ROS_AVAILABLE and collection_path.suffix == ".py" and collection_path.name.startswith("test_") and needs_ros(collection_path):
        _left_out.append(collection_path.name)
        return True
    return None


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        if not any(item.get_closest_marker(t) for t in TIERS):
            item.add_marker(pytest.mark.unit)


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    if _left_out:
        terminalreporter.write_line(
            f"rclpy not installed: {len(_left_out)} test files that need ROS 2 not collected ({', '.join(sorted(_left_out))})"
        )


@pytest.fixture
def ros():
    """A ROS harness on a domain of its own; stops every process it started."""
    from ros_harness import harness

    yield from harness()
