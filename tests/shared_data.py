"""Where the real data made outside this project lives (../shared/data), and what a test does without it.

Tests that read people's strokes or real tablet captures call `shared_path`. Without the data a developer's
`pytest` skips them, saying why; `.ci/run` sets ``PHYSINK_REQUIRE_SHARED_DATA=1`` so that CI fails instead of
passing with hundreds of tests gone. ``PHYSINK_SHARED_DATA`` points elsewhere when the folder is not beside the
checkout.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

_CANDIDATES = (
    Path(os.environ["PHYSINK_SHARED_DATA"]) if os.environ.get("PHYSINK_SHARED_DATA") else None,
    Path(__file__).resolve().parents[2] / "shared" / "data",  # beside the checkout
    Path("/work/shared/data"),  # the workplace's copy, for clones made elsewhere on this machine
)


def shared_root() -> Path | None:
    """The first candidate folder that exists, else None."""
    return next((p for p in _CANDIDATES if p is not None and p.is_dir()), None)


def shared_path(*parts: str, module_level: bool = True) -> Path:
    """``../shared/data/<parts>``; skips the test (or module) when absent, or fails under
    ``PHYSINK_REQUIRE_SHARED_DATA=1``."""
    root = shared_root()
    path = root.joinpath(*parts) if root is not None else None
    if path is not None and path.exists():
        return path
    tried = ", ".join(str(p) for p in _CANDIDATES if p is not None)
    reason = f"shared data {'/'.join(parts)!r} not found (looked in {tried})"
    if os.environ.get("PHYSINK_REQUIRE_SHARED_DATA") == "1":
        pytest.fail(f"{reason}; CI needs it (PHYSINK_REQUIRE_SHARED_DATA=1)", pytrace=False)
    pytest.skip(reason, allow_module_level=module_level)
    raise AssertionError("unreachable")  # pytest.skip raises
