"""`haven plugins new KIND NAME`: each kind's package is written, refused names say why in one line,
and (integration) each package's own tests pass once it is installed as a lab installs it."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from haven_scenarios.conduct.plugin_package import TEMPLATES, package_files, write_package
from haven_sim.common import plugins

KINDS = list(TEMPLATES)


def test_every_plugin_kind_has_a_package_to_start_from():
    assert sorted(TEMPLATES) == sorted(plugins.kinds())


@pytest.mark.parametrize("kind", ["cue", "cues"])
def test_a_cue_package_registers_the_cue_by_its_entry_point(kind):
    files = package_files(kind, "my_cue")
    assert sorted(files) == [
        "README.md",
        "conftest.py",
        "haven_my_cue/__init__.py",
        "haven_my_cue/my_cue.py",
        "pyproject.toml",
        "tests/test_my_cue.py",
    ]
    assert '[project.entry-points."haven.cues"]\nmy_cue = "haven_my_cue.my_cue:MyCue"' in files["pyproject.toml"]
    assert 'pytest_plugins = ["haven_scenarios.testing"]' in files["conftest.py"]
    compile(files["haven_my_cue/my_cue.py"], "my_cue.py", "exec")
    compile(files["tests/test_my_cue.py"], "test_my_cue.py", "exec")


@pytest.mark.parametrize(
    ("kind", "name", "said"),
    [
        ("widget", "x", "unknown plugin kind 'widget' (known: "),
        ("cue", "My_Cue", "plugin name 'My_Cue': lower-case letters"),
        ("cue", "gaze", "cue 'gaze' is HAVEN's own (HAVEN's cues: arrow, "),
        ("participant", "walker", "participant model 'walker' is HAVEN's own"),
    ],
)
def test_a_kind_or_name_that_cannot_be_is_refused_in_one_line(kind, name, said):
    with pytest.raises(ValueError, match="^" + said.replace("(", r"\(")) as e:
        package_files(kind, name)
    assert "\n" not in str(e.value)


def test_an_existing_folder_is_never_written_over(tmp_path):
    (tmp_path / "haven_mine").mkdir()
    with pytest.raises(ValueError, match="exists already"):
        write_package("metric", "mine", tmp_path)
    assert list((tmp_path / "haven_mine").iterdir()) == []


@pytest.mark.integration
@pytest.mark.parametrize("kind", KINDS)
def test_the_package_s_own_tests_pass_once_installed(kind, tmp_path):
    """Installed as a package is (its entry point in its dist-info; `--target`, so HAVEN's own
    environment is untouched), its tests load it through the registry and run a batch trial with it."""
    folder = write_package(kind, f"lab_{kind}", tmp_path)
    target = tmp_path / "site"
    uv = Path(sys.executable).with_name("uv")
    install = (
        [str(uv), "pip", "install", "--python", sys.executable]
        if uv.exists()
        else [sys.executable, "-m", "pip", "install"]
    )
    subprocess.run(
        [*install, "-q", "--no-deps", "--no-build-isolation", "--target", str(target), str(folder)], check=True
    )
    shutil.rmtree(folder / "build", ignore_errors=True)
    env = {**os.environ, "PYTHONPATH": str(target)}
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider"],
        cwd=folder,
        env=env,
        capture_output=True,
        text=True,
        timeout=240,
    )
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
    assert "2 passed" in run.stdout
