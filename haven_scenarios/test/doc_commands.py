"""The docs' shell examples as tests (Sybil, conftest.py): every ```bash block of every page, one
command line at a time, in the page's own folder, in order.

Each command is checked as far as it can be here:
- `haven ...` is parsed by the command's own parser (an option renamed or a value it refuses fails
  the page), then run, when it ends on its own and needs nothing beyond this machine (`RUNS`);
  a sweep runs with its seeds cut to the first (`one_seed`: every scenario, grid cell and robot of
  it still loads and runs a trial). What starts a ROS suite, a server or a wait for a person
  (`run`, `serve`, `edit`, `sim`, `teleop`, ...), and what reaches another machine (`--cluster`), is
  parsed only;
- `pip install -e DIR` installs DIR into the page's own folder (`uv pip install --target`, HAVEN's
  environment untouched), and the page's commands after it run with it (as processes of their own,
  so the plugin registries read it); `pytest DIR` runs DIR's tests so; `python FILE` (a node started
  in the background) needs FILE to exist; `make TARGET` needs the target in the Makefile;
- anything else fails: a new kind of command needs a rule here.

`% file: NAME` (a MyST comment) before a ```yaml or ```toml block writes that block into the page's
folder as NAME, so the commands after it read the file the page shows.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shlex
import subprocess
import sys
from collections.abc import Iterable
from pathlib import Path

import pytest
from sybil import Document, Example, Region

ROOT = Path(__file__).resolve().parents[2]
SHELL = re.compile(r"^```(?:bash|sh|shell)\n(.*?)^```", re.M | re.S)
FILE = re.compile(r"^% file: (\S+)\n```(?:yaml|toml|text)\n(.*?)^```", re.M | re.S)
PROMPT = re.compile(r"^[\w.-]+\$ ")  # `lab-pc-1$ haven serve ...`: the machine it is typed on
# Subcommands that end on their own and need no ROS graph, server or person: run here.
RUNS = {
    ("validate",),
    ("world", "show"),
    ("schema",),
    ("robots",),
    ("plugins",),
    ("plugins", "new"),
    ("cert",),
    ("batch",),
    ("study", "plan"),
    ("study", "status"),
    ("study", "run", "--batch"),
    ("study", "report"),
}
SITE = "site"  # a page's installed packages (`pip install`), in its folder


def page_folder(example: Example, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The page's own folder, shared by its examples in order (made for the first): the fixture
    `in_tmp` makes it every example's working folder."""
    if "__folder__" not in example.namespace:
        example.namespace["__folder__"] = tmp_path_factory.mktemp(Path(example.path).stem)
    return Path(example.namespace["__folder__"])


def commands(block: str) -> list[str]:
    """A block's command lines: continuation lines joined, comments and prompts dropped."""
    joined = re.sub(r"\\\n\s*", " ", block)
    out = []
    for line in joined.splitlines():
        words = shlex.split(PROMPT.sub("", line.strip()), comments=True)
        if words:
            out.append(shlex.join(words))
    return out


def one_seed(argv: list[str]) -> list[str]:
    """A sweep's arguments with its seeds cut to the first (`--seeds 0-9` -> `--seeds 0`)."""
    out = list(argv)
    for i, word in enumerate(out[:-1]):
        if word == "--seeds":
            out[i + 1] = re.split(r"[-,]", out[i + 1])[0]
        elif word == "--trials":
            out[i + 1] = "1"
    return out


def runs_here(argv: list[str]) -> bool:
    """Whether a `haven` command ends on its own here (`RUNS`; never in the background or on a cluster)."""
    if "--cluster" in argv or argv[-1:] == ["&"]:
        return False
    words = tuple(w for w in argv if not w.startswith("-")) + tuple(w for w in argv if w == "--batch")
    return any(words[: len(r)] == r or (words[:2] == r[:2] and r[-1] in words) for r in RUNS)


def check_haven(argv: list[str]) -> None:
    from haven_scenarios.tools.cli import build_parser, main

    args = [a for a in argv if a != "&"]
    into = args[args.index(">") + 1] if ">" in args else None  # (`haven schema scenario > FILE`)
    args = args[: args.index(">")] if into else args
    said = io.StringIO()
    with contextlib.redirect_stderr(said):
        try:
            build_parser().parse_args(args)
        except SystemExit:
            raise AssertionError(f"haven {shlex.join(args)}: {said.getvalue().strip()}") from None
    if not runs_here(args):
        return
    args = one_seed(args) if args[0] == "batch" else args
    if Path(SITE).is_dir():  # (a package the page installed: a process of its own reads its entry points)
        done = subprocess.run(
            [sys.executable, "-m", "haven_scenarios", *args], env=with_site(), capture_output=True, text=True
        )
        code, output = done.returncode, done.stdout + done.stderr
    else:
        with contextlib.redirect_stdout(said), contextlib.redirect_stderr(said):
            code, output = main(args), said.getvalue()
    assert code == 0, f"haven {shlex.join(args)}: exit code {code}:\n{output[-2000:]}"
    if into:
        Path(into).write_text(output)


def with_site() -> dict[str, str]:
    """The environment of a command after the page's `pip install`: its packages importable."""
    return {**os.environ, "PYTHONPATH": os.pathsep.join([str(Path(SITE).resolve()), os.environ.get("PYTHONPATH", "")])}


def pip_install(path: str) -> None:
    """`pip install -e PATH` into the page's folder (`--target`: HAVEN's environment is left as it is)."""
    uv = Path(sys.executable).with_name("uv")
    install = (
        [str(uv), "pip", "install", "--python", sys.executable]
        if uv.exists()
        else [sys.executable, "-m", "pip", "install"]
    )
    source = Path(path).resolve() if Path(path).exists() else ROOT / path  # (a folder, not a package's name)
    command = [*install, "-q", "--no-deps", "--no-build-isolation", "--target", SITE, str(source)]
    done = subprocess.run(command, capture_output=True, text=True)
    assert done.returncode == 0, f"pip install -e {path}: {(done.stdout + done.stderr)[-2000:]}"


def check_command(line: str) -> None:
    argv = shlex.split(line)
    program = Path(argv[0]).name
    if program == "haven":
        return check_haven(argv[1:])
    if program == "make":
        targets = re.findall(r"^([\w-]+):", (ROOT / "Makefile").read_text(), re.M)
        assert all(t in targets for t in argv[1:]), f"{line}: no such target in the Makefile"
        return None
    paths = [a for a in argv[1:] if not a.startswith("-") and a not in ("install", "&")]
    missing = [p for p in paths if not Path(p).exists() and not (ROOT / p).exists()]
    assert not missing, f"{line}: {missing} not in the page's folder or the repository"
    if program == "pip" and argv[1:2] == ["install"]:
        for path in paths:
            pip_install(path)
        return None
    if program == "pytest":
        done = subprocess.run(
            [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", *argv[1:]],
            env=with_site(),
            capture_output=True,
            text=True,
        )
        assert done.returncode == 0, f"{line}: exit code {done.returncode}:\n{(done.stdout + done.stderr)[-2000:]}"
        return None
    if program in ("python", "python3") and argv[-1] == "&":  # (a node of the user's, beside a running suite)
        assert paths, line
        return None
    raise AssertionError(f"{line}: no rule for {program} in haven_scenarios/test/doc_commands.py")


def evaluate_shell(example: Example) -> None:
    for line in example.parsed:
        check_command(line)


def evaluate_file(example: Example) -> None:
    name, text = example.parsed
    Path(name).parent.mkdir(parents=True, exist_ok=True)
    Path(name).write_text(text)


def parse_shell(document: Document) -> Iterable[Region]:
    for m in SHELL.finditer(document.text):
        yield Region(m.start(), m.end(), commands(m.group(1)), evaluate_shell)


def parse_files(document: Document) -> Iterable[Region]:
    for m in FILE.finditer(document.text):
        yield Region(m.start(), m.end(), (m.group(1), m.group(2)), evaluate_file)
