import pytest
import yaml

from haven_sim.sim.world import WorldError, packaged_world, resolve_world_path
from haven_sim.sim.world_file import load_world


def test_packaged_world_loads():
    w = load_world(packaged_world("small_test"))
    assert w.name == "small_test"
    assert [r.name for r in w.rooms] == ["west", "east"]
    assert w.humans[0].id == "h1"
    assert {g.owner for g in w.gems} == {"robot", "human"}
    assert w.charging_base is not None and w.charging_base.radius == 0.5
    assert w.edges().shape == (4 * (len(w.walls) + len(w.obstacles)), 4)
    assert resolve_world_path("small_test") == packaged_world("small_test")


def test_polygons_are_stored_counter_clockwise():
    from haven_sim.common.geometry import polygon_area

    w = load_world(packaged_world("small_test"))
    assert all(polygon_area(list(s.polygon)) > 0 for s in w.solid_shapes())


def _base():
    return yaml.safe_load(packaged_world("small_test").read_text())


def _write(tmp_path, data):
    p = tmp_path / "bad.yaml"
    p.write_text(data if isinstance(data, str) else yaml.safe_dump(data))
    return p


def _mutate(fn):
    d = _base()
    fn(d)
    return d


BAD = [
    (lambda d: d.pop("name"), "name", "is required"),
    (lambda d: d["walls"][2].update(thickness=-1), "walls[2].thickness", "must be positive"),
    (lambda d: d["walls"][0].pop("thickness"), "walls[0].thickness", "is required"),
    (lambda d: d["walls"][1].update(polygon=[[0, 0], [1, 1], [2, 2]]), "walls[1]", "exactly one"),
    (lambda d: d["obstacles"][0].update(polygon=[[0, 0], [1, 1], [2, 2]]), "obstacles[0].polygon", "zero area"),
    (lambda d: d.update(colour="red"), "colour", "unknown key"),
    (lambda d: d["gems"][1].update(id="r1"), "gems[1].id", "duplicate"),
    (lambda d: d["gems"][0].update(owner="dog"), "gems[0].owner", "must be one of"),
    (lambda d: d["robot"].update(start=[4.0, 1.0, 0.0]), "robot.start", "inside a wall"),
    (lambda d: d["humans"][0].update(start=[6.3, 3.8]), "humans[0].start", "inside an obstacle"),
    (lambda d: d["rooms"][0].update(centre=[1, "x"]), "rooms[0].centre[1]", "finite number"),
    (lambda d: d["hallways"][0].update(centreline=[[0, 0]]), "hallways[0].centreline", "at least 2"),
    (
        lambda d: d.update(
            obstructions=[
                {"id": "o", "segment": [[4, 2], [4, 3]], "thickness": 0.1, "removed_when_human_reaches": "attic"}
            ]
        ),
        "obstructions[0].removed_when_human_reaches",
        "names no room",
    ),
]


@pytest.mark.parametrize("mutate,key,problem", BAD, ids=[b[1] for b in BAD])
def test_invalid_world_names_file_key_and_problem(tmp_path, mutate, key, problem):
    path = _write(tmp_path, _mutate(mutate))
    with pytest.raises(WorldError) as e:
        load_world(path)
    msg = str(e.value)
    assert msg.startswith(f"{path}: {key}: "), msg
    assert problem in msg
    assert "\n" not in msg


def test_yaml_syntax_error_and_missing_file(tmp_path):
    path = _write(tmp_path, "name: x\nwalls: [\n")
    with pytest.raises(WorldError, match=r"bad.yaml: YAML syntax error at line \d+"):
        load_world(path)
    with pytest.raises(WorldError, match="cannot read world file"):
        load_world(tmp_path / "nope.yaml")
    with pytest.raises(WorldError, match="empty"):
        load_world(_write(tmp_path, ""))


def test_obstructions_are_solid_until_removed():
    d = _base()
    d["obstructions"] = [
        {"id": "door", "segment": [[4, 1.9], [4, 3.1]], "thickness": 0.05, "removed_when_human_reaches": "west"}
    ]
    from haven_sim.sim.world_file import parse_world

    w = parse_world(d)
    assert len(w.solid_shapes()) == len(w.solid_shapes(frozenset({"door"}))) + 1
    assert w.obstructions[0].removed_when_human_reaches == "west"
