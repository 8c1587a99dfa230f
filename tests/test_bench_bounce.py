"""benchmarks/bench_bounce.py: a --quick run measures bounces in the physics world and the calibrated model agrees."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_bounce.py"


def test_a_quick_run_prints_the_table_and_the_models_direction_error(capsys) -> None:
    spec = importlib.util.spec_from_file_location("bench_bounce", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    try:
        spec.loader.exec_module(module)
        assert module.main(["--quick"]) == 0
    finally:
        del sys.modules[spec.name]
    out = capsys.readouterr().out
    rows = [line for line in out.splitlines() if line.startswith(("| box", "| polygon"))]
    assert len(rows) == 4  # two surfaces, two angles, one speed, one friction
    worst = float(out.split("worst ")[1].split("°")[0])
    assert worst < 2.0, out
