"""Benchmark: the kiosk (issue 17) — how far behind the journal is when the kiosk is killed (wall-clock side), and
its memory over an hour of visitors replayed at 50x.

Usage: .venv/bin/python benchmarks/bench_kiosk.py [--kills 20] [--hours 1.0] [--speed 50]
       [--write docs/BENCHMARKS.md] [--quick]

- Kill lag: `physink kiosk --replay` of two visitors (tests/kiosk/visits.hid) at real speed, SIGKILLed at a random
  moment (seeded) and restarted, ``--kills`` times. At each kill: the last report the kiosk had read by then (from
  the wall time since it said it began reading, the capture being paced at 1x), against the last report in the
  journal; "behind" is the difference of their capture times, in ms (a report that a session never journals —
  hovering before the first touch, a tap on a hot zone — does not count as read). The test
  (tests/test_kiosk_crash.py) measures the same in input time at a quarter speed.
- Soak: ``--hours`` of input, visitors of about four minutes each (eight strokes 20 s apart, a demonstration, the
  end zone, a minute without the pen), replayed at ``--speed``; the kiosk's resident memory (VmRSS) is sampled
  every second. Reported: the first sample after the first session started, the largest, the last, and the
  growth per session over the second half of the run (a leak would show as a steady growth).

``--write FILE`` replaces what lies between ``<!-- bench_kiosk -->`` and ``<!-- /bench_kiosk -->`` in FILE.
"""

from __future__ import annotations

import argparse
import bisect
import json
import platform
import random
import shlex
import signal
import statistics
import sys
import tempfile
import time
from datetime import UTC, datetime
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from kiosk.captures import END, MODE, on_canvas, write_capture  # noqa: E402
from kiosk.process import start_kiosk  # noqa: E402

from physink_tui.formats.journal.entries import HidEntry  # noqa: E402
from physink_tui.formats.journal.reader import read_journal  # noqa: E402
from physink_tui.input.captures.capture import Capture  # noqa: E402
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen  # noqa: E402


def journaled(out: Path, names: set[str], sent: list[bytes]) -> list[int]:
    positions: list[int] = []
    for folder in sorted(p for p in out.iterdir() if p.is_dir() and p.name not in names):
        i = 0
        for e in read_journal(folder / "journal.physink.jsonl").entries:
            if isinstance(e, HidEntry):
                while sent[i] != e.data:
                    i += 1
                positions.append(i)
                i += 1
    return positions


def kill_lag(kills: int, work: Path) -> list[float]:
    capture = Capture.from_file(ROOT / "tests" / "kiosk" / "visits.hid")
    times = [e.t - capture.events[0].t for e in capture.events]
    sent = [e.data for e in capture.events]
    reference = work / "reference"
    proc, _ = start_kiosk(reference, ROOT / "tests" / "kiosk" / "visits.hid", 20.0)
    proc.wait()
    worthy = sorted(journaled(reference, set(), sent))
    worthy_times = [times[i] for i in worthy]
    rng = random.Random(17)
    out, behind = work / "kills", []
    out.mkdir()
    while len(behind) < kills:
        before = {p.name for p in out.iterdir()}
        proc, reading = start_kiosk(out, ROOT / "tests" / "kiosk" / "visits.hid", 1.0)
        time.sleep(rng.uniform(0.5, 8.0))
        read_by = time.monotonic() - reading
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        got = journaled(out, before, sent)
        read = bisect.bisect_right(worthy_times, read_by) - 1
        if read >= 0 and got:
            behind.append(1000.0 * max(0.0, worthy_times[read] - times[max(got)]))
    return behind


def visitor(k: int) -> list[Stroke]:
    """About three minutes of drawing: eight shapes, a demonstration, the end zone."""
    x = 0.1 + 0.1 * (k % 5)
    shapes = [Stroke.circle(on_canvas(x, 0.2), 0.04, aspect=1.6),
              Stroke.box(*on_canvas(0.05, 0.7), *on_canvas(0.6, 0.75))]
    shapes += [Stroke.box(*on_canvas(0.6 + 0.05 * (i % 3), 0.1 * i), *on_canvas(0.65 + 0.05 * (i % 3), 0.1 * i + 0.05))
               for i in range(1, 7)]
    return [*shapes, Stroke(MODE), Stroke((on_canvas(x, 0.2), on_canvas(x + 0.05, 0.5), on_canvas(x + 0.05, 0.68))),
            Stroke(END)]


def soak_capture(hours: float, path: Path) -> tuple[int, float]:
    pen = VirtualPen(REFERENCE_DEVICES["uclogic-v1"], seed=5)
    devices, events, t, k = None, [], 0.0, 0
    while t < hours * 3600:
        capture = pen.record(visitor(k), start_t=t, gap_s=20.0)
        devices, k = capture.devices, k + 1
        events.extend(capture.events)
        t = capture.events[-1].t + 60.0
    assert devices is not None
    write_capture(Capture(devices, tuple(events)), path)
    return k, t


def rss_mb(pid: int) -> float | None:
    try:
        for line in Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    except OSError:
        return None
    return None


def soak(hours: float, speed: float, work: Path) -> dict[str, float]:
    path = work / "soak.hid"
    count, seconds = soak_capture(hours, path)
    out = work / "soak"
    proc, _ = start_kiosk(out, path, speed, "320x200")
    samples: list[tuple[float, float, int]] = []  # (wall s, MB, sessions finished)
    began = time.monotonic()
    while proc.poll() is None:
        mb = rss_mb(proc.pid)
        done = len((out / "index.jsonl").read_text().splitlines()) if (out / "index.jsonl").exists() else 0
        if mb is not None:
            samples.append((time.monotonic() - began, mb, done))
        time.sleep(1.0)
    wall = time.monotonic() - began
    records = [json.loads(line) for line in (out / "index.jsonl").read_text().splitlines()]
    half = [s for s in samples if s[2] >= len(records) // 2]
    growth = (half[-1][1] - half[0][1]) / max(1, half[-1][2] - half[0][2]) if len(half) > 1 else 0.0
    return {"visitors": count, "input_s": seconds, "wall_s": wall, "sessions": len(records),
            "first_mb": samples[0][1], "max_mb": max(s[1] for s in samples), "last_mb": samples[-1][1],
            "growth_mb_per_session": growth, "status": proc.returncode}


def report(behind: list[float], soaked: dict[str, float], argv: list[str]) -> str:
    now = datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")
    lines = [f"Measured {now}: `benchmarks/bench_kiosk.py {shlex.join(argv)}`; CPython "
             f"{platform.python_version()}, {platform.machine()}.", ""]
    if behind:
        lines.append(f"SIGKILL at {len(behind)} random moments of a 1x replay of tests/kiosk/visits.hid: the journal "
                     f"was behind what had been read by median {statistics.median(behind):.0f} ms, at most "
                     f"{max(behind):.0f} ms (goal: at most 100 ms).")
    if soaked:
        s = soaked
        lines.append(f"Soak: {s['input_s'] / 3600:.2f} h of input ({s['visitors']} visitors of about four minutes) "
                     f"replayed in {s['wall_s']:.0f} s, {s['sessions']} sessions written, exit {s['status']}; resident "
                     f"memory {s['first_mb']:.0f} MB at the start, {s['max_mb']:.0f} MB at most, {s['last_mb']:.0f} "
                     f"MB at the end, {s['growth_mb_per_session']:+.2f} MB a session over the second half (goal: flat, "
                     "under 200 MB).")
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kills", type=int, default=20)
    parser.add_argument("--hours", type=float, default=1.0)
    parser.add_argument("--speed", type=float, default=50.0)
    parser.add_argument("--write", metavar="FILE")
    parser.add_argument("--quick", action="store_true", help="3 kills and 0.1 h (for the benchmark's own test)")
    args = parser.parse_args()
    if args.quick:
        args.kills, args.hours = 3, 0.1
    with tempfile.TemporaryDirectory() as tmp:
        behind = kill_lag(args.kills, Path(tmp)) if args.kills else []
        soaked = soak(args.hours, args.speed, Path(tmp)) if args.hours > 0 else {}
    text = report(behind, soaked, sys.argv[1:])
    print(text)
    if args.write:
        target = Path(args.write)
        doc = target.read_text()
        start_mark, end_mark = "<!-- bench_kiosk -->", "<!-- /bench_kiosk -->"
        if start_mark in doc:
            head, _, rest = doc.partition(start_mark)
            _, _, tail = rest.partition(end_mark)
            doc = f"{head}{start_mark}\n{text}\n{end_mark}{tail}"
        else:
            doc += f"\n## Kiosk (issue 17)\n\n{start_mark}\n{text}\n{end_mark}\n"
        target.write_text(doc)
    return 0


if __name__ == "__main__":
    sys.exit(main())
