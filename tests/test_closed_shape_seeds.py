"""The closed-shape pen benches' ``--seeds``: a range, or the names the other pen benches take; a bad value refused."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

BENCHMARKS = Path(__file__).resolve().parents[1] / "benchmarks"
sys.path.insert(0, str(BENCHMARKS))

import bench_closed_shapes  # noqa: E402


def test_seed_names_and_ranges_read_as_the_other_pen_benches_take_them() -> None:
    parser = bench_closed_shapes.family_bench_parser("a bench")
    assert bench_closed_shapes.chosen_seeds(parser.parse_args(["--seeds", "held"]))[0] == range(1000, 1030)
    assert bench_closed_shapes.chosen_seeds(parser.parse_args(["--seeds", "tune"]))[0] == range(0, 30)
    assert bench_closed_shapes.chosen_seeds(parser.parse_args(["--seeds", "3:5"])) == (range(3, 5), "seeds 3-4")
    assert bench_closed_shapes.chosen_seeds(parser.parse_args([]))[0] == range(0, 30)


@pytest.mark.parametrize("value", ["later", "5:2", "1:2:3"])
def test_a_bad_seed_value_is_refused_naming_it(value: str) -> None:
    run = subprocess.run([sys.executable, str(BENCHMARKS / "bench_box_bows.py"), "--seeds", value],
                         capture_output=True, text=True, check=False)
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert repr(value) in run.stderr and "--seeds" in run.stderr
