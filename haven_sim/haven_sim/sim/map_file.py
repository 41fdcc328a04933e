"""The `map:` key of a world file: a ROS map (the map_server YAML that map_saver and slam_toolbox
write, named by its path) or a floor-plan image with its scale, given inline::

    map: building.yaml                 # a map_server YAML beside the world file
    map: {image: plan.png, resolution: 0.02, origin: [-5.0, -3.0, 0.0]}   # a floor plan, 2 cm per pixel

The inline keys are map_server's (image, resolution, origin, negate, occupied_thresh, free_thresh,
mode), with map_saver's defaults where map_server requires them (`map_image`); a map_server YAML's
other keys are ignored, as map_server ignores them. Paths are relative to the file that names them.
HAVEN needs `origin`'s yaw to be 0 (Nav2's documentation: "many parts of the system currently
ignore yaw"); a rotated map is refused in one line.
"""

from __future__ import annotations

from difflib import get_close_matches
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import ValidationError

from haven_sim.common.schema import FileModel, Positive, check, checked, problem
from haven_sim.common.yaml_file import file_label, finite, read_yaml, short
from haven_sim.sim.map_image import FREE_THRESH, OCCUPIED_THRESH, MapImage, image_path, read_image
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_checks import MAX_COORDINATE_M


def _origin(value: Any) -> Any:
    if not isinstance(value, list) or len(value) not in (2, 3) or any(finite(v) is None for v in value):
        raise ValueError(f"must be [x, y, yaw] (the lower-left pixel's pose), got {short(value)}")
    if any(abs(v) > MAX_COORDINATE_M for v in value[:2]):
        raise ValueError(f"must be within ±{MAX_COORDINATE_M:g} m, got {short(value)}")
    if len(value) == 3 and value[2] != 0:
        raise ValueError(f"yaw must be 0 (HAVEN does not rotate maps; nor do many Nav2 parts), got {value[2]:g}")
    return [float(v) for v in value]


def _negate(value: Any) -> Any:
    if value in (0, 1) and not isinstance(value, float):
        return bool(value)
    raise ValueError(f"must be 0 or 1 (or false / true), got {short(value)}")


class MapFile(FileModel):
    """A map's settings, as map_server reads them from its YAML."""

    image: str
    resolution: Positive()  # type: ignore[valid-type]  # (checked here, so the error names the file that sets it)
    origin: Annotated[list[float], checked(_origin)] = [0.0, 0.0, 0.0]  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    negate: Annotated[bool, checked(_negate)] = False
    occupied_thresh: float = OCCUPIED_THRESH
    free_thresh: float = FREE_THRESH
    mode: Literal["trinary", "scale", "raw"] = "trinary"


def load_map(value: Any, world_source: str) -> MapImage:
    """The map a world file's `map:` names: a map_server YAML path or inline settings."""
    base = Path(world_source).parent
    if isinstance(value, str):
        if Path(value).suffix.lower() in IMAGE_SUFFIXES:
            raise WorldError(
                f"{file_label(world_source)}: map: {value} is an image: give its scale with it, "
                f"map: {{image: {value}, resolution: M_PER_PIXEL, origin: [X, Y, 0]}}"
            )
        path = image_path(value, base, world_source, "map")
        data = read_yaml(path, "map file", WorldError)
        if not isinstance(data, dict):
            raise WorldError(f"{file_label(path)}: the map file must be a mapping")
        known = {k: v for k, v in data.items() if k in MapFile.model_fields}  # (map_server ignores other keys)
        try:
            settings = check(MapFile, known, str(path), WorldError, "map file")
        except WorldError as e:
            raise WorldError(f"{e}{_misspelt(data)}") from None
        return _read(settings, path.parent, str(path), "")
    if isinstance(value, dict):
        try:
            inline = MapFile.model_validate(value)
        except ValidationError as e:
            raise WorldError(f"{file_label(world_source)}: map.{problem(MapFile, e)}") from None
        return _read(inline, base, world_source, "map")
    raise WorldError(
        f"{file_label(world_source)}: map: must be a map_server YAML "
        f"file or a mapping (image, resolution, ...), got {short(value)}"
    )


IMAGE_SUFFIXES = (".pgm", ".png", ".jpg", ".jpeg", ".bmp", ".gif", ".tif", ".tiff")


def _misspelt(data: dict[Any, Any]) -> str:
    """The note for a key map_server would ignore that is close to one of its own, as in
    " (is 'resolutoin' meant to be 'resolution'?)" (a typo would only show as a missing key)."""
    for key in data:
        if isinstance(key, str) and key not in MapFile.model_fields:
            close = get_close_matches(key, list(MapFile.model_fields), n=1, cutoff=0.75)
            if close:
                return f" (is {key!r} meant to be {close[0]!r}?)"
    return ""


def _read(m: MapFile, base: Path, source: str, key: str) -> MapImage:
    path = image_path(m.image, base, source, f"{key}.image" if key else "image")
    return read_image(
        path, m.resolution, (m.origin[0], m.origin[1]), m.negate, m.occupied_thresh, m.free_thresh, m.mode, key
    )
