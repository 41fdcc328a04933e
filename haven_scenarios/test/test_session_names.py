"""Names cannot escape `--sessions`, and a session that cannot be made is one line.

Participant ids and scenario names become part of a session folder's name: they are checked
against a safe set (letters, digits, '_', '.', '-', starting with a letter or digit, no '..')
before any path is built, and `new_session_dir` checks again that the folder lands directly inside
the sessions folder. Nothing here starts ROS nodes: every case fails before they would start.

A full disk while the session is made is produced without root: `haven run` runs in a child whose
file size limit (RLIMIT_FSIZE, set in preexec_fn) is smaller than the world file it copies; Python
ignores SIGXFSZ, so the write fails with EFBIG the way it fails with ENOSPC on a full disk.
"""

import json
import os
import resource
import subprocess
import sys

import pytest

from haven_scenarios.record.session import new_session_dir, write_inputs
from haven_scenarios.study.names import check_name
from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.tools.cli import main

pytestmark = pytest.mark.integration

SCENARIO = "name: {name}\nworld: small_test\nkind: retrieval\ntimeout_s: 20\nrobot: {{order: nearest}}\n"
RULE = "must be 1 to 64 ASCII letters, digits, '_', '.' or '-', starting with a letter or digit, without '..'"
BAD = [
    "",
    ".",
    "..",
    "../x",
    "../../../x",
    "a/b",
    "/abs",
    "a..b",
    "-x",
    ".hidden",
    "x" * 65,
    "a b",
    "ü",
    "a\x00b",
    "a\\b",
    None,
    7,
]


def every_path(root):
    return sorted(str(p.relative_to(root)) for p in root.rglob("*"))


@pytest.mark.parametrize("name", ["sim", "p07", "h1-h2", "P.1_a", "x" * 64, "7"])
def test_safe_names_pass(name):
    assert check_name(name, "--participant") == name


@pytest.mark.parametrize("name", BAD)
def test_names_that_could_be_paths_are_refused_in_one_line(name):
    with pytest.raises(ValueError) as e:
        check_name(name, "--participant")
    assert str(e.value).startswith("--participant: must be ") and "\n" not in str(e.value)


@pytest.mark.parametrize("name", BAD[:10])
def test_new_session_dir_never_builds_a_path_from_a_bad_name(tmp_path, name):
    root = tmp_path / "sessions"
    for scenario, participant in ((name, "sim"), ("hallway", name)):
        with pytest.raises(ValueError):
            new_session_dir(root, scenario, participant)
    assert every_path(tmp_path) == []
    assert new_session_dir(root, "hallway", "p07").parent == root


def run_haven(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err.strip().splitlines()


def test_haven_run_refuses_a_participant_id_that_is_a_path(tmp_path, capsys):
    code, out, err = run_haven(
        capsys, "run", "hallway", "--participant", "../../x", "--sessions", str(tmp_path / "a" / "s")
    )
    assert code == 2 and out == ""
    rule = "1 to 64 ASCII letters, digits, '_', '.' or '-', starting with a letter or digit, without '..'"
    assert err == [f"haven: error: --participant: must be {rule}, got '../../x'"]
    assert every_path(tmp_path) == []  # nothing made, inside --sessions or out


@pytest.mark.parametrize("name", ["../evil", "a/b", "'..'"])
def test_haven_run_refuses_a_scenario_name_that_is_a_path(tmp_path, capsys, name):
    scenario = tmp_path / "evil.yaml"
    scenario.write_text(SCENARIO.format(name=name))
    code, _, err = run_haven(capsys, "run", str(scenario), "--sessions", str(tmp_path / "s"))
    assert code == 2 and len(err) == 1 and err[0].startswith(f"haven: error: {scenario}: name: must be ")
    assert every_path(tmp_path) == ["evil.yaml"]


def test_haven_rerun_checks_the_names_in_the_session_it_reads(tmp_path, capsys):
    """A session folder is data: its session.json may say anything."""
    old = tmp_path / "old"
    old.mkdir()
    write_inputs(old, load_scenario("hallway"), "{}\n")
    (old / "session.json").write_text(json.dumps({"participant": "../../../x", "seed": 0}))
    code, _, err = run_haven(capsys, "rerun", str(old), "--sessions", str(tmp_path / "s"))
    assert code == 2 and err == [f"haven: error: {old / 'session.json'}: participant: {RULE}, got '../../../x'"]
    assert not (tmp_path / "s").exists() and sorted(p.name for p in tmp_path.iterdir()) == ["old"]


def test_sessions_under_a_regular_file_is_one_line(tmp_path, capsys):
    afile = tmp_path / "afile"
    afile.write_text("not a folder\n")
    for sessions in (afile, afile / "s"):
        code, _, err = run_haven(capsys, "run", "hallway", "--sessions", str(sessions))
        assert code == 2 and err == [
            f"haven: error: --sessions {sessions}: cannot make a session folder there: Not a directory"
        ]
    assert afile.read_text() == "not a folder\n"


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into a read-only folder all the same")
def test_an_unwritable_sessions_folder_is_one_line(tmp_path, capsys):
    locked = tmp_path / "locked"
    locked.mkdir(mode=0o500)
    code, _, err = run_haven(capsys, "run", "hallway", "--sessions", str(locked))
    assert code == 2 and err == [
        f"haven: error: --sessions {locked}: cannot make a session folder there: Permission denied"
    ]


def test_a_full_disk_while_the_session_is_made_is_one_line_and_leaves_nothing_half_made(tmp_path):
    def small_files():
        resource.setrlimit(resource.RLIMIT_FSIZE, (1000, 1000))  # world.yaml alone is larger

    sessions = tmp_path / "s"
    r = subprocess.run(
        [sys.executable, "-m", "haven_scenarios.tools.cli", "run", "hallway", "--sessions", str(sessions)],
        capture_output=True,
        text=True,
        timeout=120,
        preexec_fn=small_files,
        # (the data file of `make coverage` would not fit either)
        env={k: v for k, v in os.environ.items() if not k.startswith("COVERAGE_")},
    )
    assert r.returncode == 2 and r.stdout == "" and "Traceback" not in r.stderr
    (line,) = r.stderr.strip().splitlines()
    assert line.startswith(f"haven: error: {sessions}/hallway_sim_") and line.endswith(
        ": cannot write the session's files: File too large"
    )
    assert list(sessions.iterdir()) == []  # the half-made session folder is gone (it held only copies)
