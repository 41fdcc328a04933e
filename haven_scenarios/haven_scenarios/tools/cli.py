"""The `haven` command: starts HAVEN's nodes as plain Python processes and supervises them.

    haven sim  [--world W] [--rtf X] [--duration S]   simulator, mux, planner, controller, viz until Ctrl-C
    haven goto X Y [YAW]                              send a goal to a running suite, wait for arrival
    haven snapshot [OUT.png]                          save what the viewers show as a picture
    haven run [SCENARIO] [--participant ID] [--condition CUE...] [--rtf X] [--seed S] [--teleop [HUMAN...]]
                                                      one recorded trial -> a session folder
                       [--web [--host H] [--port P]]  ... with first-person participant pages and a researcher console
    haven teleop [HUMAN]                              drive a participant's avatar from the keyboard
    haven report SESSION... [--out CSV]               metrics recomputed from recordings
    haven repair SESSION...                           rebuild a bag its recorder never closed (killed, disk full)
    haven play SESSION [--rate R] [--hold]            a recorded session back on the graph (latched topics latched)
    haven topics | echo TOPIC | hz TOPIC              graph inspection without the ros2 command
    haven bridge [--host H] [--port P]                live Foxglove WebSocket view of a running suite
    haven batch SCENARIO --trials N --seed S          simulated trials without ROS, one CSV row each
    haven study plan|run|status|report STUDY          a whole study: schedule, a participant's trials, progress, tables
    haven demo [--world W] [--rtf X]                  the same plus a node that drives a square
    haven validate FILE...                            check world and scenario files without starting anything
    haven schema world|scenario|study|questionnaire|robot   a file kind's JSON Schema, for YAML editors
    haven plugins                                     the registered plugins: KIND NAME PACKAGE
    haven plugins new KIND NAME [--into DIR]          a plugin package to start from, with its test
    haven robots [NAME|FILE]                          the robots to choose from; one robot's figures and sources
    haven world show WORLD [--out PNG]                check a world file and draw it from above
    haven edit [WORLD] [--out DIR] [--host H] [--port P]   the world editor in the browser
    haven serve STUDY [--capacity N] [--host H] [--port P]  a study for remote participants (panel ids, completion code)

Discovery stays on this machine unless --network is given (study data stays local). Each group of
subcommands lives in `haven_scenarios.tools.commands`.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from typing import NoReturn


class Parser(argparse.ArgumentParser):
    """Usage errors in one line (naming the argument), with where to find the usage."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    from haven_scenarios.tools.commands import (
        batch_report,
        cert,
        clients,
        edit,
        files,
        recordings,
        robots,
        serve,
        study,
        suite,
        trial,
        world,
    )

    parser = Parser(prog="haven", description="HAVEN for ROS 2: AR-cue HRI studies with a simulated TurtleBot2.")
    sub = parser.add_subparsers(dest="command", required=True)
    for group in (suite, clients, trial, batch_report, study, recordings, files, robots, world, edit, cert, serve):
        group.add(sub)
    return parser


# Commands that run or check trials: a plugin left out is said first (one line each), so a lab
# sees why its item is missing before a name is refused or a trial runs without it.
TELLS_LEFT_OUT = frozenset({"sim", "demo", "run", "rerun", "batch", "study", "validate"})


def main(argv: Sequence[str] | None = None) -> int:
    try:  # Ctrl-C while the command modules still load (rclpy, numpy) is a plain stop, too
        args = build_parser().parse_args(argv)
        if args.command in TELLS_LEFT_OUT:
            from haven_sim.common import plugins

            for line in (p for reg in plugins.every() for p in reg.problems):
                print(f"haven: plugin left out: {line}", file=sys.stderr)
        code: int = args.func(args)
    except KeyboardInterrupt:
        print("haven: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # `haven study plan | head`: the reader has what it wanted
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())  # (so the interpreter's last flush cannot fail again)
        return 141  # 128 + SIGPIPE, as a shell reports a command ended by a closed pipe
    return code


if __name__ == "__main__":
    sys.exit(main())
