"""`recognition.linalg_cores` calls numpy.linalg's private LAPACK gufuncs (``numpy.linalg._umath_linalg``) directly:
these fail loudly when a numpy upgrade moves them, and hold each function to numpy.linalg's own numbers to the bit and
to its errors (NaN in, LinAlgError out). Session 32 measured what it buys: 10-20 us a call under load, a few calls a
stroke (thickness, fit_line, fit_circle, fit_ellipse, fit_cubic, the polygon checks' side lines)."""

from __future__ import annotations

import numpy as np
import pytest

from physink_tui.scene.recognition import linalg_cores as lc

MOVED = ("numpy {v} no longer has numpy.linalg._umath_linalg or its error callbacks: linalg_cores has fallen back to "
         "numpy.linalg (the same numbers, slower); drop the private import, or find where numpy moved them")


def _arrays(seed: int, count: int = 60) -> list[np.ndarray]:
    """Stroke-like (n, 2) arrays, some strided views, some nearly collinear, a few with repeated rows."""
    rng = np.random.default_rng(seed)
    out = []
    for k in range(count):
        n = int(rng.integers(1, 400))
        pts = np.cumsum(rng.normal(size=(n, 2)), axis=0) * rng.uniform(1e-3, 1e3)
        if k % 5 == 0:
            pts[:, 1] = 1e-9 * pts[:, 0]  # a straight line
        if k % 7 == 0 and n > 3:
            pts[n // 2] = pts[n // 2 - 1]
        out.append(pts[::2] if k % 3 == 0 else pts)
    return out


def test_linalg_cores_uses_numpys_compiled_gufuncs() -> None:
    if lc._core is None:
        pytest.fail(MOVED.format(v=np.__version__))
    assert callable(lc._core.svd_s) and callable(lc._core.lstsq) and callable(lc._core.eig)


def test_svd_vt_is_numpys_to_the_bit() -> None:
    for a in _arrays(1):
        centred = a - a.mean(axis=0)
        assert np.array_equal(lc.svd_vt(centred), np.linalg.svd(centred, full_matrices=False)[2])


def test_lstsq_solution_is_numpys_to_the_bit() -> None:
    rng = np.random.default_rng(2)
    for a in _arrays(2):
        design = np.column_stack([a, np.ones(len(a))])
        one, two = a[:, 0] ** 2 + a[:, 1] ** 2, rng.normal(size=(len(a), 2))
        assert np.array_equal(lc.lstsq_solution(design, one), np.linalg.lstsq(design, one, rcond=None)[0])
        assert np.array_equal(lc.lstsq_solution(a, two), np.linalg.lstsq(a, two, rcond=None)[0])


def test_eig_vectors_and_solve_are_numpys_to_the_bit() -> None:
    rng = np.random.default_rng(3)
    for _ in range(300):
        m, b = rng.normal(size=(3, 3)), rng.normal(size=(3, 3))
        assert np.array_equal(lc.eig_vectors(m), np.real(np.linalg.eig(m)[1]))
        assert np.array_equal(lc.solve(m, b.T), np.linalg.solve(m, b.T))


def test_errors_are_numpys() -> None:
    bad = np.array([[1.0, np.nan], [2.0, 3.0], [4.0, 5.0]])
    with np.errstate(all="ignore"):  # as recognition calls them
        for call in (lambda: lc.svd_vt(bad), lambda: lc.eig_vectors(bad[:2]),
                     lambda: lc.solve(np.zeros((2, 2)), bad[1:]), lambda: lc.lstsq_solution(bad, bad[:, 1])):
            with pytest.raises(np.linalg.LinAlgError):
                call()


def test_the_fallback_gives_the_same_numbers(monkeypatch: pytest.MonkeyPatch) -> None:
    arrays = [a - a.mean(axis=0) for a in _arrays(4)]
    fast = [(lc.svd_vt(a), lc.lstsq_solution(a, a[:, 0] ** 2)) for a in arrays]
    monkeypatch.setattr(lc, "_core", None)
    slow = [(lc.svd_vt(a), lc.lstsq_solution(a, a[:, 0] ** 2)) for a in arrays]
    assert all(np.array_equal(f[0], s[0]) and np.array_equal(f[1], s[1]) for f, s in zip(fast, slow, strict=True))
