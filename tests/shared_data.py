"""Finds the shared data folder next to the repository, skipping the calling test module when it is absent."""

from __future__ import annotations

from pathlib import Path

import pytest

SHARED_DATA = Path(__file__).resolve().parents[2] / "shared" / "data"


def shared_path(*parts: str) -> Path:
    """The path under ``../shared/data``; skips the whole calling module, saying why, when it is missing.

    Call it at module level: ``HID = shared_path("hid")``.
    """
    path = SHARED_DATA.joinpath(*parts)
    if not path.exists():
        pytest.skip(f"shared data {str(path)!r} is not present (tests on real captures need it)",
                    allow_module_level=True)
    return path
