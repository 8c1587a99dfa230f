"""benchmarks/bench_simulate.py: its ratio rules, and a --quick run that rewrites a marked section (a few seconds)."""

from __future__ import annotations

import doctest
import importlib.util
import math
import sys
from pathlib import Path

import pytest

from physink_tui.sim.evaluate import EXPLODED_SCORE, Score

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_simulate.py"


@pytest.fixture(scope="module")
def bench():
    spec = importlib.util.spec_from_file_location("bench_simulate", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    try:
        spec.loader.exec_module(module)
        yield module
    finally:
        del sys.modules[spec.name]


def trace(*qualitative: float | None) -> list[Score]:
    """Scores with these qualitative distances (None: exploded)."""
    return [EXPLODED_SCORE if q is None else Score(q, 100.0) for q in qualitative]


def test_doctests(bench) -> None:
    assert doctest.testmod(bench).failed == 0


def test_ratio_is_grid_rollouts_over_default_rollouts_to_the_grids_lowest(bench) -> None:
    r = bench.ratio(trace(5, 4, 3, 2, 3, 2), trace(5, None, 2.0, 1))
    assert (r.target, r.grid_needs, r.default_needs, r.value, r.bound) == (2, 4, 3, 4 / 3, False)


def test_ratio_when_the_default_never_gets_there(bench) -> None:
    r = bench.ratio(trace(5, 1), trace(5, 2, None))
    assert r.value is None and r.default_needs is None and r.text.startswith("n/a")


def test_ratio_when_every_grid_rollout_exploded(bench) -> None:
    r = bench.ratio(trace(None, None), trace(5))
    assert r.target is None and r.value is None and r.text.startswith("n/a")


def test_ratio_is_a_bound_when_the_grid_never_beat_its_seed(bench) -> None:
    r = bench.ratio(trace(4, 4, 5, None), trace(4, 4.5, 3.75))
    assert r.bound and math.isclose(r.value, 4 / 3) and r.text.startswith(">")
    assert bench.ratio(trace(4, 6), trace(4, 4)).text == "1 (seed)"
    swept = bench.ratio(trace(4, 6), trace(4, 3), swept=True)
    assert swept.value == math.inf and swept.text.startswith("inf")


def test_quick_run_replaces_the_marked_section(bench, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    doc = tmp_path / "BENCHMARKS.md"
    doc.write_text(f"# before\n\n{bench.BEGIN}\nold numbers\n{bench.END}\n\n# after\n", encoding="utf-8")
    assert bench.main(["--quick", "--write", str(doc)]) == 0
    text = doc.read_text(encoding="utf-8")
    assert text.startswith("# before\n") and text.endswith(f"{bench.END}\n\n# after\n")
    assert "old numbers" not in text
    inside = text[text.index(bench.BEGIN) + len(bench.BEGIN):text.index(bench.END)]
    rows = [line for line in inside.splitlines() if line.startswith("| ") and not line.startswith("| scene")]
    assert [row.split(" | ")[0].removeprefix("| ") for row in rows] == list(bench.QUICK_SCENES)
    assert "World step vs raw pymunk:" in inside and "--quick --write" in inside
    assert inside.strip() in capsys.readouterr().out


def test_to_an_equivalent_counts_each_search_to_its_first_equivalent_simulation(bench) -> None:
    assert bench.to_equivalent(186, 193, False, 117) == (186 / 117, "1.59 (186 / 117)")
    value, text = bench.to_equivalent(None, 1226, True, 100)
    assert value == 12.26 and text.startswith("> 12.3") and "all 1226" in text  # a bound: the grid never got there
    assert bench.to_equivalent(36, 49, False, None) == (None, "grid only (36)")
    assert bench.to_equivalent(None, 400, False, None) == (None, "—")
