"""A study file's `online` key: what `haven serve` (web/study_server.py) shows a remote participant
and gives them at the end.

```yaml
online:
  welcome: |                      # the landing page: what the study is, how long, what they need
    In this study you walk past a robot in a virtual building (about 15 minutes; a keyboard).
  completion_code: C1A2B3         # shown when they are done: they paste it into the panel
  completion_url: https://app.prolific.com/submissions/complete?cc=C1A2B3   # or: their browser goes here
  join_limit: {places: 2, minutes: 60}   # new places one network address may take in that time (places 0: no limit)
  allowed_ids: panel_ids.txt      # only these ids may join (one a line; relative to the study file)
  link_secret_file: link_secret.txt   # signed links: the panel adds sig=HMAC-SHA256(secret, id); others are refused
```

Recruitment panels (Prolific, MTurk, SONA) append the participant's panel id to the study link and
take a completion code, or a redirect, back at the end (Palan & Schitter 2018, "Prolific.ac - A
subject pool for online experiments", J. Behav. Exp. Finance 17:22-27).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Annotated, TypeVar

from haven_scenarios.study.instruments import read_text
from haven_scenarios.study.names import check_name
from haven_sim.common.schema import FileModel, Positive, Whole, checked
from haven_sim.common.yaml_file import file_label, short

MAX_WELCOME_CHARS = 5_000
MAX_LIST_BYTES = 4 << 20  # an allow-list of ids: 4 MiB (some 100 000 panel ids)
MIN_SECRET_BYTES = 16  # a link secret: at least 128 bits (`python3 -c "import secrets; print(secrets.token_hex(32))"`)
E = TypeVar("E", bound=Exception)
CODE = re.compile(r"[A-Za-z0-9_-]{1,64}")


def _code(v: object) -> object:
    if not isinstance(v, str) or not (v == "" or CODE.fullmatch(v)):
        raise ValueError(f"must be 1..64 letters, digits, _ or -, got {short(v)}")
    return v


def _url(v: object) -> object:
    if not isinstance(v, str) or not (v == "" or re.fullmatch(r"https?://\S+", v)):
        raise ValueError(f"must be an http(s):// address, got {short(v)}")
    return v


def _welcome(v: object) -> object:
    if not isinstance(v, str) or len(v) > MAX_WELCOME_CHARS:
        raise ValueError(f"must be a text of at most {MAX_WELCOME_CHARS} characters")
    return v


def _file(v: object) -> object:
    if not isinstance(v, str) or "\0" in v or len(v) > 4096:
        raise ValueError(f"must be a file's path (relative to the study file), got {short(v)}")
    return v


class JoinLimit(FileModel):
    """How many new places one network address may take (web/online_gate.py): a link preview, a bot
    or a person trying ids cannot fill the study. A lab whose participants share one address (one
    campus NAT, a proxy in front of `haven serve`, a pilot from one PC) raises `places` or sets 0."""

    places: Whole(0, 999) = 2  # type: ignore[valid-type]  # new places per address within `minutes` (0: no limit)
    minutes: Positive(7 * 24 * 60) = 60.0  # type: ignore[valid-type]


class Online(FileModel):
    """`haven serve`'s texts, who may join, and the end of a participant's session (the module
    docstring shows one)."""

    welcome: Annotated[str, checked(_welcome)] = ""
    completion_code: Annotated[str, checked(_code)] = ""
    completion_url: Annotated[str, checked(_url)] = ""
    join_limit: JoinLimit = JoinLimit()
    # a file of the ids that may join, one a line ('#' starts a comment)
    allowed_ids: Annotated[str, checked(_file)] = ""
    link_secret_file: Annotated[str, checked(_file)] = ""  # signed links: the secret the panel signs each id with


def read_ids(path: str) -> frozenset[str]:
    """An allow-list file's ids (one a line; blank lines and '#' comments left out); ValueError
    (one line) for a file that cannot be read, an id that is not one, or no id at all."""
    ids = []
    for n, line in enumerate(read_text(Path(path), MAX_LIST_BYTES).splitlines(), 1):
        text = line.split("#", 1)[0].strip()
        if text:
            ids.append(check_name(text, f"{path} line {n}"))
    if not ids:
        raise ValueError(f"{path}: no participant id in it")
    return frozenset(ids)


def read_secret(path: str) -> bytes:
    """A link secret file's secret (its text without the line end); ValueError (one line) when
    others than its owner may read it or it is shorter than MIN_SECRET_BYTES."""
    if Path(path).exists() and Path(path).stat().st_mode & 0o077:
        raise ValueError(f"{path}: others can read this link secret: chmod 600 {path}")
    secret = read_text(Path(path), 4096).strip().encode()
    if len(secret) < MIN_SECRET_BYTES:
        raise ValueError(
            f"{path}: a link secret of at least {MIN_SECRET_BYTES} characters is needed, got {len(secret)}"
        )
    return secret


def resolved(online: Online | None, source: str, error: type[E]) -> Online:
    """A study file's `online` key with its files found (relative to the study file) and read
    once, so `haven validate` names a bad one; `error` (one line: file, key, problem) if not."""
    online = online or Online()
    paths = {}
    for key, read in (("allowed_ids", read_ids), ("link_secret_file", read_secret)):
        given = getattr(online, key)
        if given:
            path = Path(given) if Path(given).is_absolute() else Path(source).parent / given
            try:
                read(str(path))
            except ValueError as e:
                raise error(f"{file_label(source)}: online.{key}: {e}") from None
            paths[key] = str(path.resolve())
    return online.model_copy(update=paths)
