"""numpy.linalg's SVD, least squares, eigenvectors and solve on real float arrays, by LAPACK's compiled cores directly.

``np.linalg.svd``, ``lstsq``, ``eig`` and ``solve`` check and convert their arguments on every call (array wrapping,
type promotion, result named tuples: 15-25 us a call, as long as the LAPACK work itself on a stroke's 2-column arrays),
then call ``numpy.linalg._umath_linalg``'s gufuncs under an ``errstate`` that turns LAPACK's failures into
``LinAlgError``. Recognition calls them a few times a stroke on real (float) 2-D arrays only, so these call the same
gufuncs with the same signatures under the same ``errstate`` and checks, and return the same numbers to the bit
(tests/test_linalg_cores.py holds them to numpy.linalg's). Where a numpy release moves the private module, the public
functions are used instead: the same numbers, only slower.
"""

from __future__ import annotations

from typing import Any

import numpy as np

_core: Any = None  # numpy.linalg's compiled cores, where this numpy has them where this code looks (private)
try:  # and the callbacks that raise numpy.linalg's errors (tests/test_linalg_cores.py)
    from numpy.linalg import _linalg, _umath_linalg

    _raise_linalgerror_svd_nonconvergence = getattr(_linalg, "_raise_linalgerror_svd_nonconvergence")  # noqa: B009
    _raise_linalgerror_lstsq = getattr(_linalg, "_raise_linalgerror_lstsq")  # noqa: B009
    _raise_linalgerror_eigenvalues_nonconvergence = getattr(  # noqa: B009
        _linalg, "_raise_linalgerror_eigenvalues_nonconvergence")
    _raise_linalgerror_singular = getattr(_linalg, "_raise_linalgerror_singular")  # noqa: B009
    _core = _umath_linalg
except (ImportError, AttributeError):  # another numpy: the public functions, the same numbers
    pass

_EPS = float(np.finfo(np.float64).eps)


def _fast(a: np.ndarray, *more: np.ndarray) -> bool:
    """Whether the cores take these arrays as numpy.linalg would pass them: real floats (float64), 2-D."""
    return _core is not None and all(x.dtype == np.float64 for x in (a, *more)) and a.ndim == 2


def svd_vt(a: np.ndarray) -> np.ndarray:
    """``np.linalg.svd(a, full_matrices=False)[2]``: the right singular vectors, rows in order of singular value."""
    if not _fast(a):
        return np.linalg.svd(a, full_matrices=False)[2]
    with np.errstate(call=_raise_linalgerror_svd_nonconvergence, invalid="call", over="ignore", divide="ignore",
                     under="ignore"):
        _, _, vt = _core.svd_s(a, signature="d->ddd")
    out: np.ndarray = vt
    return out


def lstsq_solution(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``np.linalg.lstsq(a, b, rcond=None)[0]`` (``b`` one column or a 2-D array of columns)."""
    if not _fast(a, b) or b.ndim not in (1, 2) or len(a) != len(b) or (b.ndim == 2 and b.shape[1] == 0):
        public: np.ndarray = np.linalg.lstsq(a, b, rcond=None)[0]
        return public
    m, n = a.shape
    rhs = b[:, np.newaxis] if b.ndim == 1 else b
    with np.errstate(call=_raise_linalgerror_lstsq, invalid="call", over="ignore", divide="ignore", under="ignore"):
        x: np.ndarray = _core.lstsq(a, rhs, _EPS * max(n, m), signature="ddd->ddid")[0]
    if m == 0:
        x[...] = 0
    return x.squeeze(axis=-1) if b.ndim == 1 else x


def eig_vectors(a: np.ndarray) -> np.ndarray:
    """``np.real(np.linalg.eig(a)[1])``: the real parts of a square matrix's eigenvectors (columns)."""
    if not _fast(a) or a.shape[0] != a.shape[1]:
        return np.real(np.linalg.eig(a)[1])
    if not np.isfinite(a).all():
        raise np.linalg.LinAlgError("Array must not contain infs or NaNs")
    with np.errstate(call=_raise_linalgerror_eigenvalues_nonconvergence, invalid="call", over="ignore",
                     divide="ignore", under="ignore"):
        _, vt = _core.eig(a, signature="d->DD")
    out: np.ndarray = vt.real
    return out


def solve(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``np.linalg.solve(a, b)`` for a square ``a`` and a 2-D ``b`` (columns)."""
    if not _fast(a, b) or b.ndim != 2 or a.shape[0] != a.shape[1]:
        return np.linalg.solve(a, b)
    with np.errstate(call=_raise_linalgerror_singular, invalid="call", over="ignore", divide="ignore",
                     under="ignore"):
        out: np.ndarray = _core.solve(a, b, signature="dd->d")
    return out
