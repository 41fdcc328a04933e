"""Hostile world files (issue 14): whatever a file holds, `load_world` loads it or refuses it in one
short line naming the file (and the key) -- no traceback, no hang, no unbounded memory."""

import copy
import os
import threading

import yaml
from hostile import BOMB, refused

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import polygon_problem
from haven_sim.common.yaml_file import MAX_DEPTH, MAX_FILE_BYTES, MAX_NODES, read_yaml, short
from haven_sim.robots.fields import DEFAULT as ROBOT_BODY
from haven_sim.sim.world import WorldError, packaged_world
from haven_sim.sim.world_checks import MAX_COORDINATE_M, MAX_EXTENT_M
from haven_sim.sim.world_file import load_world

BASE = yaml.safe_load(packaged_world("small_test").read_text())


def refusal(path, *needles):
    return refused(WorldError, path, load_world, *needles)


def world_file(tmp_path, data, name="w.yaml"):
    p = tmp_path / name
    p.write_bytes(
        data if isinstance(data, bytes) else (data if isinstance(data, str) else yaml.safe_dump(data)).encode()
    )
    return p


def mutated(fn):
    d = copy.deepcopy(BASE)
    fn(d)
    return d


def test_invalid_utf8_binary_and_utf16_are_one_line_naming_the_byte(tmp_path):
    refusal(world_file(tmp_path, b"name: caf\xe9\nwalls: []\n"), "not UTF-8", "byte 0xe9 at offset 9")
    refusal(world_file(tmp_path, bytes(range(256)) * 4), "not UTF-8")
    refusal(world_file(tmp_path, packaged_world("small_test").read_text().encode("utf-16")), "UTF-16")
    refusal(world_file(tmp_path, b"name: a\x00b\n"), "line 1", "control characters")


def test_an_alias_bomb_is_refused_at_the_alias_without_expanding_it(tmp_path):
    text = "name: bomb\nrobot: {start: [1, 1, 0]}\n" + BOMB
    assert len(text) < 600
    refusal(world_file(tmp_path, text), "l5[", f"more than {MAX_NODES} values", "line 8")
    walls = (
        "name: bomb\nrobot: {start: [1, 1]}\n"
        "walls: [&w {segment: [[0, 0], [1, 0]], thickness: 0.1}, [*w, *w, *w, *w], &x [*w, *w], [*x, *x]]\n"
    )
    refusal(world_file(tmp_path, walls), "walls[1]", "must be a mapping")  # aliases that stay small are YAML as usual


def test_a_self_referencing_alias_and_deep_nesting_are_refused(tmp_path):
    refusal(world_file(tmp_path, "name: &n [1, *n]\n"), "name[1]", "refers to itself")
    refusal(world_file(tmp_path, "name: " + "[" * 100_000 + "]" * 100_000 + "\n"), f"deeper than {MAX_DEPTH} levels")
    refusal(
        world_file(tmp_path, "walls:\n" + "".join("  " * i + "- \n" for i in range(1, 200))),
        "walls[0][0]",
        f"deeper than {MAX_DEPTH}",
    )


def test_files_over_the_size_cap_are_refused_unread(tmp_path):
    flow = "walls: [" + ", ".join(["{segment: [[0, 0], [1, 1]], thickness: 0.1}"] * 50_000) + "]\n"  # ~2 MB
    assert len(flow) > 2 * MAX_FILE_BYTES - 200_000
    refusal(world_file(tmp_path, flow), "larger than 1 MiB")
    # < 1 MiB, too many values
    many = "name: many\nwalls: [" + ", ".join(["{polygon: [[0, 0], [1, 0], [1, 1]]}"] * 25_000) + "]\n"
    assert len(many) < MAX_FILE_BYTES
    refusal(world_file(tmp_path, many), f"more than {MAX_NODES} values")


def test_special_files_are_refused_before_they_are_opened(tmp_path):
    refusal("/dev/zero", "not a regular file")
    refusal(tmp_path, "a folder")
    refusal(tmp_path / "missing.yaml", "No such file")
    fifo = tmp_path / "fifo.yaml"
    os.mkfifo(fifo)

    # only if load_world opened the FIFO and waits for a writer: give it one, and a world it must not accept
    def unblock():
        fd = os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)
        os.write(fd, b"hung: true\n")
        os.close(fd)

    guard = threading.Timer(30.0, unblock)
    guard.start()
    try:
        refusal(fifo, "not a regular file")
    finally:
        guard.cancel()


def test_far_away_coordinates_and_worlds_too_large_for_the_grid_are_refused(tmp_path):
    far = world_file(tmp_path, mutated(lambda d: d["robot"].update(start=[1e6, 1e6, 0.0])))
    refusal(far, "robot.start[0]", f"within ±{MAX_COORDINATE_M:g} m")
    huge = world_file(
        tmp_path, mutated(lambda d: d["walls"].append({"segment": [[0, 0], [5000, 0]], "thickness": 0.1}))
    )
    refusal(huge, "walls[6].segment[1][0]", "within ±1000 m")
    wide = world_file(tmp_path, mutated(lambda d: d["walls"].append({"segment": [[0, 0], [500, 0]], "thickness": 0.1})))
    refusal(wide, "walls[6]", f"a world fits in {MAX_EXTENT_M:g} m x {MAX_EXTENT_M:g} m")
    gem = world_file(tmp_path, mutated(lambda d: d["gems"][0].update(position=[-300.0, 2.0])))
    refusal(gem, "gems[0].position", "makes the world span")
    thick = world_file(tmp_path, mutated(lambda d: d["walls"][0].update(thickness=1e300)))
    refusal(thick, "walls[0].thickness", "at most 100 m")
    refusal(
        world_file(tmp_path, mutated(lambda d: d["walls"][0].update(thickness=10**400))),
        "walls[0].thickness",
        "finite number",
    )


def test_the_robots_and_peoples_whole_bodies_must_be_clear_of_walls_at_start(tmp_path):
    # small_test has a wall along x = 4 (0.1 m thick) from y = 0 to 1.9: its face is at x = 3.95.
    just_clear = world_file(
        tmp_path, mutated(lambda d: d["robot"].update(start=[3.95 - ROBOT_BODY.radius_m - 0.01, 1.0, 0.0]))
    )
    assert load_world(just_clear).robot_start.x < 3.95
    body = world_file(
        tmp_path, mutated(lambda d: d["robot"].update(start=[3.95 - ROBOT_BODY.radius_m + 0.05, 1.0, 0.0]))
    )
    refusal(body, "robot.start", f"the robot's body (radius {ROBOT_BODY.radius_m:g} m) into a wall")
    human = world_file(
        tmp_path, mutated(lambda d: d["humans"][0].update(start=[7.95 - HUMAN_BODY.radius_m + 0.05, 1.0, 0.0]))
    )
    refusal(human, "humans[0].start", f"the person's body (radius {HUMAN_BODY.radius_m:g} m) into a wall")
    # obstacle spans x 6.0..6.6
    pillar = world_file(tmp_path, mutated(lambda d: d["humans"][0].update(start=[5.9, 3.8, 0.0])))
    refusal(pillar, "humans[0].start", "into an obstacle")
    door = world_file(
        tmp_path,
        mutated(
            lambda d: d.update(obstructions=[{"id": "door", "segment": [[0.9, 2.0], [0.9, 3.0]], "thickness": 0.1}])
        ),
    )
    refusal(door, "robot.start", "into an obstruction door")


def test_places_someone_must_stand_on_are_clear_of_walls_and_furniture(tmp_path):
    """A gem, a room's centre or the charging base in a wall would only show as a trial that times
    out (the planner refuses the goal): refused in one line instead, with its owner's body size."""
    gem = world_file(tmp_path, mutated(lambda d: d["gems"][0].update(position=[4.0, 1.0])))  # in the x = 4 wall
    refusal(gem, "gems[0].position", "(4, 1) lies inside a wall")
    room = world_file(
        tmp_path, mutated(lambda d: d["rooms"][0].update(centre=[3.95 - ROBOT_BODY.radius_m + 0.05, 1.0]))
    )
    refusal(room, "rooms[0].centre", f"the robot's body (radius {ROBOT_BODY.radius_m:g} m) into a wall")
    under = world_file(tmp_path, mutated(lambda d: d["gems"][0].update(position=[6.3, 3.8])))  # under the obstacle
    refusal(under, "gems[0].position", "lies inside an obstacle")
    base = world_file(tmp_path, mutated(lambda d: d.update(charging_base={"position": [4.0, 0.5], "radius": 0.4})))
    refusal(base, "charging_base.position", "lies inside a wall")


def test_polygons_must_be_simple(tmp_path):
    bowtie = [[6.0, 3.5], [6.6, 4.1], [6.6, 3.5], [6.0, 4.3]]  # edges 0 and 2 cross; the area is not zero
    crossing = "edges from point 0 to 1 and from point 2 to 3 cross"
    refusal(
        world_file(tmp_path, mutated(lambda d: d["obstacles"][0].update(polygon=bowtie))),
        "obstacles[0].polygon",
        crossing,
    )
    repeated = [[6.0, 3.5], [6.6, 3.5], [6.6, 3.5], [6.6, 4.1], [6.0, 4.1]]
    refusal(
        world_file(tmp_path, mutated(lambda d: d["obstacles"][0].update(polygon=repeated))), "point 2 repeats point 1"
    )
    closed = [[6.0, 3.5], [6.6, 3.5], [6.6, 4.1], [6.0, 4.1], [6.0, 3.5]]  # the first point again at the end
    refusal(
        world_file(tmp_path, mutated(lambda d: d["obstacles"][0].update(polygon=closed))), "point 0 repeats point 4"
    )
    spike = [[6.0, 3.5], [6.6, 3.5], [6.6, 4.1], [6.6, 3.8], [6.0, 4.1]]
    refusal(world_file(tmp_path, mutated(lambda d: d["obstacles"][0].update(polygon=spike))), "folds back")
    many = [[6.0 + 0.3 * (i % 2), 3.5 + 0.001 * i] for i in range(600)]
    refusal(
        world_file(tmp_path, mutated(lambda d: d["obstacles"][0].update(polygon=many))), "has 600 points; at most 500"
    )


def test_polygon_checks_accept_simple_polygons_of_any_winding():
    square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    ell = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)]
    assert polygon_problem(square) is None and polygon_problem(square[::-1]) is None and polygon_problem(ell) is None
    # a vertex on an edge
    assert "cross or touch" in polygon_problem([(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (1.0, 0.0), (0.0, 2.0)])


def test_values_in_messages_are_truncated(tmp_path):
    long_name = "x" * 100_000
    msg = refusal(world_file(tmp_path, mutated(lambda d: d["rooms"][0].update(name=long_name))), "rooms[0].name")
    assert len(msg) < 250
    nested = mutated(lambda d: d["robot"].update(start=[[[[[["deep"] * 50] * 50]]]]))
    refusal(world_file(tmp_path, nested), "robot.start", "must be a pose")
    refusal(world_file(tmp_path, mutated(lambda d: d.update({"bad\nkey": 1}))), "'bad\\nkey': unknown key")
    assert len(short(list(range(10**5)))) <= 60 and len(short(10**4000)) <= 60


def test_yaml_tags_huge_integers_and_several_documents_are_one_line(tmp_path):
    refusal(
        world_file(tmp_path, "name: !!python/object/apply:os.system [echo]\n"),
        "YAML syntax error at line 1",
        "constructor",
    )
    refusal(world_file(tmp_path, "name: " + "9" * 5000 + "\n"), "invalid value")
    refusal(world_file(tmp_path, "name: a\n---\nname: b\n"), "line 2")


def test_the_shared_reader_keeps_merge_keys_and_a_utf8_bom(tmp_path):
    p = world_file(tmp_path, "\ufeffbase: &b {x: 1}\nuse: {<<: *b, y: 2}\n")
    assert read_yaml(p) == {"base": {"x": 1}, "use": {"x": 1, "y": 2}}
