"""Runs a search's rollouts on a Dask distributed cluster (the optional extra ``physink-tui[dask]``); starts no
cluster of its own and does not choose the candidates.

`DaskExecutor` is an `Executor` like the local ones (``map(fn, items)``, results in the items' order) and a
`SharingExecutor`: ``map_shared(fn, shared, items)`` scatters ``shared`` (a search's problem: the scene and the
demonstrated timeline with its trajectories) to every worker once, then sends each task only its candidate and a
reference to that copy. Every task has its own key (``pure=False``), so two identical candidates are two rollouts,
counted as the search counts them.

Workers need physink-tui (the same version) importable. A worker evaluates one task at a time whatever its thread
count (the rollout caches of `physink_tui.sim.evaluate` are per process and not thread-safe): start workers with
one thread each and as many processes as cores (``dask worker ADDRESS --nworkers -1 --nthreads 1``).

``distributed`` is imported here only, when an executor is made, so nothing else needs the extra.
"""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable, Sequence
from typing import Any

from physink_tui.errors import SimulationError

CONNECT_SECONDS = 5.0
"""How long to try reaching a scheduler before giving up."""

INSTALL_HINT = "install physink-tui[dask] (pip install 'physink-tui[dask]')"

_one_at_a_time = threading.Lock()


def _call(fn: Callable[..., Any], *args: Any) -> Any:
    """On a worker: ``fn(*args)``, one call at a time in this process."""
    with _one_at_a_time:
        return fn(*args)


def _probe(distributed: Any, address: str, seconds: float) -> None:
    """Connects to ``address`` and asks the scheduler who it is, every wait bounded by ``seconds`` in all
    (connecting, the comm handshake, the first answer), on a thread of its own: a port that accepts and never
    answers, or answers something that is not Dask, is one `SimulationError`, and no half-made client is left
    behind to complain when it is collected."""
    outcome: list[BaseException | object] = []
    reached: list[bool] = []  # the TCP connection was made: what follows is the handshake and the answer

    async def ask() -> object:
        host, port = distributed.comm.get_address_host_port(address)
        _, writer = await asyncio.open_connection(host, port)  # the bare connection first, to tell the waits apart
        writer.close()
        reached.append(True)
        comm = await distributed.comm.connect(address, timeout=seconds)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    def run() -> None:
        try:
            outcome.append(asyncio.run(asyncio.wait_for(ask(), seconds)))
        except BaseException as exc:  # anything at all: it is reported below, in the caller's thread
            outcome.append(exc)

    thread = threading.Thread(target=run, name="dask-probe", daemon=True)
    thread.start()
    thread.join(seconds + 1.0)
    reply = outcome[0] if outcome else TimeoutError()
    if isinstance(reply, OSError | TimeoutError | asyncio.TimeoutError) and reached:
        raise SimulationError(f"no Dask scheduler answered at {address!r} within {seconds:g} s (something accepted "
                              "the connection and said nothing a scheduler says)")
    if isinstance(reply, OSError | TimeoutError | asyncio.TimeoutError):
        cause = f" ({reply.strerror or reply})" if isinstance(reply, OSError) and str(reply) else ""
        raise SimulationError(f"cannot reach the Dask scheduler at {address!r} within {seconds:g} s{cause}")
    if isinstance(reply, BaseException) or not (isinstance(reply, dict) and reply.get("type") == "Scheduler"):
        what = f"{type(reply).__name__}" if isinstance(reply, BaseException) else "an answer that is not a scheduler's"
        raise SimulationError(f"no Dask scheduler at {address!r}: something answered there, but not as a Dask "
                              f"scheduler ({what})")


class DaskExecutor:
    """Evaluates on the Dask cluster whose scheduler is at ``address`` (e.g. ``tcp://10.0.0.5:8786``), or on
    ``cluster`` (a ``distributed.LocalCluster`` or any object ``distributed.Client`` accepts; the caller closes
    it). Connects at once.

    Raises:
        SimulationError: the extra is not installed, or no scheduler answered at ``address`` within
            ``timeout`` seconds (`CONNECT_SECONDS` by default).
    """

    def __init__(self, address: str | None = None, *, cluster: Any = None, timeout: float | None = None) -> None:
        if (address is None) == (cluster is None):
            raise ValueError("give exactly one of address and cluster")
        try:
            import distributed
        except ImportError:
            raise SimulationError(f"--scheduler needs Dask: {INSTALL_HINT}") from None
        self.address = address if address is not None else getattr(cluster, "scheduler_address", repr(cluster))
        if address is not None:
            try:  # checked first: a Client given a malformed address hangs for seconds when it is collected
                distributed.comm.get_address_host_port(address)
            except ValueError as exc:
                raise SimulationError(f"{address!r} is not a Dask scheduler address like tcp://HOST:8786 "
                                      f"({exc})") from None
        seconds = CONNECT_SECONDS if timeout is None else timeout
        if address is not None:
            _probe(distributed, address, seconds)
        try:
            self._client = distributed.Client(address if address is not None else cluster, timeout=seconds,
                                              set_as_default=False)
        except (OSError, TimeoutError) as exc:
            raise SimulationError(f"cannot reach the Dask scheduler at {self.address!r} within {seconds:g} s "
                                  f"({exc})") from None
        except Exception as exc:  # something answered that is not a Dask scheduler (of this protocol version)
            raise SimulationError(f"no Dask scheduler at {self.address!r}: the connection failed with "
                                  f"{type(exc).__name__}: {exc}") from None
        self._shared: tuple[Any, Any] | None = None  # (value, its future on the cluster)
        self._pending: list[Any] = []
        try:  # the first answer: a worker to run the rollouts (without one, gathering would wait for ever)
            self._client.wait_for_workers(1, timeout=seconds)
        except Exception:
            self._client.close()
            raise SimulationError(f"the Dask scheduler at {self.address!r} has no worker (waited {seconds:g} s); "
                                  f"start some: dask worker {self.address} --nworkers -1 --nthreads 1") from None

    def map(self, fn: Callable[[Any], Any], items: Sequence[Any]) -> list[Any]:
        return self._run([fn] * len(items), items)

    def map_shared(self, fn: Callable[[Any, Any], Any], shared: Any, items: Sequence[Any]) -> list[Any]:
        """``[fn(shared, item) for item in items]`` on the cluster, ``shared`` sent to each worker once (again only
        when a call passes another object)."""
        if self._shared is None or self._shared[0] is not shared:
            self._release_shared()
            future = self._guard(lambda: self._client.scatter(shared, broadcast=True, hash=False))
            self._shared = (shared, future)
        future = self._shared[1]
        return self._run([fn] * len(items), [future] * len(items), items)

    def _run(self, *columns: Sequence[Any]) -> list[Any]:
        if not columns[-1]:
            return []
        self._pending = self._client.map(_call, *columns, pure=False)
        results = self._guard(lambda: self._client.gather(self._pending))
        self._pending = []  # kept until then, so that close(cancel=True) after Ctrl-C can cancel them
        return results

    def _guard(self, call: Callable[[], Any]) -> Any:
        try:
            return call()
        except OSError as exc:
            raise SimulationError(f"lost the Dask scheduler at {self.address!r} ({exc})") from None
        except ModuleNotFoundError as exc:
            raise SimulationError(f"a Dask worker of {self.address!r} cannot import {exc.name!r}: install "
                                  "physink-tui on every worker") from None

    def _release_shared(self) -> None:
        if self._shared is not None:
            self._shared[1].release()
            self._shared = None

    def close(self, *, cancel: bool = False) -> None:
        """Forgets this executor's tasks and shared values on the cluster and disconnects (the cluster stays up).
        ``cancel`` also cancels tasks still running (Ctrl-C)."""
        if cancel and self._pending:
            self._client.cancel(self._pending)
        self._pending = []
        self._release_shared()
        self._client.close()

    def __enter__(self) -> DaskExecutor:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close(cancel=exc[0] is not None)
