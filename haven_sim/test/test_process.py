"""How HAVEN's children are started (runtime/process.py): whatever the parent ignores, a child stops
on Ctrl-C as it is told."""

import signal
import subprocess
import sys

import pytest

from haven_sim.runtime.process import die_with_parent

pytestmark = pytest.mark.integration  # (it starts processes)

CHILD = "import signal; print(signal.getsignal(signal.SIGINT) is signal.default_int_handler)"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="prctl is Linux's")
def test_a_child_of_a_parent_that_ignores_ctrl_c_still_takes_it():
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)  # (a background job of a script; a worker starting)
    try:
        plain = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True, check=True)
        ours = subprocess.run(
            [sys.executable, "-c", CHILD], capture_output=True, text=True, check=True, preexec_fn=die_with_parent()
        )
    finally:
        signal.signal(signal.SIGINT, previous)
    assert plain.stdout.strip() == "False"  # (the ignored signal is inherited across exec)
    assert ours.stdout.strip() == "True"
