"""How HAVEN's processes end: the signals that mean "stop cleanly", and children that die with
their supervisor however it ends (Linux's PR_SET_PDEATHSIG; elsewhere, the supervisor's own stop).
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
import signal
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import FrameType

# Every signal whose default action ends a process and that a process can catch: each one stops
# a node cleanly (the recorder closes its bag) and the supervisor with all its children.
STOP_SIGNALS = (
    signal.SIGINT,
    signal.SIGTERM,
    signal.SIGHUP,
    signal.SIGQUIT,
    signal.SIGUSR1,
    signal.SIGUSR2,
    signal.SIGALRM,
    signal.SIGXCPU,
)
PR_SET_PDEATHSIG = 1
SIG_DFL = 0  # the C value of a default disposition (signal.h)


@contextmanager
def on_stop_signals(handler: Callable[[int, FrameType | None], None], but: tuple[int, ...] = ()) -> Iterator[None]:
    """`handler` for every stop signal (less `but`) while the block runs, the previous handlers
    back after it. Main thread only. Installed explicitly, a handler also catches a SIGINT that the
    shell had ignored (a background job), which Python would otherwise leave ignored."""
    previous = {sig: signal.signal(sig, handler) for sig in STOP_SIGNALS if sig not in but}
    try:
        yield
    finally:
        for sig, old in previous.items():
            signal.signal(sig, old)


def interrupted(signum: int, frame: FrameType | None) -> None:
    """A stop signal as Ctrl-C (`on_stop_signals(interrupted)`): KeyboardInterrupt at once, a
    BaseException, so no `except Exception` on the way (a plugin's containment) swallows it, and
    the command's own `finally` blocks and KeyboardInterrupt handlers end it cleanly."""
    raise KeyboardInterrupt


def die_with_parent(sig: int = signal.SIGTERM) -> Callable[[], None] | None:
    """A `preexec_fn` that has the kernel send `sig` to the child when the process that started it
    ends, even by SIGKILL (SIGTERM: the child still stops cleanly); None where there is no prctl.
    The child also gets every stop signal at its default: an ignored one is inherited across exec,
    and a parent may be ignoring Ctrl-C (a background job of a script; run/workers.py while it
    starts a worker), yet its children must stop when they are told. libc is loaded here, before
    the fork, so the child only makes system calls."""
    if not sys.platform.startswith("linux"):
        return None
    libc = ctypes.CDLL(ctypes.util.find_library("c"), use_errno=True)
    prctl, set_handler = libc.prctl, libc.signal
    parent = os.getpid()

    def preexec() -> None:
        for stop in STOP_SIGNALS:
            set_handler(stop, SIG_DFL)
        prctl(PR_SET_PDEATHSIG, sig, 0, 0, 0)
        if os.getppid() != parent:  # the parent ended before the prctl: nobody would send it
            os.kill(os.getpid(), sig)

    return preexec
