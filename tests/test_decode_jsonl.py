"""The bulk JSON-lines formatter writes, byte for byte, what ``json.dumps`` of each sample gave."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from shared_data import shared_path

from physink_tui.commands.decode import decode_capture, read_capture
from physink_tui.commands.decode_jsonl import format_jsonl
from physink_tui.errors import PhysinkError
from physink_tui.input.hid.batch import PenColumns

HID_DIR = shared_path("hid", module_level=True)


def _old_lines(cols: PenColumns) -> str:
    """The per-sample ``json.dumps`` formatter `physink decode` used before (the reference)."""
    def tilt(v: float) -> float | None:
        return None if math.isnan(v) else round(v, 2)

    out = []
    for i in range(len(cols)):
        out.append(json.dumps({
            "t": round(float(cols.t[i]), 6), "x": round(float(cols.x[i]), 6), "y": round(float(cols.y[i]), 6),
            "p": round(float(cols.p[i]), 6), "tip": bool(cols.tip[i]), "range": bool(cols.range[i]),
            "eraser": bool(cols.eraser[i]), "b1": bool(cols.b1[i]), "b2": bool(cols.b2[i]),
            "tilt_x": tilt(float(cols.tilt_x[i])), "tilt_y": tilt(float(cols.tilt_y[i])),
            "report": int(cols.report[i]),
        }) + "\n")
    return "".join(out)


@pytest.mark.parametrize("path", sorted(HID_DIR.glob("*.hid")), ids=lambda p: p.name)
def test_same_bytes_as_json_dumps_on_shared_captures(path) -> None:
    try:
        results = decode_capture(read_capture(str(path)))
    except PhysinkError:
        return  # a capture with no pen report is a one-line PhysinkError: nothing to format, which is right
    for _, _, cols in results:
        new = format_jsonl(cols)
        old = _old_lines(cols)
        assert new == old
        assert [json.loads(line) for line in new.splitlines()] == [json.loads(line) for line in old.splitlines()]


def _cols(**values: list) -> PenColumns:
    n = len(values["t"])
    f = {k: np.asarray(values.get(k, [0.0] * n), dtype=float) for k in ("t", "x", "y", "p", "tilt_x", "tilt_y")}
    b = {k: np.asarray(values.get(k, [False] * n), dtype=bool) for k in ("tip", "range", "eraser", "b1", "b2")}
    return PenColumns(**f, **b, report=np.full(n, 7, np.uint8), index=np.arange(n))


def test_edge_values_match_json_dumps() -> None:
    cols = _cols(t=[0.0, 1e-7, 0.0000049, 1234567.1234565, 2.5e-5], x=[-0.0, 1.0, 0.1 + 0.2, 1e-6, 0.5],
                 p=[float("nan"), float("inf"), 0.3333335, 0.0, 1.0],
                 tilt_x=[float("nan"), 12.345, -60.0, 0.005, 1e-3],
                 tilt_y=[float("nan")] * 5, tip=[True, False, True, False, True], b2=[False, True, False, True, True])
    assert format_jsonl(cols) == _old_lines(cols)
    assert format_jsonl(_cols(t=[])) == ""


def test_random_values_at_every_scale_match_json_dumps() -> None:
    rng = np.random.default_rng(11)
    values = np.concatenate([rng.random(3000), rng.random(3000) * 10.0 ** rng.integers(-9, 10, 3000),
                             np.round(rng.random(3000) * 1e4, 6), rng.integers(0, 4096, 3000) / 4095])
    cols = _cols(t=values, x=values[::-1].copy(), p=values, tilt_x=(values - 0.5) * 120)
    assert format_jsonl(cols) == _old_lines(cols)


def test_times_made_from_integers_match_json_dumps() -> None:
    stamps = [-0.0, 0.0, 0.0001, 0.00009, 0.000001, 999999999.999999, 1e9, 5.0, 0.1, 128.75182, 1e-4 + 1e-10,
              float("nan"), float("inf"), 3.0000005, 12345.000010]
    cols = _cols(t=stamps)
    assert format_jsonl(cols) == _old_lines(cols)
