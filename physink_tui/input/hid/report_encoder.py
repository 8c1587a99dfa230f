"""Encodes a pen state as the raw HID report a `PenLayout` describes; the inverse of `pen_decoder`, no timing.

`encode_report` writes exactly what `pen_decoder` reads back: normalised values become logical values
(``lo + round(v * (hi - lo))``, two's complement when signed, split over the value's parts), tilt becomes
``round((degrees - offset) / scale)``, switches become bits. Where the decoder infers something, the encoder writes what
makes the inference come out right, as a real pen does:

* pressure is written only while touching, and a touching pen always presses at least one logical unit (the
  decoder reads a zero-pressure tip with a barrel button as a button click, and a tip without a tip bit from
  pressure alone);
* the eraser follows Windows Ink: Invert is set while the eraser end is in range and Eraser (not Tip Switch)
  while it touches; a layout without those bits (or a tool code) cannot say "eraser" and the state's eraser is
  ignored;
* the in-range bit follows ``layout.in_range_inverted``;
* ``padding_ones`` fills every bit the layout does not use with ones, as some XP-Pen tablets do, except where
  that would make the report look like one of the layout's pad (frame) reports.
"""

from __future__ import annotations

from dataclasses import dataclass

from physink_tui.input.hid.pen_layout import PenLayout, ValueField


@dataclass(frozen=True, slots=True)
class PenState:
    """What the pen is doing at one report.

    Attributes:
        x: 0..1 across the active area, left to right.
        y: 0..1 down the active area, top to bottom.
        p: tip pressure 0..1; only meaningful while ``tip``.
        tip: the tip (or, with ``eraser``, the eraser end) touches the surface; implies ``in_range``.
        in_range: the pen is in proximity.
        eraser: the eraser end is the one in proximity.
        b1: first barrel button.
        b2: second barrel button.
        tilt_x: degrees, positive towards the right.
        tilt_y: degrees, positive towards the user.
    """

    x: float
    y: float
    p: float = 0.0
    tip: bool = False
    in_range: bool = True
    eraser: bool = False
    b1: bool = False
    b2: bool = False
    tilt_x: float = 0.0
    tilt_y: float = 0.0


def logical_value(v: ValueField, u: float) -> int:
    """The logical value that decodes to ``u`` (clamped to 0..1).

    >>> logical_value(ValueField(((0, 8),), False, 0, 200), 0.5)
    100
    """
    u = 0.0 if u < 0.0 else 1.0 if u > 1.0 else u
    return v.lo + round(u * (v.hi - v.lo))


def tilt_value(v: ValueField, degrees: float) -> int:
    """The logical tilt value nearest ``degrees``, clamped to the field's logical range."""
    raw = round((degrees - v.offset) / v.scale) if v.scale else 0
    return min(max(raw, v.lo), v.hi)


def _put_value(v: ValueField, raw: int) -> int:
    """The report bits holding ``raw`` in the value's parts (two's complement over the total width).

    ``raw`` is first clamped to what the width can hold: a declared range may exceed it (a signed byte
    declared up to 128), and wrapping around would read back as the opposite extreme.
    """
    w = v.width
    low, high = (-(1 << (w - 1)), (1 << (w - 1)) - 1) if v.signed else (0, (1 << w) - 1)
    raw = min(max(raw, low), high) & ((1 << w) - 1)
    bits, shift = 0, 0
    for off, size in v.parts:
        bits |= ((raw >> shift) & ((1 << size) - 1)) << off
        shift += size
    return bits


def _value_mask(v: ValueField) -> int:
    mask = 0
    for off, size in v.parts:
        mask |= ((1 << size) - 1) << off
    return mask


def used_bits(layout: PenLayout) -> int:
    """Mask (over the report read as one little-endian integer) of every bit the layout reads."""
    mask = 0
    for v in (layout.x, layout.y, layout.pressure, layout.tilt_x, layout.tilt_y):
        if v is not None:
            mask |= _value_mask(v)
    for bit in (layout.tip, layout.in_range, layout.invert, layout.eraser, layout.b1, layout.b2):
        if bit is not None:
            mask |= 1 << bit
    if layout.tool is not None:
        off, size = layout.tool
        mask |= ((1 << size) - 1) << off
    return mask


def encode_report(layout: PenLayout, state: PenState, *, padding_ones: bool = False) -> bytes:
    """The report of ``layout.length`` bytes (report id first when it is not 0) for ``state``.

    >>> from physink_tui.input.hid.vendor_layouts import TabletParams, uclogic_v1_layout
    >>> layout = uclogic_v1_layout(TabletParams(40000, 25000, 2047))  # in-range bit inverted
    >>> encode_report(layout, PenState(0.5, 0.5, 0.5, tip=True)).hex(" ")
    '07 01 20 4e d4 30 00 04'
    """
    bits = 0
    in_range = state.in_range or state.tip
    touching = state.tip
    eraser = state.eraser and in_range
    button_eraser = layout.eraser_is_button
    invert_bit = None if button_eraser else layout.invert
    eraser_bit = None if button_eraser else layout.eraser

    def setbit(bit: int | None, on: bool) -> None:
        nonlocal bits
        if bit is not None and on:
            bits |= 1 << bit

    if layout.tool is not None:
        off, size = layout.tool
        tools = layout.eraser_tools if eraser and layout.eraser_tools else layout.pen_tools
        bits |= ((tools[0] if tools else 0) & ((1 << size) - 1)) << off
        setbit(layout.tip, touching)
    elif eraser and eraser_bit is not None:
        setbit(invert_bit, True)
        setbit(eraser_bit, touching)  # Windows Ink: Eraser replaces Tip Switch while the eraser touches
    else:
        setbit(invert_bit, eraser)
        setbit(layout.tip, touching)
    setbit(layout.b1, state.b1)
    setbit(layout.b2, state.b2)
    if layout.in_range is not None:
        setbit(layout.in_range, in_range != layout.in_range_inverted)

    bits |= _put_value(layout.x, logical_value(layout.x, state.x))
    bits |= _put_value(layout.y, logical_value(layout.y, state.y))
    if layout.pressure is not None:
        v = layout.pressure
        raw = logical_value(v, state.p) if touching else v.lo
        if touching and raw <= v.lo:
            raw = v.lo + 1
        bits |= _put_value(v, raw)
    for tilt, degrees in ((layout.tilt_x, state.tilt_x), (layout.tilt_y, state.tilt_y)):
        if tilt is not None:
            bits |= _put_value(tilt, tilt_value(tilt, degrees))

    id_bits = 8 if layout.report_id else 0
    if padding_ones:
        free = ((1 << (layout.length * 8)) - 1) & ~((1 << id_bits) - 1) & ~used_bits(layout)
        padded = bits | free
        if layout.frame_byte is not None:
            index, mask, values = layout.frame_byte
            if (padded >> (8 * index)) & mask in values:
                padded &= ~(free & (mask << (8 * index)))  # leave that byte's padding clear
        bits = padded
    bits |= layout.report_id & ((1 << id_bits) - 1)
    return bits.to_bytes(layout.length, "little")
