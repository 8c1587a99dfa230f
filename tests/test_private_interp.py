"""`stroke_geometry.resample` calls numpy's private compiled ``interp`` (``numpy._core.multiarray.interp``, what
``np.interp`` calls after its checks): these fail loudly when a numpy upgrade removes it or changes its numbers, and
hold the public fallback to the same numbers to the bit. Session 29 measured what it buys: 2.6 us a call under load
(4.8 against 7.4 us), two calls a resample, about eleven resamples a stroke, some 1-2 % of a recognition."""

from __future__ import annotations

import numpy as np
import pytest

from physink_tui.scene.recognition import stroke_geometry as sg

MOVED = ("numpy {v} no longer has numpy._core.multiarray.interp: stroke_geometry.resample has fallen back to np.interp "
         "(the same numbers, about 2 us a call slower); drop the private import, or find where numpy moved it")


def _cases() -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Targets, knots (non-decreasing, some repeated: steps of no length) and values, as `resample` passes them (a
    column of an (n, 2) array: a strided view), at and beyond the ends too."""
    rng = np.random.default_rng(29)
    out = []
    for n in (1, 2, 3, 17, 200, 4000):
        pts = np.cumsum(rng.normal(size=(n, 2)), axis=0)
        if n > 3:
            pts[n // 2] = pts[n // 2 - 1]  # a repeated point: two equal knots
        cum = sg.along(pts)
        targets = np.concatenate([sg.spaced(float(cum[-1]), 64) if cum[-1] > 0 else np.zeros(3),
                                  [-1.0, cum[-1] + 1.0, *cum[:5]]])
        out.append((targets, cum, pts[:, 0]))
        out.append((targets, cum, pts[:, 1]))
    return out


def test_resample_uses_numpys_compiled_interp() -> None:
    if sg._interp is np.interp:
        pytest.fail(MOVED.format(v=np.__version__))
    assert callable(sg._interp) and sg._interp.__name__ == "interp"


@pytest.mark.parametrize("case", range(12))
def test_the_private_interp_gives_np_interps_numbers_to_the_bit(case: int) -> None:
    targets, cum, values = _cases()[case]
    assert np.array_equal(sg._interp(targets, cum, values), np.interp(targets, cum, values))


def test_resample_with_the_fallback_gives_the_same_points(monkeypatch: pytest.MonkeyPatch) -> None:
    rng = np.random.default_rng(5)
    strokes = [(np.cumsum(rng.normal(size=(int(rng.integers(2, 300)), 2)), axis=0), int(rng.integers(2, 200)))
               for _ in range(200)]
    fast = [sg.resample(pts, n) for pts, n in strokes]
    monkeypatch.setattr(sg, "_interp", np.interp)
    assert all(np.array_equal(sg.resample(pts, n), a) for (pts, n), a in zip(strokes, fast, strict=True))
