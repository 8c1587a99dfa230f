"""benchmarks/bench_seeds.py: one search of a portfolio journal at a seed, reported as a row; seed ranges parsed."""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_seeds.py"


def test_one_search_is_a_row_and_seed_ranges_read_as_written(capsys: pytest.CaptureFixture[str]) -> None:
    spec = importlib.util.spec_from_file_location("bench_seeds", SCRIPT)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    try:
        spec.loader.exec_module(module)
        assert module.seed_range("0,3,5-7") == [0, 3, 5, 6, 7]
        assert module.main(["--one", "pinball:0", "--budget", "5", "--workers", "1"]) == 0
    finally:
        del sys.modules[spec.name]
    row = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    assert row["journal"] == "pinball" and row["seed"] == 0
    assert row["found_at"] == 1 and row["legs"] == row["of"] and row["rollouts"] <= 5  # the seed reproduces it
