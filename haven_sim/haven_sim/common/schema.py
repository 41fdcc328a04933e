"""The schema layer of HAVEN's files, on pydantic v2: a file's shape (its keys, their types, ranges
and choices) is a model; `check` validates a YAML tree read by `yaml_file.read_yaml` (which keeps
its guards: size, nesting, aliases, keys given twice) and turns the first problem into the one line
users know, `file: key: problem`. A model also gives the file's JSON Schema (`haven schema`), which
YAML editors use for completion and checking as the file is written.

Types with our own wording (`Whole`, `Positive`, `Line`, `listing`, `mapping`) check in one step so the message says
what is wanted ("must be a whole number 1..999, got 0"); a validator that raises ValueError has
its message used as it is. Checks that need more than the file (a scenario file to load, a cue
to look up) stay with the code that reads the model.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Annotated, Any, TypeVar, get_args, get_origin

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, ValidationError

from haven_sim.common.yaml_file import file_label, finite, short, shown_key

M = TypeVar("M", bound=BaseModel)


class FileModel(BaseModel):
    """A part of a file: unknown keys refused, values as written (no silent coercion), frozen."""

    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)


def Whole(low: int, high: int) -> Any:
    """A whole number within [low, high] (not a bool, not 2.0)."""

    def check(v: Any) -> Any:
        if isinstance(v, bool) or not isinstance(v, int) or not low <= v <= high:
            raise ValueError(f"must be a whole number {low}..{high}, got {short(v)}")
        return v

    return Annotated[int, Field(ge=low, le=high), BeforeValidator(check)]  # (this order: the JSON Schema has the range)


def Positive(limit: float = math.inf) -> Any:
    """A finite number above 0 and at most `limit` (an int is taken as a float; not a bool)."""

    def check(v: Any) -> float:
        f = finite(v)
        if f is None or not f > 0:
            raise ValueError(f"must be a positive number, got {short(v)}")
        if f > limit:
            raise ValueError(f"must be at most {limit:g}, got {f:g}")
        return f

    return Annotated[float, Field(gt=0, le=limit) if math.isfinite(limit) else Field(gt=0), BeforeValidator(check)]


def Line(limit: int) -> Any:
    """A non-empty line of printable text of at most `limit` characters."""

    def check(v: Any) -> str:
        if not isinstance(v, str) or not v or not v.isprintable() or len(v) > limit:
            raise ValueError(f"must be a non-empty line of at most {limit} characters, got {short(v)}")
        return v

    return Annotated[str, Field(max_length=limit), BeforeValidator(check)]


def listing(what: str, non_empty: bool = True) -> BeforeValidator:
    """A list (non-empty unless said), else "must be <what>, got ..."."""

    def check(v: Any) -> Any:
        if not isinstance(v, list) or (non_empty and not v):
            raise ValueError(f"must be {what}, got {short(v)}")
        return v

    return BeforeValidator(check)


def mapping(what: str) -> BeforeValidator:
    """A non-empty mapping, else "must be <what>"."""

    def check(v: Any) -> Any:
        if not isinstance(v, dict) or not v:
            raise ValueError(f"must be {what}")
        return v

    return BeforeValidator(check)


def checked(fn: Callable[[Any], Any]) -> BeforeValidator:
    """A check of ours (raises ValueError with the problem) before pydantic's own."""
    return BeforeValidator(fn)


def check(model: type[M], data: Any, source: str, error: type[Exception], what: str = "file") -> M:
    """`data` as a `model`; `error` (one line: `source: key: problem`) on the first problem."""
    if not isinstance(data, dict):
        raise error(f"{file_label(source)}: the {what} must be a mapping")
    try:
        return model.model_validate(data)
    except ValidationError as e:
        raise error(f"{file_label(source)}: {problem(model, e)}") from None


def problem(model: type[BaseModel], e: ValidationError) -> str:
    """The first problem as `key: problem` (an unknown key first, then a missing one, then in the
    models' field order)."""
    errors = e.errors(include_url=False)
    rank = {"extra_forbidden": 0, "missing": 1}
    err = min(errors, key=lambda x: rank.get(x["type"], 2))
    loc = tuple(err["loc"])
    key = _key(loc)
    kind, given = err["type"], err.get("input")
    if kind == "extra_forbidden":
        return f"{key}: unknown key (allowed: {', '.join(_fields_at(model, loc[:-1]))})"
    if kind == "missing":
        return f"{key}: is required"
    if kind == "value_error":  # (a check of the whole file names its keys itself)
        msg = str(err["msg"]).removeprefix("Value error, ")
        return f"{key}: {msg}" if loc else msg
    if kind == "literal_error":
        options = str(err.get("ctx", {}).get("expected", "")).replace("'", "").replace(" or ", ", ")
        return f"{key}: must be one of {options}, got {short(given)}"
    if kind in ("model_type", "model_attributes_type", "dict_type"):
        return f"{key}: must be a mapping, got {short(given)}"
    if kind == "list_type":
        return f"{key}: must be a list, got {short(given)}"
    if kind in ("string_type", "str_type"):
        return f"{key}: must be text, got {short(given)}"
    wanted = {"int_type": "a whole number", "float_type": "a number", "bool_type": "true or false"}
    if kind in wanted:
        return f"{key}: must be {wanted[kind]}, got {short(given)}"
    return f"{key}: {err['msg']}, got {short(given)}"


def _key(loc: tuple[Any, ...]) -> str:
    out = ""
    for part in loc:
        if isinstance(part, str) and "[" in part:  # (a member of a union, as pydantic tags it)
            continue
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += ("." if out else "") + shown_key(part)
    return out or "(the file)"


def _fields_at(model: type[BaseModel], loc: tuple[Any, ...]) -> list[str]:
    """The keys allowed at `loc` (the model nested there, through lists and mappings)."""
    current: Any = model
    for part in loc:
        if isinstance(part, int) or not (isinstance(current, type) and issubclass(current, BaseModel)):
            current = _inner(current)
            if isinstance(part, int):
                continue
        field = current.model_fields.get(part) if isinstance(current, type) and issubclass(current, BaseModel) else None
        current = _inner(field.annotation) if field is not None else None
    return list(current.model_fields) if isinstance(current, type) and issubclass(current, BaseModel) else []


def _inner(annotation: Any) -> Any:
    """The model inside list[...], dict[..., ...], X | None or Annotated[...] (else the annotation)."""
    for arg in reversed(get_args(annotation) if get_origin(annotation) is not None else ()):
        found = _inner(arg)
        if isinstance(found, type) and issubclass(found, BaseModel):
            return found
    return annotation
