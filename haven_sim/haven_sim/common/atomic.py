"""Files written whole or not at all: a reader (or a study resumed after a crash or a full disk)
finds either the old content or all of the new, never a half-written or empty file.

The content goes to a hidden temporary file beside the target, is flushed to disk, and is renamed
over the target (`os.replace` is atomic within a file system); if anything fails on the way, the
temporary file is removed and the target is left as it was.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from pathlib import Path


@contextlib.contextmanager
def replacing(path: str | Path) -> Iterator[Path]:
    """`with replacing(p) as tmp:` write the new file to `tmp`; on leaving the block it becomes `p`."""
    target = Path(path)
    tmp = target.with_name(f".{target.name}.tmp")
    try:
        yield tmp
        with tmp.open("rb") as f:
            os.fsync(f.fileno())
        os.replace(tmp, target)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def write_text(path: str | Path, text: str) -> None:
    """`path` holds either its old content or all of `text` (UTF-8), however the process stops."""
    with replacing(path) as tmp:
        tmp.write_text(text, encoding="utf-8")


def write_bytes(path: str | Path, data: bytes) -> None:
    """`path` holds either its old content or all of `data`, however the process stops."""
    with replacing(path) as tmp:
        tmp.write_bytes(data)
