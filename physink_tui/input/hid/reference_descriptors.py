"""Hand-written report descriptors for the main classes of pen tablet; no decoding and no real device's bytes.

Each `ReferenceDevice` is what a device of its class declares, written item by item with
`descriptor_builder` so a reader can check it against the HID 1.11 and Windows pen specifications:

* ``windows-ink``: a generic Windows Ink pen (Digitizer page, report 0x02) as Microsoft's pen guidelines
  describe it: six switches, 16-bit X/Y with physical extents, 12-bit pressure, tilt in degrees.
* ``wacom-ff0d``: a Wacom-style pen whose usages mirror the Digitizer page on vendor page 0xFF0D (report 0x10,
  24-bit X/Y, 13-bit pressure, tilt).
* ``uclogic-v1``: the descriptor a UC-Logic/Huion tablet reports before its vendor initialisation: pen report
  0x07 (where the second barrel button is declared as Eraser) and the mouse-mode report 0x09.
* ``huion-v2``: the single vendor collection of a Huion tablet in v2 mode (report 0x08); its layout is known
  only from the protocol.

The virtual pen (`virtual_pen`) writes captures for these, and tests decode them.
"""

from __future__ import annotations

from dataclasses import dataclass

from physink_tui.input.hid import descriptor_builder as d

PAGE_GENERIC_DESKTOP = 0x01
PAGE_BUTTON = 0x09
PAGE_DIGITIZER = 0x0D
PAGE_VENDOR = 0xFF00
PAGE_WACOM = 0xFF0D

# Digitizer usages (the Wacom page mirrors them).
PEN = 0x02
STYLUS = 0x20
TIP_PRESSURE = 0x30
IN_RANGE = 0x32
INVERT = 0x3C
X_TILT = 0x3D
Y_TILT = 0x3E
TIP_SWITCH = 0x42
SECONDARY_TIP_SWITCH = 0x43
BARREL_SWITCH = 0x44
ERASER = 0x45
SECONDARY_BARREL_SWITCH = 0x5A
# Generic Desktop usages.
MOUSE = 0x02
POINTER = 0x01
X = 0x30
Y = 0x31


@dataclass(frozen=True, slots=True)
class ReferenceDevice:
    """A device the virtual pen can stand in for.

    Attributes:
        name: the HID name written to the capture's ``N:`` line.
        vid: USB vendor id, 0..0xffff.
        pid: USB product id, 0..0xffff.
        descriptor: the report descriptor bytes.
        protocol: the vendor protocol the device speaks once initialised (``uclogic-v1``, ``huion-v2``),
            or None when its descriptor tells everything.
    """

    name: str
    vid: int
    pid: int
    descriptor: bytes
    protocol: str | None = None


def _switches(*usages: int) -> bytes:
    """One-bit Data,Var,Abs switches for the given usages."""
    return d.build([d.usage(u) for u in usages], d.logical(0, 1), d.report_size(1),
                   d.report_count(len(usages)), d.input(d.DATA_VARIABLE))


def _padding(bits: int) -> bytes:
    return d.build(d.report_size(1), d.report_count(bits), d.input(d.CONSTANT_VARIABLE))


def windows_ink_descriptor() -> bytes:
    """A 344 x 194 mm pen display (logical units of 10 um), 4096 pressure levels, +-60 degree tilt."""
    return d.build(
        d.usage_page(PAGE_DIGITIZER), d.usage(PEN), d.collection("application"),
        d.report_id(0x02),
        d.usage(STYLUS), d.collection("physical"),
        _switches(TIP_SWITCH, BARREL_SWITCH, ERASER, INVERT, SECONDARY_BARREL_SWITCH, IN_RANGE),
        _padding(2),
        d.push(),
        d.usage_page(PAGE_GENERIC_DESKTOP),
        d.report_size(16), d.report_count(1),
        d.unit(d.UNIT_CM), d.unit_exponent(-3),  # physical units of 10 um
        d.usage(X), d.logical(0, 34416), d.physical(0, 34416), d.input(d.DATA_VARIABLE),
        d.usage(Y), d.logical(0, 19359), d.physical(0, 19359), d.input(d.DATA_VARIABLE),
        d.pop(),
        d.usage(TIP_PRESSURE), d.logical(0, 4095), d.report_size(16), d.report_count(1),
        d.input(d.DATA_VARIABLE),
        d.usage(X_TILT), d.usage(Y_TILT), d.logical(-60, 60), d.physical(-60, 60),
        d.unit(d.UNIT_DEGREES), d.unit_exponent(0), d.report_size(8), d.report_count(2),
        d.input(d.DATA_VARIABLE),
        d.end_collection(),
        d.end_collection(),
    )


def wacom_ff0d_descriptor() -> bytes:
    """A 224 x 148 mm Wacom-style tablet (200 lines/mm), 8192 pressure levels, tilt -64..63 degrees."""
    return d.build(
        d.usage_page(PAGE_WACOM), d.usage(0x01), d.collection("application"),
        d.report_id(0x10),
        d.usage(STYLUS), d.collection("physical"),
        _switches(TIP_SWITCH, BARREL_SWITCH, ERASER, INVERT, SECONDARY_BARREL_SWITCH, IN_RANGE),
        _padding(2),
        d.push(),
        d.report_size(24), d.report_count(1),
        d.unit(d.UNIT_CM), d.unit_exponent(-3),
        d.usage(0x130), d.logical(0, 44800), d.physical(0, 22400), d.input(d.DATA_VARIABLE),
        d.usage(0x131), d.logical(0, 29600), d.physical(0, 14800), d.input(d.DATA_VARIABLE),
        d.pop(),
        d.usage(TIP_PRESSURE), d.logical(0, 8191), d.report_size(16), d.report_count(1),
        d.input(d.DATA_VARIABLE),
        d.push(),
        d.usage(X_TILT), d.usage(Y_TILT), d.logical(-64, 63), d.physical(-64, 63),
        d.unit(d.UNIT_DEGREES), d.unit_exponent(0), d.report_size(8), d.report_count(2),
        d.input(d.DATA_VARIABLE),
        d.pop(),
        d.end_collection(),
        d.end_collection(),
    )


def uclogic_v1_descriptor() -> bytes:
    """A 10 x 6.25 inch tablet (4000 lines/inch), 2048 pressure levels, plus its mouse-mode report.

    Byte 1 of report 0x07 declares Tip, Barrel, Eraser, Invert, Secondary Tip, Barrel and In Range in bits
    0..6; the pen has two barrel buttons and no eraser, which the decoder knows from the vendor id.
    """
    pen = d.build(
        d.usage_page(PAGE_DIGITIZER), d.usage(PEN), d.collection("application"),
        d.report_id(0x07),
        d.usage(STYLUS), d.collection("physical"),
        _switches(TIP_SWITCH, BARREL_SWITCH, ERASER, INVERT, SECONDARY_TIP_SWITCH, BARREL_SWITCH),
        _switches(IN_RANGE),
        _padding(1),
        d.usage_page(PAGE_GENERIC_DESKTOP), d.report_size(16), d.report_count(1),
        d.push(),
        d.unit(d.UNIT_INCH), d.unit_exponent(-3),  # physical units of a thousandth of an inch
        d.usage(X), d.logical(0, 40000), d.physical(0, 10000), d.input(d.DATA_VARIABLE),
        d.usage(Y), d.logical(0, 25000), d.physical(0, 6250), d.input(d.DATA_VARIABLE),
        d.pop(),
        d.usage_page(PAGE_DIGITIZER),
        d.usage(TIP_PRESSURE), d.logical(0, 2047), d.input(d.DATA_VARIABLE),
        d.end_collection(),
        d.end_collection(),
    )
    mouse = d.build(
        d.usage_page(PAGE_GENERIC_DESKTOP), d.usage(MOUSE), d.collection("application"),
        d.report_id(0x09),
        d.usage(POINTER), d.collection("physical"),
        d.usage_page(PAGE_BUTTON), d.usage_range(1, 3), d.logical(0, 1), d.report_size(1), d.report_count(3),
        d.input(d.DATA_VARIABLE),
        d.report_count(5), d.input(d.CONSTANT),
        d.usage_page(PAGE_GENERIC_DESKTOP), d.report_size(16), d.report_count(1),
        d.usage(X), d.logical(0, 2048), d.input(d.DATA_VARIABLE),
        d.usage(Y), d.logical(0, 2048), d.input(d.DATA_VARIABLE),
        d.usage_page(PAGE_DIGITIZER),
        d.usage(TIP_PRESSURE), d.logical(0, 2047), d.input(d.DATA_VARIABLE),
        d.end_collection(),
        d.end_collection(),
    )
    return pen + mouse


def huion_v2_descriptor() -> bytes:
    """One vendor-defined input report 0x08 of eleven bytes after the id."""
    return d.build(
        d.usage_page(PAGE_VENDOR), d.usage(0x01), d.collection("application"),
        d.report_id(0x08),
        d.usage(0x01), d.logical(0, 255), d.report_size(8), d.report_count(11), d.input(d.DATA_VARIABLE),
        d.end_collection(),
    )


REFERENCE_DEVICES: dict[str, ReferenceDevice] = {
    "windows-ink": ReferenceDevice(
        "PhysInk Reference Windows Ink Pen", 0x1234, 0x5678, windows_ink_descriptor()),
    "wacom-ff0d": ReferenceDevice(
        "PhysInk Reference Wacom-style Pen", 0x056A, 0x0374, wacom_ff0d_descriptor()),
    "uclogic-v1": ReferenceDevice(
        "PhysInk Reference UC-Logic v1 Tablet", 0x256C, 0x006E, uclogic_v1_descriptor(), "uclogic-v1"),
    "huion-v2": ReferenceDevice(
        "PhysInk Reference Huion v2 Tablet", 0x256C, 0x006D, huion_v2_descriptor(), "huion-v2"),
}
"""The reference devices by short id."""
