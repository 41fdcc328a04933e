"""Files written whole or not at all: a reader (or a study resumed after a crash or a full disk)
finds either the old content or all of the new, never a half-written or empty file.

The content goes to a hidden temporary file beside the target, is flushed to disk, and is renamed
over the target (`os.replace` is atomic within a file system); if anything fails on the way, the
temporary file is removed and the target is left as it was. A file that holds a secret is
written with `write_secret`: 0600 from its first byte, never through a symbolic link.
"""

from __future__ import annotations

import contextlib
import errno
import os
import secrets
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


class SymlinkRefused(OSError):
    """A secret was to be written where a symbolic link stands: it is written nowhere."""


def refuse_link(target: Path) -> None:
    """SymlinkRefused if `target` is a symbolic link (a secret is never written through one)."""
    if target.is_symlink():
        raise SymlinkRefused(
            f"{target} is a symbolic link: refusing to write a secret through it (remove the link, then try again)"
        )


def write_secret(path: str | Path, data: bytes, mode: int = 0o600) -> None:
    """A file that holds a secret (a key, a token, a session key): readable by its owner only
    (0600) from its first byte (`mode` 0o644 for the public half kept beside a secret: a
    certificate), whole or not at all, and never written through a symbolic link (SymlinkRefused,
    an OSError, when `path` is one: its target is left untouched).

    The content goes to a new file beside `path` created with O_CREAT|O_EXCL|O_NOFOLLOW and mode
    0600 (so no other user can open it, and no link planted in the folder is followed), is flushed
    to disk and renamed over `path`; os.replace renames over a link, it never follows it."""
    target = Path(path)
    refuse_link(target)
    tmp = target.with_name(f".{target.name}.{secrets.token_hex(8)}.tmp")
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | getattr(os, "O_CLOEXEC", 0), 0o600)
    try:
        os.fchmod(fd, mode)
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        refuse_link(target)  # (a link put there meanwhile is refused too, not replaced)
        os.replace(tmp, target)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def open_secret_log(path: str | Path) -> int:
    """A log that holds secrets (addresses with tokens), opened to append: created 0600, never
    through a symbolic link (SymlinkRefused); an existing log is made 0600. The file descriptor."""
    target = Path(path)
    refuse_link(target)
    try:
        fd = os.open(
            target, os.O_WRONLY | os.O_APPEND | os.O_CREAT | os.O_NOFOLLOW | getattr(os, "O_CLOEXEC", 0), 0o600
        )
    except OSError as e:
        if e.errno == errno.ELOOP:  # (a link put there meanwhile)
            raise SymlinkRefused(f"{target} is a symbolic link: refusing to write a secret through it") from None
        raise
    os.fchmod(fd, 0o600)
    return fd
