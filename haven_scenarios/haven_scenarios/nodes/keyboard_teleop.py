"""Drive a human avatar from this terminal: keys -> geometry_msgs/Twist on /humans/<human>/cmd_vel.

Works against `haven run --teleop` (or any running suite); the terminal is restored on exit. The
participant is told where the trial is when the client starts (the latched /haven/trial_status), then
their progress from the study log, and the client ends with the trial.
"""

from __future__ import annotations

import contextlib
import select
import sys
import termios
import time
import tty

from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import String

from haven_scenarios.teleop.keys import HELP, KeyMapper
from haven_scenarios.teleop.status import announce, joined
from haven_sim.common.events import EventError, EventKind
from haven_sim.nodes import conversions as conv, qos
from haven_sim.nodes.runner import declare, run_node


class KeyboardTeleop(Node):
    def __init__(self) -> None:
        super().__init__("keyboard_teleop")
        human = declare(self, "human", "h1")
        self.human = str(human)
        self.over = False
        self.keys = KeyMapper(speed_mps=declare(self, "speed_mps", 1.0))
        self.pub = self.create_publisher(Twist, f"humans/{human}/cmd_vel", qos.RELIABLE)
        if not sys.stdin.isatty():
            raise ValueError("keyboard teleop needs a terminal (stdin is not one)")
        self._saved = termios.tcgetattr(sys.stdin)
        tty.setcbreak(sys.stdin.fileno())
        print(f"teleop {human}: {HELP}", flush=True)
        self.create_subscription(String, "haven/events", self._on_event, qos.EVENTS)
        self._joined = False
        self.create_subscription(String, "haven/trial_status", self._on_status, qos.LATCHED)
        self.create_timer(0.05, self._tick)

    def _on_event(self, msg: String) -> None:
        try:
            e = conv.event_from_msg(msg)
        except EventError:
            return
        line = announce(e, self.human)
        if line is not None:
            print(f"\r{line}", flush=True)
        self.over = self.over or e.kind is EventKind.TRIAL_END

    def _on_status(self, msg: String) -> None:
        """Once, on joining (later changes come as events): where the trial is."""
        if self._joined:
            return
        self._joined = True
        line, over = joined(msg.data)
        if line is not None:
            print(f"\r{line}", flush=True)
        self.over = self.over or over

    def _tick(self) -> None:
        if self.over:
            raise SystemExit(0)
        now = time.monotonic()
        while select.select([sys.stdin], [], [], 0.0)[0]:
            key = sys.stdin.read(1)
            if key in ("x", ""):  # x, or the terminal is gone (end of input): stop
                raise SystemExit(0)
            self.keys.press(key, now)
        self.pub.publish(conv.twist_msg(self.keys.command(now)))

    def destroy_node(self) -> None:
        with contextlib.suppress(termios.error, OSError):  # the terminal is gone: nothing to restore
            termios.tcsetattr(sys.stdin, termios.TCSADRAIN, self._saved)
        super().destroy_node()


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(KeyboardTeleop, args))


if __name__ == "__main__":
    main()
