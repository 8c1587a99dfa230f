"""Benchmark: from a HID report arriving to its gesture update, and CPU use at a tablet's report rate.

A writer thread plays a virtual-pen capture into a pipe at a fixed report rate (1 kHz, then 200 Hz),
the real `HidrawReader` thread reads it (select, read, monotonic timestamp, queue), and the consumer
(the main thread) decodes, maps and follows the pen to gestures, exactly as the session will. The
latency of a report is the consumer's clock when its gestures are ready minus the writer's clock
just before the write: it includes the pipe, the reader thread, the queue hand-over, decoding and
gestures. CPU use is process CPU time over wall time while the pen draws.

Usage: .venv/bin/python benchmarks/bench_input_latency.py [--seconds S]
"""

from __future__ import annotations

import argparse
import os
import queue
import statistics
import threading
import time
from pathlib import Path

from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.readers import HidrawReader
from physink_tui.input.pen.pen_input import PenInput
from physink_tui.input.sources import RawReport, SourceEnded

CAPTURE = Path(__file__).resolve().parents[1] / "tests" / "recorded_hid" / "windows-ink-strokes.hid"


def run(rate_hz: float, seconds: float) -> dict[str, float]:
    capture = Capture.from_file(CAPTURE)
    device = capture.devices[0]
    reports = [e.data for e in capture.events]
    length = len(reports[0])
    assert all(len(r) == length for r in reports), "a pipe keeps report boundaries only for equal lengths"
    read_fd, write_fd = os.pipe()
    reader = HidrawReader(read_fd, "tablet0", read_size=length)
    pen = PenInput()
    pen.add_hid_device("tablet0", HidPenDecoder(device.descriptor, device.vid, device.pid))
    q: queue.Queue = queue.Queue()
    sent_at: list[float] = []
    count = int(rate_hz * seconds)

    def writer() -> None:
        period = 1.0 / rate_hz
        start = time.monotonic()
        for i in range(count):
            delay = start + i * period - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            sent_at.append(time.monotonic())
            os.write(write_fd, reports[i % len(reports)])
        os.close(write_fd)

    reader.start(q)
    cpu0, wall0 = time.process_time(), time.monotonic()
    thread = threading.Thread(target=writer)
    thread.start()
    latencies = []
    gestures = 0
    index = 0
    while True:
        item = q.get()
        if isinstance(item, RawReport):
            gestures += len(pen.handle(item))
            done = time.monotonic()
            latencies.append(done - sent_at[index])
            index += 1
        elif isinstance(item, SourceEnded):
            break
    cpu, wall = time.process_time() - cpu0, time.monotonic() - wall0
    thread.join()
    reader.stop()
    latencies.sort()
    return {
        "reports": len(latencies),
        "p50_ms": statistics.median(latencies) * 1e3,
        "p99_ms": latencies[int(0.99 * (len(latencies) - 1))] * 1e3,
        "max_ms": latencies[-1] * 1e3,
        "cpu_pct": 100.0 * cpu / wall,
        "gestures": gestures,
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seconds", type=float, default=10.0)
    args = ap.parse_args()
    print(f"capture {CAPTURE.name}, {args.seconds:.0f} s per rate\n")
    print("| report rate | reports | latency p50 | latency p99 | max | process CPU (all threads) |")
    print("|---:|---:|---:|---:|---:|---:|")
    for rate in (1000.0, 200.0):
        r = run(rate, args.seconds)
        print(f"| {rate:.0f} Hz | {r['reports']:,} | {r['p50_ms']:.3f} ms | {r['p99_ms']:.3f} ms | "
              f"{r['max_ms']:.2f} ms | {r['cpu_pct']:.1f} % |")


if __name__ == "__main__":
    main()
