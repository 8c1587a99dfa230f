"""Benchmark: our decoders side by side with hid-tools (GPL, not a dependency) on the same capture.

hid-tools is only imported here, from a separate environment, to measure the ratio the HID issue
asks about; nothing of it is shipped or copied. Run:

    python3 -m venv /tmp/htvenv && /tmp/htvenv/bin/pip install hid-tools numpy
    PYTHONPATH=. /tmp/htvenv/bin/python benchmarks/compare_hid_tools.py [CAPTURE.hid] [--repeat N]

hid-tools' work per report is taken as: find the report by id and size, then read every field's
values (``HidField.get_values``), which is what a decoder needs; its ``format_report`` (text) is
slower still and timed separately.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import hidtools.hid as ht

from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.batch import decode_batch
from physink_tui.input.hid.decoder import HidPenDecoder

SHARED = Path(__file__).resolve().parents[2] / "shared" / "data" / "hid"


def median_rate(fn, n: int, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return n / statistics.median(times)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("capture", nargs="?", type=Path)
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    path = args.capture or max(SHARED.glob("*.hid"), key=lambda p: p.stat().st_size)
    capture = Capture.from_file(path)
    dev = capture.devices[0]
    times = [e.t for e in capture.events]
    reports = [e.data for e in capture.events]
    lists = [list(r) for r in reports]
    n = len(reports)
    rdesc = ht.ReportDescriptor.from_bytes(list(dev.descriptor))

    def hidtools_fields() -> None:
        for data in lists:
            report = rdesc.get(data[0], len(data))
            if report is not None:
                for field in report:
                    field.get_values(data)

    def hidtools_format() -> None:
        for data in lists[:5000]:
            rdesc.format_report(data)

    def ours_stream() -> None:
        decode = HidPenDecoder(dev.descriptor, dev.vid, dev.pid).decode
        for t, data in zip(times, reports, strict=True):
            decode(data, t)

    def ours_batch() -> None:
        decode_batch(HidPenDecoder(dev.descriptor, dev.vid, dev.pid), times, reports)

    rates = {
        "hid-tools get_values": median_rate(hidtools_fields, n, args.repeat),
        "hid-tools format_report": median_rate(hidtools_format, min(n, 5000), args.repeat),
        "physink one at a time": median_rate(ours_stream, n, args.repeat),
        "physink batch (numpy)": median_rate(ours_batch, n, args.repeat),
    }
    base = rates["hid-tools get_values"]
    print(f"{path.name}: {n:,} reports, median of {args.repeat} runs, measured in one process\n")
    print("| decoder | reports/s | vs hid-tools get_values |")
    print("|---|---:|---:|")
    for name, rate in rates.items():
        print(f"| {name} | {rate:,.0f} | {rate / base:.1f}x |")


if __name__ == "__main__":
    main()
