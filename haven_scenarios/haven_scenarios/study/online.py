"""A study file's `online` key: what `haven serve` (web/study_server.py) shows a remote participant
and gives them at the end.

```yaml
online:
  welcome: |                      # the landing page: what the study is, how long, what they need
    In this study you walk past a robot in a virtual building (about 15 minutes; a keyboard).
  completion_code: C1A2B3         # shown when they are done: they paste it into the panel
  completion_url: https://app.prolific.com/submissions/complete?cc=C1A2B3   # or: their browser goes here
```

Recruitment panels (Prolific, MTurk, SONA) append the participant's panel id to the study link and
take a completion code, or a redirect, back at the end (Palan & Schitter 2018, "Prolific.ac - A
subject pool for online experiments", J. Behav. Exp. Finance 17:22-27).
"""

from __future__ import annotations

import re
from typing import Annotated

from haven_sim.common.schema import FileModel, checked
from haven_sim.common.yaml_file import short

MAX_WELCOME_CHARS = 5_000
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


class Online(FileModel):
    """`haven serve`'s texts and the end of a participant's session (the module docstring shows one)."""

    welcome: Annotated[str, checked(_welcome)] = ""
    completion_code: Annotated[str, checked(_code)] = ""
    completion_url: Annotated[str, checked(_url)] = ""
