"""Benchmark: HID decoding throughput (batch and one report at a time) and descriptor parse time.

Usage: .venv/bin/python benchmarks/bench_hid_decode.py [CAPTURE.hid ...] [--repeat N]
Without captures it takes the largest capture in ../shared/data/hid (the development data).
Prints medians of N runs as a Markdown table for docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import platform
import statistics
import time
from pathlib import Path

from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.batch import decode_batch
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.descriptor import ReportDescriptor

SHARED = Path(__file__).resolve().parents[2] / "shared" / "data" / "hid"


def median_time(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def bench_capture(path: Path, repeat: int) -> dict[str, float]:
    capture = Capture.from_file(path)
    device = capture.devices[0]
    events = capture.events
    times = [e.t for e in events]
    reports = [e.data for e in events]
    n = len(reports)

    def batch() -> None:
        decode_batch(HidPenDecoder(device.descriptor, device.vid, device.pid), times, reports)

    def streaming() -> None:
        decoder = HidPenDecoder(device.descriptor, device.vid, device.pid)
        decode = decoder.decode
        for t, data in zip(times, reports, strict=True):
            decode(data, t)

    def parse() -> None:
        ReportDescriptor.from_bytes(device.descriptor)

    def build() -> None:
        HidPenDecoder(device.descriptor, device.vid, device.pid)

    parse_s = median_time(parse, repeat * 20)
    build_s = median_time(build, repeat * 5)
    return {
        "reports": n,
        "descriptor_bytes": len(device.descriptor),
        "batch_per_s": n / median_time(batch, repeat),
        "stream_per_s": n / median_time(streaming, repeat),
        "parse_us": parse_s * 1e6,
        "build_us": build_s * 1e6,
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("captures", nargs="*", type=Path)
    ap.add_argument("--repeat", type=int, default=7)
    args = ap.parse_args()
    paths = args.captures or [max(SHARED.glob("*.hid"), key=lambda p: p.stat().st_size)]
    print(f"machine: {platform.machine()}, {platform.python_implementation()} {platform.python_version()}, "
          f"median of {args.repeat} runs\n")
    print("| capture | reports | batch reports/s | one-at-a-time reports/s | descriptor parse | decoder build |")
    print("|---|---:|---:|---:|---:|---:|")
    for path in paths:
        r = bench_capture(path, args.repeat)
        print(f"| {path.name} | {r['reports']:,} | {r['batch_per_s']:,.0f} | {r['stream_per_s']:,.0f} | "
              f"{r['parse_us']:.0f} µs ({r['descriptor_bytes']} B) | {r['build_us']:.0f} µs |")


if __name__ == "__main__":
    main()
