"""`haven serve STUDY`: the study for remote participants (web/study_server.py): a landing page,
a join link for recruitment panels (`/?participant=ID`), each participant's own `haven study run
--web` (at most --capacity at once; the others wait in line), a completion code or redirect at the
end, and the researcher's list of every session. Runs until Ctrl-C or SIGTERM, which stop every
participant's trial cleanly (each runs again when they come back)."""

from __future__ import annotations

import argparse
import re
from pathlib import Path

from haven_scenarios.study.presence import OnDisconnect
from haven_scenarios.study.protocol import study_names
from haven_scenarios.tools.commands.common import (
    PORT,
    add_domains_option,
    add_dropout_options,
    add_tls_options,
    bounded_int,
    existing_file,
    fail,
)
from haven_sim.runtime.process import interrupted, on_stop_signals

DEFAULT_PORT = 8080


def port_range(text: str) -> tuple[int, int]:
    m = re.fullmatch(r"(\d+)-(\d+)", text)
    if not m or not 1024 <= int(m.group(1)) <= int(m.group(2)) <= 65535:
        raise argparse.ArgumentTypeError(f"expected FIRST-LAST, ports 1024..65535, got {text!r}")
    return int(m.group(1)), int(m.group(2))


def query_key(text: str) -> str:
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]{0,63}", text):
        raise argparse.ArgumentTypeError(
            f"expected a query key of letters, digits and _ (such as PROLIFIC_PID), got {text!r}"
        )
    return text


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    from haven_scenarios.web.study_server import DEFAULT_CAPACITY

    serve = sub.add_parser(
        "serve", help="run a study for remote participants: landing page, panel ids, a completion code"
    )
    serve.add_argument("study", help=f"a study file, or a shipped study ({', '.join(study_names())})")
    serve.add_argument(
        "--dir",
        type=Path,
        default=None,
        help="the study's folder (default: studies/<study name> here); servers may share one",
    )
    serve.add_argument(
        "--host",
        default="127.0.0.1",
        help="the address to serve on (0.0.0.0: every interface; default this machine only)",
    )
    serve.add_argument(
        "--port",
        type=PORT,
        default=DEFAULT_PORT,
        help=f"the landing page's port (default {DEFAULT_PORT}; 0: any free one)",
    )
    serve.add_argument(
        "--capacity",
        type=bounded_int(1, 64),
        default=DEFAULT_CAPACITY,
        help=f"participants in a trial at once (default {DEFAULT_CAPACITY})",
    )
    serve.add_argument(
        "--trial-ports",
        type=port_range,
        default=None,
        metavar="FIRST-LAST",
        help="the trials' pages on these ports (default any)",
    )
    serve.add_argument(
        "--id-param",
        type=query_key,
        default="participant",
        help="the link's query key with the panel's id (default participant)",
    )
    add_tls_options(serve)
    add_dropout_options(serve, OnDisconnect.PAUSE.value)  # (a participant gone for good frees their place)
    serve.add_argument("--params-file", type=existing_file, default=None, help="ROS parameter YAML for every trial")
    add_domains_option(serve)
    serve.add_argument("--network", action="store_true", help="allow DDS discovery beyond localhost")
    serve.set_defaults(func=serve_cmd)


def serve_cmd(args: argparse.Namespace) -> int:
    from haven_scenarios.conduct.online_study import open_server  # (the server loads only for this command)

    names = (
        "host",
        "port",
        "capacity",
        "trial_ports",
        "id_param",
        "on_disconnect",
        "reconnect_timeout",
        "network",
        "domains",
    )
    try:
        server = open_server(
            args.study, args.dir, args.tls_cert, args.tls_key, args.params_file, **{n: getattr(args, n) for n in names}
        )
    except ValueError as e:  # (StudyError, ScenarioError and ParamsError are ValueErrors)
        return fail(str(e))
    except OSError as e:
        return fail(f"cannot write the study's folder: {e.strerror or e}")
    study, root = server.study, server.o.root
    server.start()
    try:
        with on_stop_signals(interrupted):
            print(
                f"serve: study {study.name} ({len(study.participants)} places, {args.capacity} at once; folder {root})",
                flush=True,
            )
            print(
                f"serve: participants join at {server.join_url} ({server.gate.rules()}: docs/howto/online-study.md)",
                flush=True,
            )
            print(f"serve: researcher's list: {server.console_url}", flush=True)
            server.server.wait()
    except KeyboardInterrupt:
        print("serve: stopping every participant's trial (each runs again when they come back)", flush=True)
    finally:
        server.stop()
    return 0
