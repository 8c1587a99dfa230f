"""Runs `physink kiosk --replay` in a subprocess and says when it began reading the capture (for the kill test and
the benchmark of the same)."""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

PHYSINK = [sys.executable, "-m", "physink_tui"]


def start_kiosk(out: Path, capture: Path, speed: float, video_size: str = "160x100") -> tuple[subprocess.Popen[str],
                                                                                             float]:
    """The kiosk, and the wall time (monotonic) at which it said it began reading the capture."""
    proc = subprocess.Popen([*PHYSINK, "kiosk", "--out", str(out), "--replay", str(capture), "--speed", str(speed),
                             "--video-size", video_size], stdout=subprocess.PIPE, text=True, bufsize=1)
    assert proc.stdout is not None
    for line in proc.stdout:
        if line.startswith("kiosk: reading the capture"):
            return proc, time.monotonic()
    raise RuntimeError(f"the kiosk ended before reading (status {proc.wait()})")
