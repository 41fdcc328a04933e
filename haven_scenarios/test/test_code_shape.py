"""The shape the codebase keeps: short functions, measured in statements (issue "One house"; a module is one idea
and has no length cap), and the pure core importing nothing of ROS (the design contract's one architectural rule)."""

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


MAX_STATEMENTS = 50


def statements(function: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    """The statements in a function's body, nested ones included (those of an inner function or class too), its
    docstring not: a count that line length and layout cannot change."""
    body = function.body[1:] if ast.get_docstring(function) is not None else function.body
    return sum(isinstance(node, ast.stmt) for top in body for node in ast.walk(top))


def test_functions_stay_within_50_statements():
    long_functions = [
        f"{p.relative_to(ROOT)}:{node.lineno} {node.name}: {n}"
        for p in SOURCES
        for node in ast.walk(ast.parse(p.read_text()))
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and (n := statements(node)) > MAX_STATEMENTS
    ]
    assert long_functions == []


def test_the_core_imports_no_ros():
    leaks = []
    for p in SOURCES:
        if "nodes" in p.parts:
            continue
        for node in ast.walk(ast.parse(p.read_text())):
            names = (
                [a.name for a in node.names]
                if isinstance(node, ast.Import)
                else [node.module or ""]
                if isinstance(node, ast.ImportFrom)
                else []
            )
            leaks += [f"{p.relative_to(ROOT)}: {n}" for n in names if n.split(".")[0] in ROS_IMPORTS]
    assert leaks == []
