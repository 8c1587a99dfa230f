"""Runs the parameter search (`physink_tui.sim.search`) with an executor: serially or in local processes.

`run_search(search, problem, executor, progress)` asks the search for a generation, has the executor score it and
tells the scores back in candidate order, so a seed gives the same search whatever runs it (tested for all three
executors). An `Executor` is `map(fn, items)` and `close(cancel=)`:

- `executors.py`: the `Executor` protocol; `SerialExecutor` (`--workers 1`); `ProcessExecutor` (a local
  `ProcessPoolExecutor`, forked where possible, the default with one worker per core); `share`/`shared`: the
  driver's `Evaluate` pickles as the problem's key only, the problem itself reaching forked workers when the pool
  starts; `SharingExecutor`, the protocol of an executor that ships a value once itself (`map_shared(fn, shared,
  items)`)
- `dask_executor.py`: `DaskExecutor(address)` or `(cluster=)` (`--scheduler`, the optional extra `physink-tui[dask]`;
  `distributed` is imported nowhere else): before `distributed.Client` is made, `_probe` connects on a thread of its own
  and asks the scheduler for its identity, every wait bounded (the TCP connection, the comm handshake, the first
  answer): a port that accepts and never answers, or answers garbage, is one `SimulationError` and no half-made client
  is left; then a worker is awaited; `map_shared` scatters the problem to every worker once per search (`broadcast`),
  then each task carries only its candidate and the problem's future; every task has its own key (`pure=False`), so
  identical candidates are separate rollouts; a worker process evaluates one task at a time (the core's caches are per
  process, not thread-safe)
- `driver.py`: `Evaluate`, `run_search`: a `SharingExecutor` gets `evaluate_problem` and the problem under a fresh
  `uuid4` key (`Problem.key` counts per process, and a cluster's long-lived workers may serve searches from several
  processes, whose keys would collide in their caches); the others get an `Evaluate`

`physink simulate` connects to the scheduler before clearing the output folder, so an unreachable one leaves the
last run's files alone; `--workers` and `--scheduler` exclude each other (usage error).
"""
