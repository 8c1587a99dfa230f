"""benchmarks/bench_rollout.py on one small scene, in its own process (it wraps `World.step`): a table row whose
shares add up to at most the whole (a few seconds)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_one_scene_gives_one_row_of_shares() -> None:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    out = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_rollout.py"), "--scenes",
                          "bouncing_hits_b_once", "--repeats", "1", "--max-seconds", "1"],
                         capture_output=True, text=True, check=True, env=env, cwd=ROOT).stdout
    rows = [line for line in out.splitlines() if line.startswith("| bouncing_hits_b_once |")]
    assert len(rows) == 1
    cells = [c.strip() for c in rows[0].strip("|").split("|")]
    assert int(cells[1]) > 0
    shares = [int(c.rstrip("%")) for c in cells[3:6]]
    assert all(s >= 0 for s in shares) and sum(shares) <= 101
    assert float(cells[6]) > 0
