"""Shared pytest setup for the three packages' tests: the test tiers, and the ROS test harness,
which lives beside the tests (haven_sim/test/ros_harness.py), not in an installed package.

The tiers (markers; `make test-unit` and the others select one):
- unit: everything not marked otherwise (given the marker here): in one process, without ROS 2
  installed, in seconds;
- integration: several parts together, through processes, sockets, whole batch trials, the ROS
  Python libraries in-process or the colcon build; and Monte Carlo checks of a statistic (hundreds
  of model fits);
- ros: starts ROS 2 node processes;
- browser: drives headless Chromium.
Where rclpy cannot be imported, a test file that imports ROS at its top is not collected (one line
says how many), so the unit tier runs in a venv without ROS.

The docs' examples run as tests too (Sybil): each ```python block of a page, in order, in one
namespace per page, in a folder of its own; and each ```bash block's commands (doc_commands.py).
Hidden check blocks (`% invisible-code-block: python`, a MyST comment) hold each plugin example to
its kind's contract; an example that needs what a test here cannot have (a ROS suite, a lab's own
scenario file, a finished study) is marked `% skip: next` where it stands. They are integration
tests.
"""

import ast
import importlib.util
import os
import shutil
import sys
from pathlib import Path

import pytest
from sybil import Sybil
from sybil.parsers.myst import PythonCodeBlockParser, SkipParser

sys.path.insert(0, str(Path(__file__).resolve().parent / "haven_sim" / "test"))
sys.path.insert(0, str(Path(__file__).resolve().parent / "haven_scenarios" / "test"))
from doc_commands import page_folder, parse_files, parse_shell

TIERS = ("integration", "ros", "browser")
ROS_AVAILABLE = importlib.util.find_spec("rclpy") is not None
_left_out: list[str] = []


def needs_ros(path: Path) -> bool:
    """Whether a test file imports ROS at its top: rclpy, message packages, the harness, our nodes,
    or another test file beside it that does."""
    for node in ast.parse(path.read_text(), str(path)).body:
        names = (
            [a.name for a in node.names]
            if isinstance(node, ast.Import)
            else [node.module or ""]
            if isinstance(node, ast.ImportFrom)
            else []
        )
        for name in names:
            top = name.partition(".")[0]
            if top in ("rclpy", "ros_harness") or top.endswith(("_msgs", "_srvs")) or ".nodes" in name:
                return True
            sibling = path.with_name(f"{top}.py")
            if top.startswith("test_") and sibling != path and sibling.is_file() and needs_ros(sibling):
                return True
    return False


def pytest_ignore_collect(collection_path: Path) -> bool | None:
    if (
        not ROS_AVAILABLE
        and collection_path.suffix == ".py"
        and collection_path.name.startswith("test_")
        and needs_ros(collection_path)
    ):
        _left_out.append(collection_path.name)
        return True
    return None


@pytest.fixture
def in_tmp(request, tmp_path_factory, monkeypatch):  # type: ignore[no-untyped-def]
    """A docs page's examples run in order in a folder of the page's own, empty at first (a picture
    they draw, a file a command writes, lands there for the next)."""
    folder = page_folder(request.node.example, tmp_path_factory)
    monkeypatch.chdir(folder)
    return folder


pytest_collect_file = Sybil(
    parsers=[PythonCodeBlockParser(), SkipParser(), parse_shell, parse_files],
    path=str(Path(__file__).resolve().parent / "docs"),
    patterns=["*.md"],
    excludes=["_build/*", "_generated/*"],
    fixtures=["in_tmp"],
).pytest()


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The tiers' marks (the docs' examples: integration and docs); the tests that start ROS or a
    browser first (the longest: short ones then fill the workers' ends)."""
    for item in items:
        if item.path.suffix == ".md":  # the docs' examples: they run trials
            item.add_marker(pytest.mark.integration)
            item.add_marker(pytest.mark.docs)
        if not any(item.get_closest_marker(t) for t in TIERS):
            item.add_marker(pytest.mark.unit)
    items.sort(key=lambda item: not (item.get_closest_marker("ros") or item.get_closest_marker("browser")))


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    if _left_out:
        terminalreporter.write_line(
            f"rclpy not installed: {len(_left_out)} test files that "
            f"need ROS 2 not collected ({', '.join(sorted(_left_out))})"
        )


@pytest.fixture
def ros():
    """A ROS harness on a domain of its own; stops every process it started."""
    from ros_harness import harness

    yield from harness()


CHROMIUM_ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"]  # software WebGL


def chromium_path() -> str | None:
    found = os.environ.get("HAVEN_CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")
    return found if found and os.path.exists(found) else None


@pytest.fixture(scope="module")
def chromium():  # type: ignore[no-untyped-def]
    """Headless Chromium, launched once for a test module; skipped, with one line, where no
    Chromium or playwright can be had."""
    path = chromium_path()
    if path is None:
        pytest.skip(
            "no Chromium here (Debian's chromium package; "
            "scripts/setup.sh installs it when run as root): browser tests skipped"
        )
    playwright = pytest.importorskip("playwright.sync_api", reason="playwright is not installed: browser tests skipped")
    with playwright.sync_playwright() as p:
        b = p.chromium.launch(executable_path=path, args=CHROMIUM_ARGS)
        yield b
        b.close()


@pytest.fixture
def browser(chromium):  # type: ignore[no-untyped-def]
    """The module's Chromium for one test; every page and context the test opened is closed when it
    ends (a page left open goes on rendering, in software, through the module's later tests)."""
    patient = _PatientBrowser(chromium)
    yield patient
    for opened in reversed(patient.opened):
        opened.close()


ACTION_TIMEOUT_MS = 90_000  # a limit, not a wait: on a loaded 2-core machine a page's button took over 30 s to settle


class _PatientBrowser:
    """The browser, with every page's actions (a click, a fill) given as long as the tests' own
    waits for page state, instead of Playwright's 30 s default; it keeps what it opened."""

    def __init__(self, browser):  # type: ignore[no-untyped-def]
        self._browser = browser
        self.opened: list = []  # type: ignore[type-arg]

    def new_page(self, **options):  # type: ignore[no-untyped-def]
        page = _explained(self._browser.new_page(**options))
        page.set_default_timeout(ACTION_TIMEOUT_MS)
        self.opened.append(page)
        return page

    def new_context(self, **options):  # type: ignore[no-untyped-def]
        context = self._browser.new_context(**options)
        context.set_default_timeout(ACTION_TIMEOUT_MS)
        opens = context.new_page
        context.new_page = lambda: _explained(opens())
        self.opened.append(context)
        return context

    def __getattr__(self, name):  # type: ignore[no-untyped-def]
        return getattr(self._browser, name)


# What a page that never got where a test waited for shows of itself: its havenState, short.
PAGE_STATE = """() => JSON.stringify(window.havenState ?? null, (key, value) =>
    Array.isArray(value) && value.length > 8 ? `[${value.length} items]` : value).slice(0, 3000)"""


def _explained(page):  # type: ignore[no-untyped-def]
    """A page whose `wait_for_function` that times out says what the page held instead (a test that
    failed on a busy machine can then be read from its log)."""
    wait = page.wait_for_function

    def explained(expression, *args, **kwargs):  # type: ignore[no-untyped-def]
        try:
            return wait(expression, *args, **kwargs)
        except Exception as e:
            if type(e).__name__ != "TimeoutError":
                raise
            try:
                state = page.evaluate(PAGE_STATE)
            except Exception as unread:
                state = f"(unreadable: {type(unread).__name__})"
            raise AssertionError(f"the page never held {expression!r}; its havenState: {state}") from e

    page.wait_for_function = explained
    return page
