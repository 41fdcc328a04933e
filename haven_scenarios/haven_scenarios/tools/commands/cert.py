"""`haven cert [--dir DIR] [--name NAME ...]`: the lab's certificate authority (once) and a
certificate for this machine, so the pages can be served over HTTPS (web/tls.py;
docs/howto/https.md says how a headset trusts the authority)."""

from __future__ import annotations

import argparse
from pathlib import Path

from haven_scenarios.tools.commands.common import fail

DEFAULT_DIR = Path("tls")


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    cert = sub.add_parser(
        "cert", help="HTTPS for the pages: the lab's certificate authority and a certificate for this machine"
    )
    cert.add_argument(
        "--dir",
        type=Path,
        default=DEFAULT_DIR,
        help=f"where the files go (default: ./{DEFAULT_DIR}; the authority is kept if there)",
    )
    cert.add_argument(
        "--name",
        action="append",
        default=None,
        metavar="NAME",
        help=(
            "one more host name or IP address the pages are opened by, "
            "beside this machine's names and addresses (repeat)"
        ),
    )
    cert.set_defaults(func=cert_cmd)


def cert_cmd(args: argparse.Namespace) -> int:
    from haven_scenarios.web.tls import make_certificates, this_machines_names  # (cryptography loads only here)

    names = list(dict.fromkeys([*this_machines_names(), *(args.name or [])]))
    try:
        made = make_certificates(args.dir, names)
    except (ValueError, OSError) as e:
        return fail(str(e))
    said = "made" if made.new_ca else "kept"
    print(
        f"cert: the lab's certificate authority ({said}): "
        f"{made.ca_cert}  <- trust this once on each headset and browser"
    )
    print(f"cert: a certificate for {', '.join(names)}: {made.cert} (key {made.key})")
    print(f"cert: serve with  --tls-cert {made.cert} --tls-key {made.key}")
    return 0
