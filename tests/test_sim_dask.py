"""The Dask executor (the ``physink-tui[dask]`` extra) on a real `distributed.LocalCluster`: the same search as
the local executors, ``physink simulate --scheduler``, and the messages when Dask is missing or unreachable."""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import distributed
import pytest

from physink_tui.errors import SimulationError
from physink_tui.sim.evaluate import make_problem
from physink_tui.sim.search import Search
from physink_tui.sim_run import dask_executor
from physink_tui.sim_run.dask_executor import DaskExecutor
from physink_tui.sim_run.driver import run_search
from physink_tui.sim_run.executors import Executor, ProcessExecutor, SerialExecutor, SharingExecutor
from tests.sim_scenes import CANVAS, ball_floor_wall, demonstration, parameters
from tests.test_simulate_command import simulate

REPO = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="module")
def cluster() -> Iterator[distributed.LocalCluster]:
    """Two single-threaded worker processes (they start in about half a second)."""
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=40) as c:
        yield c


def search_with(executor: Executor, budget: int = 20) -> tuple:
    problem = make_problem(ball_floor_wall(), demonstration(), CANVAS)
    search = Search(problem.scene, problem.timeline, CANVAS, seed=7, budget=budget, start=parameters((100.0, 0.0)))
    with executor:
        run_search(search, problem, executor)
    return search.rollouts, search.exploded, search.best, search.best_score


def test_same_search_as_the_local_executors(cluster: distributed.LocalCluster) -> None:
    serial = search_with(SerialExecutor())
    processes = search_with(ProcessExecutor(2))
    dask = search_with(DaskExecutor(cluster=cluster))
    assert serial[0] <= 20
    assert dask == serial == processes


def test_keeps_order_and_identical_items_are_separate_tasks(cluster: distributed.LocalCluster,
                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    with DaskExecutor(cluster.scheduler_address) as executor:
        assert isinstance(executor, SharingExecutor)
        keys: list[str] = []
        client_map = executor._client.map

        def recording_map(*args, **kw):
            futures = client_map(*args, **kw)
            keys.extend(f.key for f in futures)
            return futures

        monkeypatch.setattr(executor._client, "map", recording_map)
        assert executor.map(abs, [3, -1, -1, -1, 2]) == [3, 1, 1, 1, 2]
        assert executor.map_shared(divmod, 7, [2, 2, 3, 2]) == [(3, 1), (3, 1), (2, 1), (3, 1)]
        assert executor.map(abs, []) == []
        assert len(keys) == len(set(keys)) == 9  # a task per item: identical ones are not merged into one


def test_the_problem_is_sent_once_per_search(cluster: distributed.LocalCluster,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    executor = DaskExecutor(cluster=cluster)
    scattered = []
    scatter = executor._client.scatter
    monkeypatch.setattr(executor._client, "scatter", lambda data, **kw: scattered.append(kw) or scatter(data, **kw))
    result = search_with(executor, budget=12)
    assert 1 < result[0] <= 12
    assert scattered == [{"broadcast": True, "hash": False}]


def test_simulate_with_a_scheduler_writes_what_one_worker_writes(tmp_path: Path,
                                                                 cluster: distributed.LocalCluster) -> None:
    files = []
    for name, extra in (("local", ["--workers", "1"]), ("dask", ["--scheduler", cluster.scheduler_address])):
        status, out = simulate(tmp_path, name, "--budget", "12", *extra)
        assert status == 0
        result = json.loads((out / "result.json").read_text())
        del result["wall_seconds"]
        files.append((result, (out / "timeline.json").read_text(), (out / "project.json").read_text()))
    assert files[0] == files[1]


def closed_port() -> str:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return f"tcp://127.0.0.1:{s.getsockname()[1]}"


def test_unreachable_scheduler_is_one_line_and_exit_1(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(dask_executor, "CONNECT_SECONDS", 1.0)  # nothing listens there: no wait would connect
    address = closed_port()
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "result.json").write_text("{}")
    status, out = simulate(tmp_path, "out", "--budget", "4", "--scheduler", address)
    assert status == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and address in err and "Traceback" not in err
    assert (out / "result.json").read_text() == "{}"  # the last run's files are left alone


@pytest.mark.parametrize("address", ["nonsense", "foo://host:1", "tcp://host:port"])
def test_malformed_address_is_one_line_before_any_connection(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                             monkeypatch: pytest.MonkeyPatch, address: str) -> None:
    def no_client(*args, **kwargs):
        raise AssertionError("a Client was made for a malformed address (it hangs for seconds when collected)")

    monkeypatch.setattr(distributed, "Client", no_client)
    assert simulate(tmp_path, "out", "--scheduler", address)[0] == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{address!r} is not a Dask scheduler address" in err


def test_scheduler_and_workers_exclude_each_other(tmp_path: Path) -> None:
    assert simulate(tmp_path, "o", "--workers", "2", "--scheduler", "tcp://127.0.0.1:1")[0] == 2


def test_without_the_extra_says_what_to_install(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed now raises ImportError
    with pytest.raises(SimulationError, match=r"physink-tui\[dask\]"):
        DaskExecutor("tcp://127.0.0.1:1")


def test_only_the_dask_executor_imports_dask() -> None:
    code = ("import sys; import physink_tui.commands.simulate, physink_tui.sim_run.driver, physink_tui.sim; "
            "print(sorted(m for m in sys.modules if m.split('.')[0] in ('dask', 'distributed')))")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(REPO), os.environ.get("PYTHONPATH")]))}
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, env=env,
                          check=True)
    assert done.stdout.strip() == "[]"
