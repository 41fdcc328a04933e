"""The pages `haven serve` itself shows (web/study_server.py): the landing page with the study's
welcome and consent text, a participant's session page (it follows their runner from page to page
and ends with the completion code), and the researcher's list of every session. Plain HTML with the
suite's stylesheet; every text from a study file or a participant is escaped."""

from __future__ import annotations

import json
from collections.abc import Sequence
from html import escape
from typing import Any

from haven_scenarios.study.protocol import Study
from haven_scenarios.web.online_seats import LIVE

POLL_MS = 1000  # the session page asks its state this often


def _page(title: str, body: str, script: str = "") -> bytes:
    return (
        "<!doctype html><html lang=en><head><meta charset=utf-8>"
        '<meta name=viewport content="width=device-width, initial-scale=1">'
        f'<title>{escape(title)}</title><link rel=stylesheet href="/static/haven.css"></head>'
        f'<body class="online"><main class="online">{body}</main>{script}</body></html>'
    ).encode()


def landing(study: Study, panel_id: str, id_param: str, returning: bool = False, sig: str = "") -> bytes:
    """The study's welcome, its consent text to read, and the way in (a form that POSTs the panel's
    id and its link's signature, or a field for the id); for a participant who has joined before,
    the way back to where they were."""
    welcome = f"<p class=welcome>{escape(study.online.welcome)}</p>" if study.online.welcome else ""
    consent = f"<h2>Consent</h2><div class=consent>{escape(study.consent_text)}</div>" if study.consent_text else ""
    field = (
        f'<input type=hidden name="{escape(id_param)}" value="{escape(panel_id)}">'
        if panel_id
        else f'<label>Your participant id <input name="{escape(id_param)}" required autocomplete=off></label>'
    )
    button = "Continue where you left off" if returning else "Start the study"
    signed = f'<input type=hidden name=sig value="{escape(sig)}">' if sig else ""
    form = f'<form action="/join" method=post>{field}{signed}<button type=submit id=join>{button}</button></form>'
    if returning:
        return _page(f"Study {study.name}", f"<h1>Welcome back</h1><p>You have joined this study before.</p>{form}")
    note = (
        "<p class=small>You will be asked for your consent before anything is recorded.</p>"
        if study.consent_text
        else ""
    )
    return _page(f"Study {study.name}", f"<h1>Welcome</h1>{welcome}{consent}{form}{note}")


def message(title: str, text: str) -> bytes:
    return _page(title, f"<h1>{escape(title)}</h1><p id=message>{escape(text)}</p>")


def session(state_url: str) -> bytes:
    """A participant's home between pages: says what is happening and takes them on."""
    script = f"""<script>
const stateUrl = {json.dumps(state_url)};
window.havenSession = null;
async function poll() {{
  try {{
    const s = await (await fetch(stateUrl, {{cache: "no-store"}})).json();
    window.havenSession = s;
    document.getElementById("title").textContent = s.title;
    document.getElementById("message").textContent = s.text;
    const code = document.getElementById("code");
    code.hidden = !s.code;
    code.textContent = s.code || "";
    if (s.url) {{ location.href = s.url; return; }}
    if (s.state === "done" || s.state === "declined" || s.state === "failed") return;
  }} catch (e) {{
    document.getElementById("message").textContent = "Cannot reach the study server; trying again…";
  }}
  setTimeout(poll, {POLL_MS});
}}
poll();
</script>"""
    body = "<h1 id=title>One moment</h1><p id=message>Preparing your session…</p><p id=code class=code hidden></p>"
    return _page("Your session", body, script)


def researcher_list(study: Study, rows: Sequence[dict[str, Any]], capacity: int) -> bytes:
    """Every participant who has joined, live ones first, refreshed every 2 s."""
    head = ["panel id", "participant", "state", "now", "joined", "researcher console"]
    cells = []
    for r in rows:
        link = f'<a href="{escape(r["console"])}" target=_blank>open</a>' if r.get("console") else ""
        values = [escape(str(r[k])) for k in ("panel_id", "participant", "state", "now", "joined")]
        cells.append("<tr>" + "".join(f"<td>{v}</td>" for v in values) + f"<td>{link}</td></tr>")
    live = sum(r["state"] in LIVE for r in rows)
    table = "<table id=sessions><tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr>" + "".join(cells) + "</table>"
    body = f"<h1>Study {escape(study.name)}</h1><p>{live} of {capacity} places in use · {len(rows)} joined</p>{table}"
    return _page(f"{study.name}: sessions", body, "<script>setTimeout(() => location.reload(), 2000);</script>")
