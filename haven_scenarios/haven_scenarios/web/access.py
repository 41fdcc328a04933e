"""Who may do what through the study's web pages: one role per page, one token per session.

A participant's page (`/participant/<id>`) may publish only that person's velocity, Start and
questionnaire answers (the web node checks the answers are that person's); the researcher console
(`/console`) may drive the robot through the velocity mux's teleop input, type the thought bubble's
text, start, stop or abort the trial, skip the questionnaires, and set the viz node's cue toggles. Every page, bundle
and WebSocket request must carry its role's token (in the URL, or the cookie the page sets): each
role's token is derived from the session's secret and the role, so a participant's address opens
their own page only: not the console, not another participant's avatar.
"""

from __future__ import annotations

import base64
import hashlib
import hmac
import re
import secrets
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from urllib.parse import urlsplit

from haven_sim.common import topics

CONSOLE = "console"
TWIST, STRING = "geometry_msgs/msg/Twist", "std_msgs/msg/String"
TOKEN_PARAM, TOKEN_COOKIE = "token", "haven_token_"  # the cookie's name ends with the role
TOKEN_ENV = "HAVEN_WEB_TOKEN"  # how `haven run --web` hands the session's secret to the web node
_ID = re.compile(r"^[A-Za-z0-9_]{1,64}$")  # a human id as ROS topic names allow it


def absolute(topic: str) -> str:
    return "/" + topic.lstrip("/")


@dataclass(frozen=True)
class Role:
    """A page's rights: `name` is a human id or CONSOLE; `publish` maps the topics it may publish
    on to their one allowed type; `parameters`: it may read and set the cue toggles."""

    name: str
    publish: Mapping[str, str] = field(default_factory=dict)
    parameters: bool = False

    @property
    def is_console(self) -> bool:
        return self.name == CONSOLE

    def may_publish(self, topic: str, schema_name: str) -> str | None:
        """None if allowed, else the one-line reason it is not."""
        wanted = self.publish.get(topic)
        if wanted is None:
            return f"{self.name} may not publish on {topic} (allowed: {', '.join(sorted(self.publish)) or 'nothing'})"
        if schema_name != wanted:
            return f"{topic} takes {wanted}, not {schema_name or 'an unnamed type'}"
        return None


# Handled by the web node, not ROS topics:
READY = "/haven/ready"  # a participant's Start (String: their id)
ANSWERS = "/haven/questionnaire"  # a participant's answers to one questionnaire (String: JSON, record/answers.py)
SKIP_QUESTIONNAIRES = "/haven/skip_questionnaires"  # the console ends the wait for answers (String, any)
# a participant page's frame rate, latency, input age (String: JSON, study/presence.py)
PAGE_REPORT = "/haven/page_report"
NOT_ROS = (READY, ANSWERS, SKIP_QUESTIONNAIRES, PAGE_REPORT)  # what pages send that the web node handles itself
PARTICIPANTS = "/haven/participants"  # to the pages: who is connected, what their pages report (String: JSON)


def participant_role(human: str) -> Role:
    return Role(
        human, {absolute(topics.human_cmd_vel(human)): TWIST, READY: STRING, ANSWERS: STRING, PAGE_REPORT: STRING}
    )


CONSOLE_ROLE = Role(
    CONSOLE,
    {
        absolute(topics.CMD_VEL_TELEOP): TWIST,
        absolute(topics.WIZARD_THOUGHT): STRING,  # {text, hold_s, everywhere} from the page (web/wizard.py)
        absolute(topics.TRIAL_CONTROL): STRING,
        SKIP_QUESTIONNAIRES: STRING,
    },
    parameters=True,
)


def roles(humans: Sequence[str]) -> dict[str, Role]:
    """The console and one participant page per teleoperated human; refuses ids a URL cannot carry."""
    bad = [h for h in humans if not _ID.match(h) or h == CONSOLE]
    if bad:
        raise ValueError(
            f"human id {bad[0]!r} cannot name a participant page (letters, digits and _ only, not 'console')"
        )
    return {CONSOLE: CONSOLE_ROLE, **{h: participant_role(h) for h in humans}}


def new_token() -> str:
    """A session's secret."""
    return secrets.token_urlsafe(16)


def role_token(secret: str, role: str) -> str:
    """The token of one role's page and socket in a session."""
    digest = hmac.new(secret.encode(), role.encode(), hashlib.sha256).digest()
    return base64.urlsafe_b64encode(digest[:16]).decode().rstrip("=")


def door_key(secret: str, role: str) -> str:
    """What the front door says first on each connection to a role's server (web/door_hello.py):
    derived from the session's secret like the tokens, but never given to a page."""
    return role_token(secret, f"front door/{role}")


@dataclass(frozen=True)
class Request:
    """What the front door reads of a request: which page or socket, and whether its token is right."""

    kind: str  # "page", "socket", "static", "robot_model", "favicon" or "" (not ours)
    role: str  # a human id, CONSOLE, or "" for static files
    rest: str  # the static file's name (the robot model's: its suffix)


ROBOT_MODEL_FILE = "model"
# + .glb/.gltf: the trial robot's glTF model (its look.model), the one file served from outside static/
ROBOT_MODEL_PATH = f"/robot/{ROBOT_MODEL_FILE}"


def route(path: str) -> Request:
    parts = [p for p in urlsplit(path).path.split("/") if p]
    if parts == ["favicon.ico"]:
        return Request("favicon", "", "")
    if parts == [CONSOLE]:
        return Request("page", CONSOLE, "")
    if len(parts) == 2 and parts[0] == "participant":
        return Request("page", parts[1], "")
    if parts == ["ws", CONSOLE]:
        return Request("socket", CONSOLE, "")
    if len(parts) == 3 and parts[:2] == ["ws", "participant"]:
        return Request("socket", parts[2], "")
    if (
        len(parts) == 2
        and parts[0] == ROBOT_MODEL_PATH.split("/")[1]
        and parts[1] in (f"{ROBOT_MODEL_FILE}.glb", f"{ROBOT_MODEL_FILE}.gltf")
    ):
        return Request("robot_model", "", parts[1].rsplit(".", 1)[1])
    if len(parts) == 2 and parts[0] == "static" and re.match(r"^[\w.-]+$", parts[1]) and not parts[1].startswith("."):
        return Request("static", "", parts[1])
    return Request("", "", "")


def token_of(query: Mapping[str, str], cookies: Mapping[str, str], role: str) -> str:
    """The token a request carries for a role: in the query, else in that role's cookie."""
    return query.get(TOKEN_PARAM, "") or cookies.get(TOKEN_COOKIE + role, "")


def cookie_tokens(cookies: Mapping[str, str]) -> list[str]:
    """Every role token in a request's cookies (the pages' code needs any one of them)."""
    return [v for n, v in cookies.items() if n.startswith(TOKEN_COOKIE)]


def token_ok(given: str, expected: str) -> bool:
    return bool(given) and hmac.compare_digest(given.encode(), expected.encode())


def urls(base: str, secret: str, humans: Sequence[str]) -> dict[str, str]:
    """The pages to open, each with its own role's token: each participant's and the console."""
    out = {h: f"{base}/participant/{h}?{TOKEN_PARAM}={role_token(secret, h)}" for h in humans}
    out[CONSOLE] = f"{base}/{CONSOLE}?{TOKEN_PARAM}={role_token(secret, CONSOLE)}"
    return out
