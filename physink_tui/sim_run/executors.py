"""Executors: evaluate a generation of candidates and give the results in candidate order, not arrival order.

`Executor` is the interface the search driver uses: ``map(fn, items) -> list``. `SerialExecutor` runs in this
process; `ProcessExecutor` in a local ``concurrent.futures.ProcessPoolExecutor`` (fork where the platform has it:
workers start in milliseconds and inherit the imported modules; spawn elsewhere); `DaskExecutor`
(`physink_tui.sim_run.dask_executor`, the optional extra ``physink-tui[dask]``, ``--scheduler``) on a Dask cluster.
An executor that can send a value to its workers once rather than with every item (a cluster's) is also a
`SharingExecutor`. Executors only run what they are given: choosing candidates is the search's.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor
from typing import Any, Protocol, runtime_checkable


class Executor(Protocol):
    """Evaluates ``fn`` on every item; the results in the items' order."""

    def map(self, fn: Callable[[Any], Any], items: Sequence[Any]) -> list[Any]: ...

    def close(self, *, cancel: bool = False) -> None:
        """Frees the workers; ``cancel`` (after Ctrl-C) drops work still queued instead of waiting for it."""
        ...


@runtime_checkable
class SharingExecutor(Executor, Protocol):
    """An executor that ships a value all items share once, not with every item (the driver sends the search's
    problem this way; local executors have `share` instead)."""

    def map_shared(self, fn: Callable[[Any, Any], Any], shared: Any, items: Sequence[Any]) -> list[Any]:
        """``[fn(shared, item) for item in items]``, in the items' order."""
        ...


class SerialExecutor:
    """One item after the other, in this process."""

    workers = 1

    def map(self, fn: Callable[[Any], Any], items: Sequence[Any]) -> list[Any]:
        return [fn(item) for item in items]

    def close(self, *, cancel: bool = False) -> None:
        pass

    def __enter__(self) -> SerialExecutor:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


FORK = "fork" in multiprocessing.get_all_start_methods()
"""Worker processes are forked: what `share` holds when a pool starts is in every worker without pickling."""

_shared: dict[object, Any] = {}
_shared_version = 0


def share(key: object, value: Any) -> None:
    """Makes ``value`` reachable as ``shared(key)`` in worker processes started from now on (forked ones; a pool
    started before is restarted on its next `ProcessExecutor.map`). A rollout's problem (the scene and the
    demonstrated timeline with its trajectories) is sent this way once, not pickled with every candidate: pickling
    it per candidate made two workers slower than one."""
    global _shared_version
    _shared[key] = value
    _shared_version += 1


def unshare(key: object) -> None:
    """Forgets ``key`` in this process (workers already started keep their copy until their pool ends)."""
    _shared.pop(key, None)


def shared(key: object) -> Any:
    """What `share` put under ``key`` (in a forked worker: as it was when the pool started)."""
    return _shared[key]


def _context() -> multiprocessing.context.BaseContext:
    return multiprocessing.get_context("fork" if FORK else "spawn")


ORPHAN_POLL_S = 0.5
"""How often a worker looks whether the process that started it is still there."""


def _exit_when_orphaned(parent: int) -> None:
    while os.getppid() == parent:
        time.sleep(ORPHAN_POLL_S)
    os._exit(1)  # no cleanup to run: a worker holds nothing of the user's


def _start_worker(parent: int) -> None:
    """In a worker: Ctrl-C is the parent's to handle (it writes the best so far), not a traceback per worker; and a
    worker whose parent was killed (SIGKILL, SIGTERM) exits instead of waiting forever on a queue whose writing end
    it holds itself (forked workers inherit it, so it never reads end-of-file). ``parent`` is the pid the parent
    gave before starting the worker: a parent killed before this runs has already left the worker to init, whose pid
    ``os.getppid()`` would give here and then be watched forever."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if os.getppid() != parent:
        os._exit(1)
    threading.Thread(target=_exit_when_orphaned, args=(parent,), name="orphan-watch", daemon=True).start()


class ProcessExecutor:
    """``workers`` local processes (started on first use; they ignore Ctrl-C, which the parent handles, and exit when
    the parent is gone)."""

    def __init__(self, workers: int) -> None:
        if workers < 1:
            raise ValueError(f"workers is {workers}; expected at least 1")
        self.workers = workers
        self._pool: ProcessPoolExecutor | None = None
        self._version = -1

    def map(self, fn: Callable[[Any], Any], items: Sequence[Any]) -> list[Any]:
        if self._pool is not None and self._version != _shared_version:
            self.close()
        if self._pool is None:
            self._version = _shared_version
            self._pool = ProcessPoolExecutor(self.workers, mp_context=_context(), initializer=_start_worker,
                                             initargs=(os.getpid(),))
        return list(self._pool.map(fn, items))

    def close(self, *, cancel: bool = False) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=not cancel, cancel_futures=cancel)
            self._pool = None

    def __enter__(self) -> ProcessExecutor:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close(cancel=exc[0] is not None)
