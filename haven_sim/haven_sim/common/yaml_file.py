"""One reader for the YAML files a user hands us (worlds, scenarios, ROS parameter files), which
may be hostile: every refusal is one line naming the file (and, where there is one, the key).

- only a regular file is opened (a FIFO, a device such as /dev/zero or a folder is refused before
  it is read; the file is opened non-blocking and checked again, so a swap cannot make it hang:
  `open_regular`, which map images are opened with too);
- at most `MAX_FILE_BYTES` (1 MiB) are read;
- the bytes must be UTF-8 (the refusal names the byte offset, and says so when it looks like UTF-16);
- the YAML event stream is checked before anything is built from it: at most `MAX_DEPTH` levels
  of nesting and at most `MAX_NODES` values with every alias expanded (aliases and merge keys stay
  usable, an alias bomb or a self-referencing alias is refused at the alias that blows the budget);
  a key given twice in one mapping is refused (YAML itself would keep the last one silently);
- then the document is built by the safe loader (libyaml's `CSafeLoader` where PyYAML has it).

`short()` shows a value in a message: one line and bounded, however large or deep the value is.
"""

from __future__ import annotations

import os
import reprlib
import stat
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, BinaryIO

import yaml

MAX_FILE_BYTES = 1 << 20
MAX_DEPTH = 64
MAX_NODES = 100_000
LOADER: type[Any] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

_REPR = reprlib.Repr()
_REPR.maxlevel, _REPR.maxlist, _REPR.maxtuple, _REPR.maxdict, _REPR.maxset = 3, 6, 6, 4, 4
_REPR.maxstring, _REPR.maxlong, _REPR.maxother = 50, 40, 50


class YamlFileError(ValueError):
    """A YAML file is unreadable, too large, not UTF-8, not YAML or too deep; one line for the user."""


def short(value: Any, limit: int = 60) -> str:
    """`repr(value)` bounded to `limit` characters and one line, computed without the whole repr."""
    try:
        text = _REPR.repr(value)
    except (ValueError, RecursionError):  # e.g. an int too long to print
        text = f"<{type(value).__name__}>"
    return text if len(text) <= limit else text[: limit - 3] + "..."


def one_line(text: str, limit: int = 100) -> str:
    """Free text (an OS or YAML error's words) as one bounded line."""
    flat = " ".join(str(text).split())
    return flat if len(flat) <= limit else flat[: limit - 3] + "..."


def shown_key(key: Any) -> str:
    """A mapping key as it goes into a message: plain when it is a short printable string."""
    return key if isinstance(key, str) and key.isprintable() and 0 < len(key) <= 40 else short(key, 40)


def file_label(path: str | Path) -> str:
    """A file name as it goes into a message (one line, at most 160 characters)."""
    text = str(path)
    if not text.isprintable():
        text = repr(text)[1:-1]
    return text if len(text) <= 160 else text[:60] + "..." + text[-97:]


def finite(value: Any) -> float | None:
    """`value` as a float when it is a finite number (not a bool, not an int beyond float range)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    try:
        f = float(value)
    except OverflowError:
        return None
    return f if f - f == 0.0 else None


def read_yaml(path: str | Path, what: str = "YAML file", error: type[ValueError] = YamlFileError) -> Any:
    """The document in `path`, read as the module docstring says; refusals raise `error` (one line)."""
    name = file_label(path)
    try:
        text = _decode(_read_bytes(Path(path), name, what), name)
        return _parse(text, name)
    except YamlFileError as e:
        raise error(str(e)) from None


class NotReadable(YamlFileError):
    """A file that is not opened (missing, not a regular file, too large); `reason` without the name."""

    def __init__(self, name: str, what: str, reason: str) -> None:
        super().__init__(f"{name}: cannot read {what}: {reason}")
        self.reason = reason


def open_regular(path: str | Path, what: str, max_bytes: int) -> BinaryIO:
    """`path` opened for reading only when it is a regular file of at most `max_bytes`: a FIFO, a
    device or a folder is refused (`NotReadable`, one line) before it is opened, and the file is
    opened non-blocking and checked again, so a FIFO swapped in meanwhile cannot make us hang."""
    name = file_label(path)
    try:
        _check_stat(os.stat(path), name, what, max_bytes)
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
        f = os.fdopen(fd, "rb")
        try:
            _check_stat(os.fstat(f.fileno()), name, what, max_bytes)  # the same file still, not a FIFO swapped in
        except BaseException:
            f.close()
            raise
    except NotReadable:
        raise
    except (OSError, ValueError) as e:
        raise NotReadable(
            name, what, one_line(e.strerror if isinstance(e, OSError) and e.strerror else str(e))
        ) from None
    return f


def _read_bytes(path: Path, name: str, what: str) -> bytes:
    with open_regular(path, what, MAX_FILE_BYTES) as f:
        try:
            data = f.read(MAX_FILE_BYTES + 1)
        except OSError as e:
            raise NotReadable(name, what, one_line(e.strerror or str(e))) from None
    if len(data) > MAX_FILE_BYTES:
        raise NotReadable(name, what, f"larger than {_mib(MAX_FILE_BYTES)}")
    return data


def _mib(n: int) -> str:
    return f"{n // (1 << 20)} MiB"


def _check_stat(st: os.stat_result, name: str, what: str, max_bytes: int) -> None:
    if not stat.S_ISREG(st.st_mode):
        raise NotReadable(name, what, "a folder" if stat.S_ISDIR(st.st_mode) else "not a regular file")
    if st.st_size > max_bytes:
        raise NotReadable(name, what, f"larger than {_mib(max_bytes)} ({st.st_size} bytes)")


def _decode(data: bytes, name: str) -> str:
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        # a BOM, or ASCII as UTF-16
        utf16 = data[:2] in (b"\xff\xfe", b"\xfe\xff") or b"\x00\x00\x00" in (data[0:6:2], data[1:6:2])
        hint = " (it looks like UTF-16: save it as UTF-8)" if utf16 else ""
        raise YamlFileError(f"{name}: not UTF-8 text: byte 0x{data[e.start]:02x} at offset {e.start}{hint}") from None


def _parse(text: str, name: str) -> Any:
    try:
        _check_events(text, name)
        return yaml.load(text, Loader=LOADER)
    except YamlFileError:
        raise
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        position = getattr(e, "position", None)  # a ReaderError (a character YAML does not allow) has no mark
        line = (
            mark.line + 1
            if mark is not None
            else text.count("\n", 0, position) + 1
            if isinstance(position, int)
            else None
        )
        where = f" at line {line}" if line is not None else ""
        problem = getattr(e, "problem", None) or getattr(e, "reason", None) or "invalid YAML"
        raise YamlFileError(f"{name}: YAML syntax error{where}: {one_line(problem)}") from None
    except ValueError as e:  # a value the constructor refuses, e.g. an integer of more than 4300 digits
        raise YamlFileError(f"{name}: invalid value: {one_line(str(e))}") from None
    except (RecursionError, MemoryError):
        raise YamlFileError(f"{name}: too large or too deeply nested to read") from None


@dataclass
class _Frame:
    """An open sequence or mapping in the event stream."""

    mapping: bool
    anchor: str | None
    children: int = 0  # values completed so far (a mapping's keys count)
    nodes: int = 1  # values in it with every alias expanded, itself included
    depth: int = 1
    key: str = ""  # a mapping's latest key
    keys: set[str] = field(default_factory=set)  # a mapping's keys so far


def _path(stack: list[_Frame]) -> str:
    """The key path of the value being read, e.g. walls[2].polygon."""
    parts = [(f".{f.key}" if f.children % 2 else "") if f.mapping else f"[{f.children}]" for f in stack]
    path = "".join(parts).lstrip(".") or "(top level)"
    return path if len(path) <= 80 else path[:30] + "..." + path[-47:]


def _new_key(stack: list[_Frame], key: str, name: str, line: int) -> None:
    """A mapping's next key; a key given twice is refused (YAML would keep the last one silently)."""
    mapping = stack[-1]
    if key in mapping.keys and key != "<<":
        where = _path(stack)
        shown = shown_key(key) if where == "(top level)" else f"{where}.{shown_key(key)}"
        raise YamlFileError(f"{name}: {shown}: given twice (line {line}); YAML would keep only the last")
    mapping.keys.add(key)
    mapping.key = shown_key(key)


def _check_events(text: str, name: str) -> None:
    """Nesting depth and expanded size from the event stream, before anything is built."""
    sizes: dict[str, tuple[int, int]] = {}  # anchor -> (values, depth) of what it names
    stack: list[_Frame] = []
    total = 0
    for event in yaml.parse(text, Loader=LOADER):
        line = event.start_mark.line + 1 if event.start_mark is not None else 0
        if isinstance(event, (yaml.SequenceStartEvent, yaml.MappingStartEvent)):
            if len(stack) >= MAX_DEPTH:
                raise YamlFileError(f"{name}: {_path(stack)}: nested deeper than {MAX_DEPTH} levels (line {line})")
            stack.append(_Frame(isinstance(event, yaml.MappingStartEvent), event.anchor))
            total += 1
            continue
        if isinstance(event, (yaml.SequenceEndEvent, yaml.MappingEndEvent)):
            done = stack.pop()
            nodes, depth, anchor = done.nodes, done.depth, done.anchor
        elif isinstance(event, yaml.AliasEvent):
            if any(f.anchor == event.anchor for f in stack):
                raise YamlFileError(
                    f"{name}: {_path(stack)}: alias *{shown_key(event.anchor)} refers to itself (line {line})"
                )
            nodes, depth = sizes.get(event.anchor or "", (1, 1))
            anchor = None
            if len(stack) + depth > MAX_DEPTH:
                raise YamlFileError(
                    f"{name}: {_path(stack)}: alias *{shown_key(event.anchor)} "
                    f"nests deeper than {MAX_DEPTH} levels (line {line})"
                )
            total += nodes
        elif isinstance(event, yaml.ScalarEvent):
            nodes, depth, anchor = 1, 1, event.anchor
            total += 1
            if stack and stack[-1].mapping and stack[-1].children % 2 == 0:
                _new_key(stack, event.value, name, line)
        else:
            continue
        if total > MAX_NODES:
            how = "its aliases expand the file to" if isinstance(event, yaml.AliasEvent) else "the file holds"
            raise YamlFileError(f"{name}: {_path(stack)}: {how} more than {MAX_NODES} values (line {line})")
        if anchor is not None:
            sizes[anchor] = (nodes, depth)
        if stack:
            parent = stack[-1]
            parent.children += 1
            parent.nodes += nodes
            parent.depth = max(parent.depth, depth + 1)
