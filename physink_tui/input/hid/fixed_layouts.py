"""Pen layouts of devices whose own descriptor is all vendor bytes and which Linux drives by replacing it; no I/O.

A device listed here reports pen data that its descriptor does not describe; the Linux kernel swaps
the descriptor for a fixed one (``report_fixup``). These layouts are written from the facts of those
fixed descriptors (report id, byte offsets, bits, maxima), not from their code.
"""

from __future__ import annotations

from dataclasses import dataclass

from physink_tui.input.hid.descriptor import ReportDescriptor
from physink_tui.input.hid.pen_layout import PenLayout, ValueField


@dataclass(frozen=True, slots=True)
class FixedDevice:
    """A device the kernel drives with a replacement descriptor.

    Attributes:
        name: the model, for summaries.
        original_size: length in bytes of the device's own descriptor (the kernel replaces only that one).
        layout: where its pen report keeps each value.
    """

    name: str
    original_size: int
    layout: PenLayout


def _pd1011_layout() -> PenLayout:
    """ViewSonic PD1011 signature pen display: report 0x02, 10 bytes.

    Facts of the kernel's fixed descriptor (hid-viewsonic): X LE16 in bytes 1-2 (0..43392, 8.541 in),
    Y LE16 in bytes 3-4 (0..27120, 5.338 in); byte 5 bit 0 constant, bit 1 in range, bit 2 tip;
    pressure LE16 in bytes 6-7 (5..2047); bytes 8-9 constant.
    """
    return PenLayout(
        report_id=0x02, length=10, source="viewsonic-pd1011",
        x=ValueField(((8, 16),), False, 0, 43392), y=ValueField(((24, 16),), False, 0, 27120),
        pressure=ValueField(((48, 16),), False, 5, 2047),
        in_range=41, tip=42, size_mm=(8.541 * 25.4, 5.338 * 25.4),
    )


VID_VIEWSONIC = 0x0543
VID_SIGNOTEC = 0x2133

# Source: the Linux kernel's hid-viewsonic fixed descriptor (facts only); no capture of these devices
# is in /work/shared/data/hid, and /work/shared/data/tablets lists only the ViewSonic Woodpads.
FIXED_DEVICES: dict[tuple[int, int], FixedDevice] = {
    (VID_VIEWSONIC, 0xE621): FixedDevice("ViewSonic PD1011", 408, _pd1011_layout()),
    (VID_SIGNOTEC, 0x0018): FixedDevice("Signotec ViewSonic PD1011", 408, _pd1011_layout()),
}


def fixed_layouts(descriptor: ReportDescriptor, vid: int | None, pid: int | None) -> dict[int, PenLayout]:
    """The replacement layout when the device is listed and its descriptor is the one the kernel replaces
    (its original length), or describes no input report with the pen's id; otherwise nothing."""
    device = FIXED_DEVICES.get((vid or 0, pid or 0))
    if device is None:
        return {}
    rid = device.layout.report_id
    if len(descriptor.raw) != device.original_size and descriptor.input_report(rid) is not None:
        return {}
    return {rid: device.layout}
