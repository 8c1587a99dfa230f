"""benchmarks/bench_efficiency.py: its summary (needle-ness groups, ratios, per case), and a tiny run that rewrites a
marked section (one constructed case, one journal, a short grid; seconds, not figures)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCRIPT = ROOT / "benchmarks" / "bench_efficiency.py"


@pytest.fixture(scope="module")
def bench():
    sys.path.insert(0, str(SCRIPT.parent))
    spec = importlib.util.spec_from_file_location("bench_efficiency", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    try:
        spec.loader.exec_module(module)
        yield module
    finally:
        del sys.modules[spec.name]
        sys.path.remove(str(SCRIPT.parent))


def test_the_ratio_is_the_defaults_rollouts_over_the_grids_where_both_find_one(bench) -> None:
    row = bench.Row("a", "constructed", 0.02, 6, 17, 0.5, 24, 33, 1.0)
    assert row.ratio == 0.25
    assert bench.Row("b", "thesis", 0.0, 6, 17, 0.5, None, 3000, 80.0).ratio is None
    assert bench.Row("c", "thesis", None, None, 200, 9.0, 40, 48, 2.0).ratio is None


def test_the_summary_groups_by_needle_ness_and_lists_every_case(bench) -> None:
    rows = [bench.Row("easy", "constructed", 0.5, 1, 1, 0.1, 1, 1, 0.1),
            bench.Row("needle", "restored", 0.0, 40, 45, 2.0, 400, 401, 20.0),
            bench.Row("grid-only", "thesis", 0.0, None, 200, 9.0, 80, 81, 4.0)]

    class Args:
        budget, grid_budget, workers, load, commit, reuse = 200, 3000, 2, 1.0, "abc1234", None

    text = bench.summary(rows, Args, "bench_efficiency.py")
    lines = text.splitlines()
    none = next(line for line in lines if line.startswith("| none in the scan |"))
    assert none.split("|")[2:5] == [" 2 ", " 1 ", " 2 "]  # cases, default found, grid found
    assert "| 0.1 (0.1-0.1) |" in none  # 40 / 400, the one both find
    assert "only the grid in 1" in text and "commit abc1234" in text
    assert [line.split("|")[1].strip() for line in lines if line.startswith("| ") and "/" in line
            and line.split("|")[1].strip() in ("easy", "needle", "grid-only")] == ["easy", "needle", "grid-only"]


def test_a_tiny_run_writes_between_its_markers_and_a_second_reuses_its_grid(bench, tmp_path: Path) -> None:
    doc, rows = tmp_path / "B.md", tmp_path / "rows.jsonl"
    doc.write_text("before\n<!-- bench_efficiency -->\nold\n<!-- /bench_efficiency -->\nafter\n", encoding="utf-8")
    tiny = ["--possible", "3-3", "--springs", "", "--journals", "pinball", "--grid-budget", "16", "--scan", "2",
            "--workers", "1"]
    assert bench.main([*tiny, "--rows", str(rows), "--write", str(doc)]) == 0
    text = doc.read_text(encoding="utf-8")
    assert text.startswith("before\n<!-- bench_efficiency -->\nWritten ") and text.endswith(
        "<!-- /bench_efficiency -->\nafter\n")
    assert "| possible-3 |" in text and "| pinball |" in text and "old" not in text
    assert bench.main([*tiny, "--reuse", str(rows), "--recheck", "2", "--write", str(doc)]) == 0
    assert "gives the same rollouts on 2." in doc.read_text(encoding="utf-8")
