"""The shape the codebase keeps: small modules and functions (issue "One house"), and the pure core
importing nothing of ROS (the design contract's one architectural rule)."""

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SOURCES = sorted(p for p in ROOT.glob("haven_*/haven_*/**/*.py"))
ROS_IMPORTS = (
    "rclpy",
    "std_msgs",
    "geometry_msgs",
    "nav_msgs",
    "sensor_msgs",
    "visualization_msgs",
    "rosgraph_msgs",
    "std_srvs",
    "builtin_interfaces",
    "tf2_msgs",
    "nav2_msgs",
    "lifecycle_msgs",
    "rcl_interfaces",
)


def test_modules_stay_under_400_lines_and_functions_under_60():
    long_modules = [f"{p.relative_to(ROOT)}: {n}" for p in SOURCES if (n := len(p.read_text().splitlines())) > 400]
    long_functions = [
        f"{p.relative_to(ROOT)}:{node.lineno} {node.name}: {node.end_lineno - node.lineno + 1}"
        for p in SOURCES
        for node in ast.walk(ast.parse(p.read_text()))
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.end_lineno - node.lineno + 1 > 60
    ]
    assert long_modules == [] and long_functions == []


def test_the_core_imports_no_ros():
    leaks = []
    for p in SOURCES:
        if "nodes" in p.parts:
            continue
        for node in ast.walk(ast.parse(p.read_text())):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""] if isinstance(node, ast.ImportFrom) else []
            leaks += [f"{p.relative_to(ROOT)}: {n}" for n in names if n.split(".")[0] in ROS_IMPORTS]
    assert leaks == []
