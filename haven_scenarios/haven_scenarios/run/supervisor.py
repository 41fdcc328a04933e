"""Starts node processes from plain Python (no launch files), watches them, and stops them all.

Each child runs in its own session, so a terminal's Ctrl-C reaches only the supervisor, which then
stops the children in order: SIGTERM (the nodes' clean shutdown; a node still importing just ends,
where SIGINT would print a KeyboardInterrupt traceback), then SIGKILL.
When one child exits on its own, the rest are stopped too: a study never runs half a suite.
No orphans, however the supervisor ends: any catchable stop signal (SIGHUP when the terminal or the
SSH session closes, too) is a stop request, and the kernel sends each child SIGTERM when the
supervisor dies of anything else (SIGKILL, a crash): PR_SET_PDEATHSIG.
"""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from importlib import resources
from types import FrameType, TracebackType
from typing import Any, TextIO, cast

from haven_sim.runtime.process import STOP_SIGNALS, die_with_parent


@dataclass(frozen=True)
class ProcessSpec:
    name: str
    argv: Sequence[str]
    env: Mapping[str, str] = field(default_factory=dict)
    cwd: str | None = None  # where it runs (a session's nodes run in the session folder)
    pass_fds: tuple[int, ...] = ()  # file descriptors it inherits (the recorder's end-of-trial pipe)


def node_argv(
    module: str,
    params: Mapping[str, object] | None = None,
    ros_args: Sequence[str] = (),
    params_file: str | None = None,
) -> list[str]:
    """Command line that runs a node module with this interpreter, a parameter file, and
    `-p name:=value` parameters (which come after the file, so they win)."""
    argv = [sys.executable, "-m", module, "--ros-args"]
    if params_file is not None:
        argv += ["--params-file", params_file]
    return argv + param_args(params or {}) + list(ros_args)


def param_args(params: Mapping[str, object]) -> list[str]:
    """`-p name:=value` for each parameter, as rcl reads them from a command line."""
    out = []
    for k, v in params.items():
        if isinstance(v, bool):
            v = "true" if v else "false"
        elif isinstance(v, (list, tuple)):
            v = "[" + ",".join(str(x) for x in v) + "]"
        out += ["-p", f"{k}:={v}"]
    return out


# Settings that would take discovery beyond this machine (an inherited discovery range is overridden).
NETWORK_REACHING = ("ROS_STATIC_PEERS", "ROS_DISCOVERY_SERVER")


def ros_environment(
    base: Mapping[str, str] | None = None, network: bool = False, domain_id: int | None = None
) -> dict[str, str]:
    """The environment for node processes: discovery on localhost unless `network`, and the
    quick-discovery Fast DDS profile unless the user chose one."""
    env = dict(os.environ if base is None else base)
    env["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "SUBNET" if network else "LOCALHOST"  # whatever the shell says
    if not network:
        for name in NETWORK_REACHING:
            env.pop(name, None)
    if domain_id is not None:
        env["ROS_DOMAIN_ID"] = str(domain_id)
    profile = resources.files("haven_sim") / "config" / "fastdds.xml"
    env.setdefault("FASTRTPS_DEFAULT_PROFILES_FILE", str(profile))
    env.setdefault("PYTHONUNBUFFERED", "1")
    return env


class Forgiving:
    """A text stream whose writes never raise (after SIGHUP a closed terminal answers EIO): the
    session is still finished and its files written when nobody can read the summary."""

    def __init__(self, stream: TextIO) -> None:
        self._stream = stream

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)

    def write(self, text: str) -> int:
        try:
            return self._stream.write(text)
        except OSError:
            return len(text)

    def flush(self) -> None:
        with contextlib.suppress(OSError):
            self._stream.flush()


@dataclass
class Exited:
    name: str
    code: int


class Supervisor:
    def __init__(self, env: Mapping[str, str] | None = None, grace_s: float = 5.0) -> None:
        self.env = dict(env) if env is not None else ros_environment()
        self.grace_s = grace_s
        self.procs: dict[str, subprocess.Popen[bytes]] = {}
        self.stopped: set[str] = set()  # children stopped on purpose while the others run on
        self._stop_requested = False
        self._preexec = die_with_parent()  # (haven starts no threads, so a preexec_fn is safe)

    def __enter__(self) -> Supervisor:
        return self

    def __exit__(self, et: type[BaseException] | None, ev: BaseException | None, tb: TracebackType | None) -> None:
        self.stop()

    def start(self, spec: ProcessSpec) -> subprocess.Popen[bytes]:
        env = {**self.env, **spec.env}
        proc = subprocess.Popen(
            list(spec.argv),
            env=env,
            cwd=spec.cwd,
            start_new_session=True,
            preexec_fn=self._preexec,
            pass_fds=spec.pass_fds,
        )
        self.procs[spec.name] = proc
        return proc

    def pids(self) -> dict[str, int]:
        return {n: p.pid for n, p in self.procs.items()}

    def poll(self) -> Exited | None:
        """The first child found to have exited, if any (of those not stopped on purpose)."""
        for name, proc in self.procs.items():
            code = None if name in self.stopped else proc.poll()
            if code is not None:
                return Exited(name, code)
        return None

    def request_stop(self, signum: int | None = None, frame: FrameType | None = None) -> None:
        self._stop_requested = True
        if signum == signal.SIGHUP:  # the terminal may be gone: what is still said must not fail
            sys.stdout, sys.stderr = cast(TextIO, Forgiving(sys.stdout)), cast(TextIO, Forgiving(sys.stderr))

    def install_signal_handlers(self) -> None:
        for sig in STOP_SIGNALS:
            signal.signal(sig, self.request_stop)

    def wait(
        self, timeout_s: float | None = None, until_exit_of: str | None = None, until: Callable[[], bool] | None = None
    ) -> Exited | None:
        """Block until a stop is requested, the timeout passes, `until()` holds, or a child exits
        (only `until_exit_of`, if given, when it exits cleanly); returns the child that ended it."""
        deadline = None if timeout_s is None else time.monotonic() + timeout_s
        while not self._stop_requested and not (until is not None and until()):
            exited = self.poll()
            if exited is not None and (until_exit_of is None or exited.name == until_exit_of or exited.code != 0):
                return exited
            if deadline is not None and time.monotonic() >= deadline:
                return None
            time.sleep(0.05)
        return None

    def stop(self, first: Sequence[str] = ()) -> dict[str, int]:
        """Stop every child that still runs (the ones named in `first` before the others, so
        they can still be heard while they stop); returns each child's exit code."""
        if first:
            self._stop([p for n, p in self.procs.items() if n in first])
        self._stop(list(self.procs.values()))
        return {n: p.wait() for n, p in self.procs.items()}

    def stop_some(self, names: Sequence[str]) -> None:
        """Stop these children now while the others run on (their exits no longer end a wait)."""
        self._stop([p for n, p in self.procs.items() if n in names])
        self.stopped.update(names)

    def _stop(self, procs: list[subprocess.Popen[bytes]]) -> None:
        for sig, wait_s in ((signal.SIGTERM, self.grace_s), (signal.SIGKILL, 2.0)):
            alive = [p for p in procs if p.poll() is None]
            if not alive:
                break
            for p in alive:
                with contextlib.suppress(ProcessLookupError):
                    os.killpg(p.pid, sig)
            deadline = time.monotonic() + wait_s
            while time.monotonic() < deadline and any(p.poll() is None for p in alive):
                time.sleep(0.02)
