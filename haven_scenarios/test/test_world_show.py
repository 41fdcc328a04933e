"""`haven world show`: a world file checked and drawn from above, or its problem in one line."""

from __future__ import annotations

from pathlib import Path

from haven_scenarios.tools.cli import main


def test_a_shipped_world_is_checked_and_drawn(capsys, tmp_path: Path) -> None:
    out = tmp_path / "hallway.png"
    assert main(["world", "show", "hallway", "--out", str(out)]) == 0
    said = capsys.readouterr().out
    assert said.startswith("ok: ") and "world hallway: 32 wall(s)" in said and "4 hallway(s)" in said and said.rstrip().endswith(str(out))
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 20_000


def test_a_broken_world_is_one_line_and_no_picture(capsys, tmp_path: Path) -> None:
    bad = tmp_path / "lab.yaml"
    bad.write_text("name: lab\nwalls: [{segment: [[0, 0], [4, 0]], thickness: -0.1}]\nrobot: {start: [1, 1, 0]}\n")
    assert main(["world", "show", str(bad), "--out", str(tmp_path / "lab.png")]) == 2
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert line.startswith(f"haven: error: {bad}: walls[0].thickness") and not (tmp_path / "lab.png").exists()
