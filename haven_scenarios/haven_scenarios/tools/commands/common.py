"""What several subcommands share: argument types, the ROS options, running supervised nodes."""

from __future__ import annotations

import argparse
import difflib
import math
import sys
from collections.abc import Callable, Sequence
from pathlib import Path

from haven_scenarios.conduct.suite_processes import claim_ros_domain
from haven_scenarios.record.outsiders import WRITERS, allowable, watched
from haven_scenarios.run.domains import DOMAINS_ENV, MAX_DOMAIN_ID, Claim, DomainRange, parse_domains
from haven_scenarios.run.supervisor import ProcessSpec, Supervisor, node_argv, ros_environment
from haven_scenarios.study.conditions import SEED_MAX
from haven_scenarios.study.questionnaires import registered
from haven_sim.common import nodes


def add_dropout_options(group: argparse._ActionsContainer, default: str = "keep") -> None:
    """What a participant's drop-out during a trial does (study/presence.py)."""
    from haven_scenarios.study.presence import DEFAULT_RECONNECT_TIMEOUT_S, OnDisconnect

    group.add_argument(
        "--on-disconnect",
        choices=[p.value for p in OnDisconnect],
        default=OnDisconnect(default).value,
        help=(
            "a participant's page disconnects during the trial: keep running, "
            f"pause simulated time until they are back, or abort the trial (default {default})"
        ),
    )
    group.add_argument(
        "--reconnect-timeout",
        type=positive,
        default=DEFAULT_RECONNECT_TIMEOUT_S,
        metavar="S",
        help=f"with --on-disconnect pause: abort after S seconds away (default {DEFAULT_RECONNECT_TIMEOUT_S:g})",
    )


def add_tls_options(group: argparse._ActionsContainer) -> None:
    """`--tls-cert FILE --tls-key FILE`: serve the pages over HTTPS (web/tls.py)."""
    group.add_argument(
        "--tls-cert",
        default=None,
        metavar="FILE",
        help="serve HTTPS with this certificate (PEM; `haven cert` makes one)",
    )
    group.add_argument("--tls-key", default=None, metavar="FILE", help="the certificate's private key (PEM)")


def finite(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"must be a finite number, got {text}")
    return value


def positive(text: str) -> float:
    value = finite(text)
    if not value > 0:
        raise argparse.ArgumentTypeError(f"must be positive, got {text}")
    return value


INT64_MAX = 2**63 - 1  # a ROS integer parameter's range: every integer option may become one


def bounded_int(low: int, high: int = INT64_MAX) -> Callable[[str], int]:
    """An argparse type: an integer in low..high (checked before anything starts: a node would
    refuse it only once the suite is up)."""

    def parse(text: str) -> int:
        try:
            value = int(text) if len(text) <= 40 else None
        except ValueError:
            value = None
        if value is None:
            raise argparse.ArgumentTypeError(f"expected an integer, got {text[:40]!r}")
        if value < low or value > high:
            raise argparse.ArgumentTypeError(
                f"must be {'at least ' + str(low) if high == INT64_MAX else f'{low}..{high}'}, got {value}"
            )
        return value

    parse.__name__ = "integer"  # (argparse names the type in its messages)
    return parse


def allowed_topic(text: str) -> str:
    """An argparse type: a topic a run may open to outside publishers (record/outsiders.py), absolute."""
    topic = "/" + text.lstrip("/")
    why = allowable(topic)
    if why is None:
        return topic
    if not watched(topic):
        known = [t for t in WRITERS if "*" not in t and allowable(t) is None]
        close = difflib.get_close_matches(topic, known, n=1)
        why += (
            f" (did you mean {close[0]}?)"
            if close
            else f" (one of {', '.join(sorted(known))}, or /humans/<id>/cmd_vel)"
        )
    raise argparse.ArgumentTypeError(f"{text[:60]}: {why}")


def existing_file(text: str) -> str:
    p = Path(text)
    if not p.is_file():
        raise argparse.ArgumentTypeError(f"{text}: {'not a regular file' if p.exists() else 'no such file'}")
    return text


PORT = bounded_int(0, 65535)
SEED = bounded_int(0, SEED_MAX)


def add_ros_options(p: argparse.ArgumentParser, suite: bool = False) -> None:
    """`suite`: the command starts a suite, which takes a domain of its own (run/domains.py)."""
    own = (
        "the inherited one if no other HAVEN suite runs there, "
        "else a free one (said); given: refused if another suite holds it"
    )
    help = f"ROS_DOMAIN_ID for the nodes (default: {own if suite else 'inherited'})"
    p.add_argument("--domain-id", type=bounded_int(0, MAX_DOMAIN_ID), default=None, help=help)
    if suite:
        add_domains_option(p)
    p.add_argument("--network", action="store_true", help="allow DDS discovery beyond localhost")


def domain_range(text: str) -> DomainRange:
    """An argparse type: `--domains A-B` (run/domains.py)."""
    try:
        return parse_domains(text)
    except ValueError as e:
        raise argparse.ArgumentTypeError(str(e).removeprefix("--domains: ")) from None


def add_domains_option(p: argparse.ArgumentParser) -> None:
    """`--domains A-B`: the ROS domains the lab lets its suites take (else the environment's HAVEN_DOMAINS)."""
    p.add_argument(
        "--domains",
        type=domain_range,
        default=None,
        metavar="A-B",
        help=(
            f"take a ROS domain only from A..B (0..{MAX_DOMAIN_ID}), "
            f"never another; default: ${DOMAINS_ENV} if set, else any as above"
        ),
    )


def add_suite_options(p: argparse.ArgumentParser, sim: bool = False) -> None:
    """--params-file and --without (`haven sim` also runs Nav2's servers, which it may leave out)."""
    p.add_argument(
        "--params-file",
        type=existing_file,
        default=None,
        help="ROS parameter YAML for every node (e.g. an edited copy of haven.yaml)",
    )
    p.add_argument(
        "--without",
        nargs="+",
        default=[],
        choices=nodes.SIM_REPLACEABLE if sim else nodes.REPLACEABLE,
        metavar="NODE",
        help="leave out our mux, planner, controller or viz"
        + (" or the Nav2 servers (nav2)" if sim else "")
        + " (to run your own in their place)",
    )
    p.add_argument(
        "--processes",
        choices=nodes.PROCESS_LAYOUTS,
        default="one",
        help="the suite's nodes in one process (default), or each in its own (separate: to debug one node)",
    )


ROBOT_HELP = (
    "the robot: a name from `haven robots` or a robot YAML file (default: the scenario's robot: model, else turtlebot2)"
)


def add_robot_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("--robot", default=None, metavar="NAME|FILE", help=ROBOT_HELP)


def fail(message: str) -> int:
    """A usage or input error: one line, exit code 2."""
    print(f"haven: error: {message}", file=sys.stderr)
    return 2


def environment(args: argparse.Namespace) -> dict[str, str]:
    return ros_environment(network=args.network, domain_id=args.domain_id)


def claim(args: argparse.Namespace, ignore: Sequence[str] = ()) -> Claim:
    """`claim_ros_domain` for a command's options, set as `args.domain_id` for its nodes."""
    got = claim_ros_domain(args.domain_id, args.network, ignore, lambda line: print(line, flush=True), args.domains)
    args.domain_id = got.domain_id
    return got


def params_file(args: argparse.Namespace) -> str | None:
    return str(Path(args.params_file).resolve()) if getattr(args, "params_file", None) else None


def run_client(
    args: argparse.Namespace, name: str, module: str, params: dict[str, object], extra: Sequence[str] = ()
) -> int:
    """Run one client node against a running suite until it exits (or Ctrl-C); its exit code is ours."""
    with Supervisor(environment(args)) as sup:
        sup.install_signal_handlers()
        sup.start(ProcessSpec(name, node_argv(module, params, extra)))
        exited = sup.wait()
        sup.stop()
    return 1 if exited is None else exited.code


def add_questionnaire_option(group: argparse._ArgumentGroup) -> None:
    group.add_argument(
        "--questionnaire",
        nargs="+",
        default=None,
        metavar="SPEC",
        help=(
            "after the trial, each teleoperated participant's page asks these questionnaires in order: "
            f"registered ones ({', '.join(registered())}) or YAML files of Likert items; "
            "haven run waits for the answers (or the console's Skip questionnaires, or Ctrl-C)"
        ),
    )


def table(rows: list[list[str]]) -> str:
    """Rows of text as aligned columns, for the terminal."""
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows)
