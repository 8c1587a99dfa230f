"""Where a pen report keeps each value: layouts found in a parsed descriptor; no decoding.

A `PenLayout` names, for one report id, the bits of X, Y, pressure, tilt and the pen's switches.
`pen_layouts()` finds every pen report of a descriptor through the standard Digitizer usages,
Wacom's mirrored 0xFF0D page, and the "mouse mode" reports UC-Logic, Huion, XP-Pen and others
send at power-on (a Mouse application with absolute X/Y and Tip Pressure or In Range). Vendor
layouts that no descriptor describes are built in `vendor_layouts`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from physink_tui.input.hid import usages as U
from physink_tui.input.hid.descriptor import Field, ReportDescriptor

# The low nibble of a HID unit code is its system: 2 = SI rotation (radians), 4 = English rotation (degrees).
_UNIT_SYSTEM_RADIANS = 2
_UNIT_SYSTEM_DEGREES = 4


@dataclass(frozen=True, slots=True)
class ValueField:
    """A numeric value made of one or more bit ranges of a report, lowest part first.

    Attributes:
        parts: ``(bit_offset, size)`` pairs; part k supplies the bits above those of parts < k.
        signed: two's complement over the total width.
        lo: logical value that maps to 0.0 (or the lowest degree for tilt).
        hi: logical value that maps to 1.0; ``hi > lo``.
        scale: for tilt, degrees per logical unit; unused for other values.
        offset: for tilt, degrees at logical value 0 (``degrees = raw * scale + offset``).
    """

    parts: tuple[tuple[int, int], ...]
    signed: bool
    lo: int
    hi: int
    scale: float = 1.0
    offset: float = 0.0

    @property
    def width(self) -> int:
        return sum(size for _, size in self.parts)


@dataclass(frozen=True, slots=True)
class PenLayout:
    """How to read one pen report.

    Attributes:
        report_id: the report id (0 when the descriptor uses none).
        length: declared report length in bytes, including the report-id byte; longer reports
            are decoded from their declared bits only.
        source: where the layout comes from: ``descriptor``, ``mouse-mode`` or a vendor protocol name.
        x, y: position; required.
        pressure: tip pressure, or None (then ``p`` is 1.0 while the tip is down).
        tilt_x, tilt_y: tilt in degrees via ``ValueField.scale``, or None.
        tip, in_range, invert, eraser, b1, b2: bit offsets of one-bit switches, or None.
        in_range_inverted: the in-range bit reads 0 while the pen is in range.
        learn_in_range: the polarity of the in-range bit is not known in advance: the decoder
            learns it from the first report whose tip or pressure shows the pen is in range.
        eraser_is_button: the bit declared Eraser is really the second barrel button (the
            UC-Logic family's descriptors), so it never means an eraser.
        tool: ``(bit_offset, size)`` of a tool-type code (older Wacom), or None.
        eraser_tools: tool codes meaning the eraser end.
        pen_tools: tool codes that are pens or erasers; other tools (mice, lenses) are not pen samples.
        frame_byte: ``(byte_index, mask, values)``: reports whose masked byte is one of the values
            carry pad buttons, strips or dials in the pen's report id, not a pen sample.
        size_mm: the active area's width and height in millimetres when the descriptor gives
            physical extents in a length unit, else None.
    """

    report_id: int
    length: int
    source: str
    x: ValueField
    y: ValueField
    pressure: ValueField | None = None
    tilt_x: ValueField | None = None
    tilt_y: ValueField | None = None
    tip: int | None = None
    in_range: int | None = None
    invert: int | None = None
    eraser: int | None = None
    b1: int | None = None
    b2: int | None = None
    in_range_inverted: bool = False
    learn_in_range: bool = False
    eraser_is_button: bool = False
    tool: tuple[int, int] | None = None
    eraser_tools: tuple[int, ...] = ()
    pen_tools: tuple[int, ...] = ()
    frame_byte: tuple[int, int, tuple[int, ...]] | None = None
    size_mm: tuple[float, float] | None = None

    def summary(self) -> str:
        """One line such as ``0x07 descriptor 8B: x y pressure tip range b1 b2``."""
        parts = [name for name in ("pressure", "tilt_x", "tilt_y") if getattr(self, name) is not None]
        switches = [n for n in ("tip", "in_range", "invert", "eraser", "b1", "b2") if getattr(self, n) is not None]
        bits = f"x{self.x.width} y{self.y.width}"
        return f"0x{self.report_id:02x} {self.source} {self.length}B: {bits} {' '.join(parts + switches)}".rstrip()


def value_from_field(f: Field, index: int = 0) -> ValueField:
    """A normalisable value for value ``index`` of a field, with a sane range even when the
    descriptor's is empty or reversed."""
    off = f.bit_offset + index * f.size
    size = min(f.size, 32)
    lo, hi = f.logical_min, f.logical_max
    if hi <= lo:  # broken range: fall back to the field's full unsigned or signed width
        lo, hi = (-(1 << (size - 1)), (1 << (size - 1)) - 1) if f.is_signed else (0, (1 << size) - 1)
    return ValueField(((off, size),), f.is_signed or lo < 0, lo, max(hi, lo + 1))


def tilt_from_field(f: Field, index: int = 0) -> ValueField:
    """A tilt value whose ``scale`` and ``offset`` turn logical units into degrees.

    With a rotation unit (HID unit system nibble 2 = radians, 4 = degrees) the logical range maps
    linearly onto the physical range times 10**exponent; otherwise logical units are taken as
    degrees, which is what tablets without units send.
    """
    v = value_from_field(f, index)
    system = f.unit & 0xF
    span_l = f.logical_max - f.logical_min
    span_p = f.physical_max - f.physical_min
    if system not in (_UNIT_SYSTEM_RADIANS, _UNIT_SYSTEM_DEGREES) or span_l <= 0 or span_p <= 0:
        return v
    power = 10.0 ** f.unit_exponent
    slope = span_p / span_l * power
    offset = (f.physical_min * power) - f.logical_min * slope
    if system == _UNIT_SYSTEM_RADIANS:
        slope, offset = math.degrees(slope), math.degrees(offset)
    return replace(v, scale=slope, offset=offset)


_MM_PER_UNIT = {1: 10.0, 3: 25.4}  # unit system 1 = SI linear (cm), 3 = English linear (inch)


def _extent_mm(f: Field) -> float | None:
    system, length = f.unit & 0xF, (f.unit >> 4) & 0xF
    span = f.physical_max - f.physical_min
    if system not in _MM_PER_UNIT or length != 1 or span <= 0:
        return None
    return span * (10.0 ** f.unit_exponent) * _MM_PER_UNIT[system]


def _size_mm(xf: Field, yf: Field) -> tuple[float, float] | None:
    """Physical width and height of the active area, when both axes declare them in a length unit."""
    w, h = _extent_mm(xf), _extent_mm(yf)
    return (w, h) if w and h else None


_PEN_APPLICATIONS = {U.DG_DIGITIZER, U.DG_PEN, U.DG_LIGHT_PEN, U.DG_TOUCH_SCREEN, U.DG_WHITEBOARD,
                     U.usage(U.PAGE_WACOM_DIGITIZER, 0x01), U.usage(U.PAGE_WACOM_DIGITIZER, 0x02)}
_MOUSE_APPLICATIONS = {U.GD_MOUSE, U.GD_POINTER}


def _values(fields: list[Field]):
    """Yield ``(canonical usage, field, index)`` for each variable value of a report's input fields."""
    for f in fields:
        if f.is_constant and not f.usages:
            continue
        if f.is_variable:
            for i in range(f.count):
                u = f.usage_at(i)
                if u:
                    yield U.canonical(u), f, i


def _is_finger(f: Field) -> bool:
    return any(c.usage in (U.DG_FINGER, U.DG_PUCK) for c in f.collections)


def layout_for_report(fields: list[Field], report_id: int, length: int) -> PenLayout | None:
    """Build the pen layout of one input report, or None when it carries no pen.

    >>> layout_for_report([], 1, 8) is None
    True
    """
    fields = [f for f in fields if not _is_finger(f)]
    if not fields:
        return None
    found: dict[str, tuple[Field, int]] = {}
    barrels: list[int] = []
    has_contact_id = False
    for u, f, i in _values(fields):
        offset = f.bit_offset + i * f.size
        one_bit = f.size == 1
        if u == U.GD_X and "x" not in found and not f.is_relative:
            found["x"] = (f, i)
        elif u == U.GD_Y and "y" not in found and not f.is_relative:
            found["y"] = (f, i)
        elif u == U.DG_TIP_PRESSURE and "pressure" not in found:
            found["pressure"] = (f, i)
        elif u == U.DG_X_TILT and "tilt_x" not in found:
            found["tilt_x"] = (f, i)
        elif u == U.DG_Y_TILT and "tilt_y" not in found:
            found["tilt_y"] = (f, i)
        elif u == U.DG_CONTACT_ID:
            has_contact_id = True
        elif one_bit:
            name = {
                U.DG_TIP_SWITCH: "tip",
                U.DG_IN_RANGE: "in_range",
                U.DG_INVERT: "invert",
                U.DG_ERASER: "eraser",
                U.DG_SECONDARY_BARREL_SWITCH: "b2",
                U.BUTTON_1: "button1",
                U.BUTTON_2: "button2",
                U.BUTTON_3: "button3",
                U.DG_TABLET_PICK: "pick",
            }.get(u)
            if u == U.DG_BARREL_SWITCH:
                barrels.append(offset)
            elif name and name not in found:
                found[name] = (f, i)
    if "x" not in found or "y" not in found:
        return None
    xf = found["x"][0]
    app = xf.application
    pen_bits = {"tip", "in_range", "pressure", "invert", "eraser"} & found.keys()
    in_stylus = any(U.canonical(c.usage) == U.DG_STYLUS for c in xf.collections)
    if has_contact_id and not in_stylus and U.canonical(app) != U.DG_PEN:
        return None  # a touch contact, not a pen (pens may carry a contact/transducer id)
    if app in _MOUSE_APPLICATIONS:
        if not ({"pressure", "in_range"} & found.keys()):
            return None  # a mouse, not a pen in mouse mode
        source = "mouse-mode"
    elif app in _PEN_APPLICATIONS or (app >> 16) == U.PAGE_WACOM_DIGITIZER:
        if not pen_bits and not in_stylus:
            return None
        source = "descriptor"
    elif pen_bits >= {"tip"} or "pressure" in found:
        source = "descriptor"  # pen usages in an unusual application collection
    else:
        return None

    def bit(name: str) -> int | None:
        if name not in found:
            return None
        f, i = found[name]
        return f.bit_offset + i * f.size

    tip = bit("tip")
    b1 = barrels[0] if barrels else None
    b2 = bit("b2") if "b2" in found else (barrels[1] if len(barrels) > 1 else bit("pick"))
    if source == "mouse-mode" or tip is None:
        tip = tip if tip is not None else bit("button1")
        b1 = b1 if b1 is not None else bit("button2")
        b2 = b2 if b2 is not None else bit("button3")
    return PenLayout(
        report_id=report_id,
        length=length,
        source=source,
        size_mm=_size_mm(found["x"][0], found["y"][0]),
        x=value_from_field(*found["x"]),
        y=value_from_field(*found["y"]),
        pressure=value_from_field(*found["pressure"]) if "pressure" in found else None,
        tilt_x=tilt_from_field(*found["tilt_x"]) if "tilt_x" in found else None,
        tilt_y=tilt_from_field(*found["tilt_y"]) if "tilt_y" in found else None,
        tip=tip,
        in_range=bit("in_range"),
        invert=bit("invert"),
        eraser=bit("eraser"),
        b1=b1,
        b2=b2,
    )


def pen_layouts(descriptor: ReportDescriptor) -> dict[int, PenLayout]:
    """Every pen layout of a descriptor, keyed by report id.

    >>> from physink_tui.input.hid.descriptor import ReportDescriptor
    >>> pen_layouts(ReportDescriptor.from_bytes(bytes.fromhex("05010902a101c0")))
    {}
    """
    layouts = {}
    for report in descriptor.input_reports():
        layout = layout_for_report(list(report.fields), report.report_id, report.size_bytes)
        if layout is not None:
            layouts[report.report_id] = layout
    return layouts


def tablet_size(layouts: dict[int, PenLayout]) -> tuple[float, float] | None:
    """Best guess at the active area's proportions (width, height) for the canvas mapping.

    Physical extents win when they are plausible for a tablet (30 mm to 1.5 m a side); else the
    logical ranges of the widest-range layout, unless they are square and suspiciously generic
    (mouse-mode reports scaled to 0..2047 or 0..32767 on both axes). None when nothing is credible.
    """
    for lay in sorted(layouts.values(), key=lambda lay: -(lay.x.hi - lay.x.lo)):
        size = lay.size_mm
        if size and all(30.0 <= v <= 1500.0 for v in size) and 0.3 < size[0] / size[1] < 3.5:
            return size
    best = max(layouts.values(), key=lambda lay: lay.x.hi - lay.x.lo, default=None)
    if best is None:
        return None
    w, h = best.x.hi - best.x.lo, best.y.hi - best.y.lo
    if w == h or not 0.3 < w / h < 3.5:
        return None
    return float(w), float(h)
