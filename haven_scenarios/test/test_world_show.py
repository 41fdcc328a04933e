"""`haven world show`: a world file checked and drawn from above, or its problem in one line."""

from __future__ import annotations

from pathlib import Path

from haven_scenarios.tools.cli import main


def test_a_shipped_world_is_checked_and_drawn(capsys, tmp_path: Path) -> None:
    out = tmp_path / "hallway.png"
    assert main(["world", "show", "hallway", "--out", str(out)]) == 0
    said = capsys.readouterr().out
    assert (
        said.startswith("ok: ")
        and "world hallway: 32 wall(s)" in said
        and "4 hallway(s)" in said
        and said.rstrip().endswith(str(out))
    )
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 20_000


def test_a_broken_world_is_one_line_and_no_picture(capsys, tmp_path: Path) -> None:
    bad = tmp_path / "lab.yaml"
    bad.write_text("name: lab\nwalls: [{segment: [[0, 0], [4, 0]], thickness: -0.1}]\nrobot: {start: [1, 1, 0]}\n")
    assert main(["world", "show", str(bad), "--out", str(tmp_path / "lab.png")]) == 2
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert line.startswith(f"haven: error: {bad}: walls[0].thickness") and not (tmp_path / "lab.png").exists()


def test_a_world_from_a_ros_map_is_drawn_with_the_maps_walls(capsys, tmp_path: Path) -> None:
    """The map the tests make (haven_sim/test/map_maker.py): its occupied and unknown cells drawn as
    walls, about 29 of its 70 m² (the building's 0.2 m shell, the dividing wall, the unknown around)."""
    import numpy as np
    from map_maker import make_map_world
    from PIL import Image

    from haven_viz.world_markers import COLORS

    make_map_world(tmp_path)
    out = tmp_path / "map.png"
    assert main(["world", "show", str(tmp_path / "world.yaml"), "--out", str(out)]) == 0
    assert "world test_map: 7 wall(s)" in capsys.readouterr().out
    pixels = np.asarray(Image.open(out).convert("RGB"))
    wall = np.array([round(255 * c) for c in COLORS["wall"][:3]])
    share = float((np.abs(pixels.astype(int) - wall).max(axis=2) <= 2).mean())
    assert 0.2 < share < 0.5, share


def test_a_maps_own_yaml_or_a_fifo_as_its_image_is_one_line(capsys, tmp_path: Path) -> None:
    import os
    import threading

    from map_maker import make_map_world

    make_map_world(tmp_path)
    for command in (["world", "show"], ["validate"]):
        assert main([*command, str(tmp_path / "map.yaml")]) == 2
        (line,) = capsys.readouterr().err.strip().splitlines()
        assert (
            line.startswith(f"haven: error: {tmp_path / 'map.yaml'}: this is a map_server map")
            and "`map: map.yaml`" in line
        ), line
    (tmp_path / "map.pgm").unlink()
    os.mkfifo(tmp_path / "map.pgm")  # (refused before it is opened: opening it would wait for a writer)
    # (if it did)
    guard = threading.Timer(20.0, lambda: os.close(os.open(tmp_path / "map.pgm", os.O_WRONLY | os.O_NONBLOCK)))
    guard.start()
    try:
        assert main(["world", "show", str(tmp_path / "world.yaml"), "--out", str(tmp_path / "w.png")]) == 2
    finally:
        guard.cancel()
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert line == f"haven: error: {tmp_path / 'map.pgm'}: image: cannot be read as an image: not a regular file"


def test_a_world_past_the_planners_caps_is_refused_in_one_line_by_validate_and_show(capsys, tmp_path: Path) -> None:
    """A map of 729 pillars (2,916 corners for the built-in planner on a 20 m map) loads, but the
    planner's graph would pass its caps: refused naming the world and the cap; the shipped worlds pass."""
    import numpy as np
    from PIL import Image

    from haven_sim.nav.planner import MAX_PLANNER_NODES

    image = np.full((400, 400), 254, np.uint8)
    image[:2], image[-2:], image[:, :2], image[:, -2:] = 0, 0, 0, 0
    image[14:-14:14, 14:-14:14] = 0
    Image.fromarray(image).save(tmp_path / "dots.pgm")
    world = tmp_path / "dots.yaml"
    world.write_text("name: dots\nmap: {image: dots.pgm, resolution: 0.05}\nrobot: {start: [0.4, 0.4, 0.0]}\n")
    scenario = tmp_path / "trial.yaml"  # what `haven run`, `batch` and studies load
    scenario.write_text("name: trial\nworld: dots.yaml\nkind: retrieval\ntimeout_s: 60\n")
    for args, said in (
        (["validate", str(world)], f"{world}: world dots: "),
        (["world", "show", str(world), "--out", str(tmp_path / "dots.png")], f"{world}: world dots: "),
        (["validate", str(scenario)], f"{scenario}: world: {world}: world dots: "),
    ):
        assert main(args) == 2
        (line,) = capsys.readouterr().err.strip().splitlines()
        assert (
            line.startswith(f"haven: error: {said}the map has 2,916 corners")
            and f"at most {MAX_PLANNER_NODES:,}" in line
        ), line
    assert not (tmp_path / "dots.png").exists()
    shipped = sorted(p.stem for p in (Path(__file__).parents[1] / "haven_scenarios" / "worlds").glob("*.yaml"))
    assert (
        len(shipped) >= 9
        and main(
            [
                "validate",
                *(str(Path(__file__).parents[1] / "haven_scenarios" / "worlds" / f"{n}.yaml") for n in shipped),
            ]
        )
        == 0
    )
