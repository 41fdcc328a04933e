"""Sphinx configuration of HAVEN for ROS 2's documentation site (built by `make docs`, and by
`make test` with warnings as errors). Pages are MyST Markdown; the API reference comes from the
docstrings (autodoc); the metric codebook from the metric table in the code."""

from __future__ import annotations

import importlib.metadata
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
for package in ("haven_sim", "haven_viz", "haven_scenarios"):
    sys.path.insert(0, str(ROOT / package))

project = "HAVEN for ROS 2"
author = "HAVEN maintainers"
copyright = "2026, HAVEN maintainers (Apache-2.0)"
release = importlib.metadata.version("haven_scenarios")  # (package.xml, through setup.py)

extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx.ext.viewcode"]
myst_enable_extensions = ["colon_fence", "deflist"]
myst_heading_anchors = 3
source_suffix = {".md": "markdown"}
exclude_patterns = ["_build", "_generated/*.part.md"]
html_theme = "furo"
html_title = "HAVEN for ROS 2"
autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_default_options = {"undoc-members": False, "show-inheritance": True}
nitpicky = False
default_role = "literal"  # `name` in a docstring is code, as in the Markdown pages


def _generated(_app: object) -> None:
    """Pages made from the code (one source): the metric codebook and the list of commands."""
    import argparse

    from haven_scenarios.record.metric_table import markdown
    from haven_scenarios.tools.cli import build_parser

    out = Path(__file__).parent / "_generated"
    out.mkdir(exist_ok=True)
    # (HAVEN's own: not whatever this venv has installed)
    (out / "metric_table.part.md").write_text(markdown(plugins=False) + "\n")
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    helps = {c.dest: c.help for c in sub._choices_actions}
    rows = ["| command | what it does |", "|---|---|"] + [
        f"| `haven {name}` | {helps.get(name, '')} |" for name in sub.choices
    ]
    (out / "commands.part.md").write_text("\n".join(rows) + "\n\nEvery command's options: `haven COMMAND --help`.\n")
    (out / "plugin_kinds.part.md").write_text(_plugin_kinds())


def _plugin_kinds() -> str:
    """Each plugin kind with HAVEN's own items, from the registries (a lab's name must not be one of
    these); plugins from other packages this venv has installed are left out."""
    from haven_sim.common import plugins

    ours = {"haven_sim", "haven_viz", "haven_scenarios", "haven-sim", "haven-viz", "haven-scenarios"}
    rows = ["| kind (entry point group) | HAVEN's own (names a lab's plugin cannot take) |", "|---|---|"]
    for reg in plugins.every():
        names = [f"`{p.name}`" for p in reg if p.package in ours]
        rows.append(f"| `haven.{reg.kind}` | {', '.join(names)} |")
    return "\n".join(rows) + "\n"


def setup(app: object) -> None:
    app.connect("builder-inited", _generated)  # type: ignore[attr-defined]
