"""Benchmark-side script: a capture to pen-sample JSON lines with hid-tools' public API; never imported by physink.

hid-tools is GPL: this file only *uses* it, from a scratch venv (see bench_decode_process.py), and copies none
of it. Each report is looked up with ``ReportDescriptor.get`` and read with ``HidField.get_values``; the
values are normalised by their logical range and written with ``json.dumps``, one DESIGN.md line per pen report.
"""

import json
import sys

import hidtools.hid as ht

X, Y = 0x010030, 0x010031
PRESSURE, IN_RANGE, TIP, BARREL, ERASER, INVERT, BARREL2 = (0x0D0000 | u for u in (0x30, 0x32, 0x42, 0x44, 0x45,
                                                                                 0x3C, 0x5A))
TILT_X, TILT_Y = 0x0D003D, 0x0D003E


def main(path: str) -> None:
    rdesc = None
    out = []
    ranges = {}
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("R: "):
                rdesc = ht.ReportDescriptor.from_bytes([int(b, 16) for b in line.split()[2:]])
            elif line.startswith("E: ") and rdesc is not None:
                parts = line.split()
                data = [int(b, 16) for b in parts[3:]]
                report = rdesc.get(data[0], len(data))
                if report is None:
                    continue
                v = {}
                for field in report:
                    values = field.get_values(data)
                    for k, usage in enumerate((field.usages or [field.usage])[:len(values)]):
                        v[usage] = values[k]
                        ranges[usage] = (field.logical_min, field.logical_max)
                if X not in v or Y not in v:
                    continue

                def norm(u, v=v):
                    lo, hi = ranges[u]
                    return min(max((v[u] - lo) / ((hi - lo) or 1), 0.0), 1.0)

                tip = bool(v.get(TIP, 0))
                out.append(json.dumps({
                    "t": round(float(parts[1]), 6), "x": round(norm(X), 6), "y": round(norm(Y), 6),
                    "p": round(norm(PRESSURE), 6) if PRESSURE in v and tip else (1.0 if tip else 0.0),
                    "tip": tip, "range": bool(v.get(IN_RANGE, 1)),
                    "eraser": bool(v.get(ERASER, 0) or v.get(INVERT, 0)), "b1": bool(v.get(BARREL, 0)),
                    "b2": bool(v.get(BARREL2, 0)),
                    "tilt_x": round(float(v[TILT_X]), 2) if TILT_X in v else None,
                    "tilt_y": round(float(v[TILT_Y]), 2) if TILT_Y in v else None,
                    "report": data[0],
                }))
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main(sys.argv[1])
