"""A search's worker processes: one whose parent is gone before it starts exits at once instead of waiting forever."""

from __future__ import annotations

import os
import subprocess
import sys

from tests.test_newer_commands_faults import ENV, ROOT

START = "import os; from physink_tui.sim_run.executors import _start_worker; _start_worker({parent}); print('alive')"


def _run(parent: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-c", START.format(parent=parent)], env=ENV, cwd=ROOT, capture_output=True,
                          text=True, timeout=120)


def test_a_worker_whose_parent_was_killed_before_it_started_exits() -> None:
    # The parent gave its pid, then was killed before the worker ran its start: the worker now has another parent
    # (init, or a subreaper). Watching that one would keep it alive forever (a killed `simulate --workers 2`).
    done = _run(str(os.getppid()))  # the pid of this test's parent: the child's grandparent, not its parent
    assert (done.returncode, done.stdout, done.stderr) == (1, "", "")


def test_a_worker_whose_parent_is_there_runs() -> None:
    done = _run("os.getppid()")
    assert (done.returncode, done.stdout.strip()) == (0, "alive"), done.stderr
