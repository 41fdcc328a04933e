"""Session files are written whole or not at all: a write that fails (a full disk; here a file size
limit, which fails the same way with EFBIG) leaves the old file, never an empty or half one."""

import json
import subprocess
import sys

from haven_sim.common import atomic

WRITE_UNDER_A_SIZE_LIMIT = """
import json, resource, sys
from pathlib import Path
from haven_sim.common import atomic
resource.setrlimit(resource.RLIMIT_FSIZE, (200, 200))  # (Python ignores SIGXFSZ: the write fails with EFBIG)
try:
    atomic.write_text(Path(sys.argv[1]), json.dumps({"big": "x" * 5000}))
except OSError as e:
    print(e.errno)
"""


def test_a_write_that_fails_leaves_the_old_file_and_no_temporary_one(tmp_path):
    target = tmp_path / "metrics.json"
    atomic.write_text(target, json.dumps({"old": 1}))
    r = subprocess.run(
        [sys.executable, "-c", WRITE_UNDER_A_SIZE_LIMIT, str(target)], capture_output=True, text=True, timeout=60
    )
    assert r.stdout.strip() == "27", r.stderr  # EFBIG
    assert json.loads(target.read_text()) == {"old": 1}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["metrics.json"]
    fresh = tmp_path / "new.json"
    r = subprocess.run(
        [sys.executable, "-c", WRITE_UNDER_A_SIZE_LIMIT, str(fresh)], capture_output=True, text=True, timeout=60
    )
    assert r.stdout.strip() == "27" and not fresh.exists()  # no 0-byte file


def test_the_file_appears_only_when_the_block_ends(tmp_path):
    target = tmp_path / "a.txt"
    with atomic.replacing(target) as tmp:
        tmp.write_bytes(b"abc")
        assert not target.exists()
    assert target.read_bytes() == b"abc" and not tmp.exists()


def test_a_secret_is_0600_from_its_first_byte_and_never_written_through_a_link(tmp_path, monkeypatch):
    import os
    import stat

    import pytest

    old = os.umask(0o000)
    try:
        seen = []
        real_fsync = os.fsync
        monkeypatch.setattr(os, "fsync", lambda fd: (seen.append(stat.S_IMODE(os.fstat(fd).st_mode)), real_fsync(fd)))
        atomic.write_secret(tmp_path / "key.pem", b"one")
        atomic.write_secret(tmp_path / "key.pem", b"two")  # over an existing one
    finally:
        os.umask(old)
    assert seen == [0o600, 0o600] and stat.S_IMODE((tmp_path / "key.pem").stat().st_mode) == 0o600
    assert (tmp_path / "key.pem").read_bytes() == b"two"
    victim = tmp_path / "victim.txt"
    victim.write_text("notes")
    (tmp_path / "link.pem").symlink_to(victim)
    with pytest.raises(atomic.SymlinkRefused, match=r"link\.pem is a symbolic link: refusing"):
        atomic.write_secret(tmp_path / "link.pem", b"secret")
    with pytest.raises(atomic.SymlinkRefused):
        atomic.open_secret_log(tmp_path / "link.pem")
    assert victim.read_text() == "notes" and (tmp_path / "link.pem").is_symlink()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["key.pem", "link.pem", "victim.txt"]  # no temporary file left
    os.close(atomic.open_secret_log(tmp_path / "online.log"))
    assert stat.S_IMODE((tmp_path / "online.log").stat().st_mode) == 0o600
