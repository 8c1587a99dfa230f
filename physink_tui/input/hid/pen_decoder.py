"""Compiles a `PenLayout` into a fast report decoder, one report at a time; no batch or device logic.

Each layout becomes a small Python function generated once (constant offsets, masks and shifts
folded into the code) that reads the whole report as one integer and slices it. The decoder
keeps the two pieces of state real tablets force on us: ranges widened when a tablet sends values
past the logical maximum it declares (as libinput does), and the learnt polarity of in-range bits
that some models invert.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from physink_tui.input.hid.pen_layout import PenLayout, ValueField
from physink_tui.input.pen.sample import PenSample

# Reasons a report yields no pen sample; the decode summary counts them.
REASON_TRUNCATED = "truncated report"
REASON_FRAME = "pad, strip or dial report"
REASON_TOOL = "tool is not a pen (mouse or lens)"

TILT_LIMIT = 90.0


def value_expr(v: ValueField) -> str:
    """Python expression for the raw integer of a value, reading from the report integer ``v``."""
    terms, shift = [], 0
    for off, size in v.parts:
        mask = (1 << size) - 1
        term = f"((v >> {off}) & {mask:#x})" if off else f"(v & {mask:#x})"
        terms.append(f"({term} << {shift})" if shift else term)
        shift += size
    return " | ".join(terms)


class Bounds:
    """A value's working range: the declared one, widened by values seen past it (never narrowed)."""

    __slots__ = ("hi", "inv", "lo", "widened")

    def __init__(self, lo: int, hi: int) -> None:
        self.lo, self.hi = lo, hi
        self.inv = 1.0 / (hi - lo)
        self.widened = False

    def widen(self, raw: int) -> None:
        if raw > self.hi:
            self.hi = raw
        elif raw < self.lo:
            self.lo = raw
        self.inv = 1.0 / (self.hi - self.lo)
        self.widened = True


class CompiledLayout:
    """A layout compiled to a function ``decode(data: bytes, t: float) -> PenSample | str``.

    A str result is the reason the report is not a pen sample.
    """

    def __init__(self, layout: PenLayout) -> None:
        self.layout = layout
        self.x = Bounds(layout.x.lo, layout.x.hi)
        self.y = Bounds(layout.y.lo, layout.y.hi)
        self.p = Bounds(layout.pressure.lo, layout.pressure.hi) if layout.pressure else None
        # in-range polarity: the bit value that means "in range"; None while still unknown
        self.in_range_value: int | None = None if layout.learn_in_range else (0 if layout.in_range_inverted else 1)
        self.in_range_guess = 0 if layout.in_range_inverted else 1
        self._last_in_range_bit = -1
        self._same_in_range_run = 0
        self._last_report_t = float("-inf")
        self.decode: Callable[[bytes, float], PenSample | str] = self._compile()

    def learn_in_range(self, bit_value: int, strong: bool, t: float) -> bool:
        """Record one observation of the in-range bit at time ``t``; return whether the pen is in range.

        Strong evidence (the tip, pressure or a button is active) fixes the polarity. Weak
        evidence only sets a guess: the first report after a silence of over 100 ms is a pen
        arriving, hence in range, and a bit value seen three reports in a row is in range too
        (leaving reports come one at a time).
        """
        if strong:
            self.in_range_value = bit_value
            return True
        if t - self._last_report_t > 0.1:
            self.in_range_guess = bit_value
            self._same_in_range_run = 0
        elif bit_value == self._last_in_range_bit:
            self._same_in_range_run += 1
            if self._same_in_range_run >= 2:
                self.in_range_guess = bit_value
        else:
            self._same_in_range_run = 0
        self._last_in_range_bit = bit_value
        self._last_report_t = t
        return bit_value == self.in_range_guess

    def _compile(self) -> Callable[[bytes, float], PenSample | str]:
        lay = self.layout
        length = lay.length
        src = ["def decode(data, t):",
               f"    if len(data) < {length}: return {REASON_TRUNCATED!r}",
               f"    v = int.from_bytes(data[:{length}], 'little')"]
        if lay.frame_byte is not None:
            index, mask, values = lay.frame_byte
            src.append(f"    if (data[{index}] & {mask:#x}) in {tuple(values)!r}: return {REASON_FRAME!r}")
        eraser_terms = []
        if lay.tool is not None:
            off, size = lay.tool
            src.append(f"    tool = (v >> {off}) & {(1 << size) - 1:#x}")
            if lay.pen_tools:
                src.append(f"    if tool not in {tuple(lay.pen_tools)!r}: return {REASON_TOOL!r}")
            if lay.eraser_tools:
                eraser_terms.append(f"tool in {tuple(lay.eraser_tools)!r}")
        for name in ("x", "y"):
            src += [f"    r{name} = {value_expr(getattr(lay, name))}"]
            if getattr(lay, name).signed:
                w = getattr(lay, name).width
                src.append(f"    if r{name} >> {w - 1}: r{name} -= {1 << w}")
        bit = {n: getattr(lay, n) for n in ("tip", "in_range", "invert", "eraser", "b1", "b2")}
        flags = {n: f"(v >> {b}) & 1 == 1" if b is not None else "False" for n, b in bit.items()}
        src.append(f"    b1 = {flags['b1']}")
        src.append(f"    b2 = {flags['b2']}")
        eraser_bit = flags["eraser"]
        if lay.eraser_is_button:
            eraser_bit = "False"
        if lay.invert is not None and not lay.eraser_is_button:
            eraser_terms.append(flags["invert"])
        if eraser_bit != "False":
            eraser_terms.append("erase")
            src.append(f"    erase = {eraser_bit}")
        if lay.pressure is not None:
            src.append(f"    rp = {value_expr(lay.pressure)}")
            if lay.pressure.signed:
                w = lay.pressure.width
                src.append(f"    if rp >> {w - 1}: rp -= {1 << w}")
            src.append("    if rp > P.hi or rp < P.lo: P.widen(rp)")
            src.append("    p = (rp - P.lo) * P.inv")
        if lay.tip is not None:
            tip = flags["tip"] + (" or erase" if eraser_bit != "False" else "")
        elif lay.pressure is not None:
            tip = "rp > P.lo" + (" or erase" if eraser_bit != "False" else "")
        else:
            tip = "erase" if eraser_bit != "False" else "False"
        src.append(f"    tip = {tip}")
        if lay.pressure is None:
            src.append("    p = 1.0 if tip else 0.0")
        else:
            # a barrel button reported together with a zero-pressure tip is a button click
            # (UC-Logic mouse mode, Waltop), not a touch; pressure while hovering is noise
            if lay.b1 is not None or lay.b2 is not None:
                src.append("    if tip and rp <= P.lo and (b1 or b2): tip = False")
            src.append("    if not tip: p = 0.0")
        if lay.in_range is not None:
            src.append(f"    ib = (v >> {lay.in_range}) & 1")
            src.append("    iv = C.in_range_value")
            src.append("    if iv is None: rng = C.learn_in_range(ib, tip or p > 0.0 or b1 or b2, t)")
            src.append("    else: rng = ib == iv")
            src.append("    if tip: rng = True")
        else:
            src.append("    rng = True")
        # widen X/Y only on reports that really place the pen (in range), never on leaving reports
        for name, bounds in (("x", "X"), ("y", "Y")):
            src.append(f"    if (r{name} > {bounds}.hi or r{name} < {bounds}.lo) and rng: {bounds}.widen(r{name})")
            src.append(f"    {name} = (r{name} - {bounds}.lo) * {bounds}.inv")
            src.append(f"    {name} = 0.0 if {name} < 0.0 else 1.0 if {name} > 1.0 else {name}")
        src.append("    p = 0.0 if p < 0.0 else 1.0 if p > 1.0 else p")
        src.append(f"    eraser = {' or '.join(eraser_terms) if eraser_terms else 'False'}")
        for name in ("tilt_x", "tilt_y"):
            tv = getattr(lay, name)
            if tv is None:
                src.append(f"    {name} = None")
                continue
            src.append(f"    {name} = {value_expr(tv)}")
            if tv.signed:
                src.append(f"    if {name} >> {tv.width - 1}: {name} -= {1 << tv.width}")
            src.append(f"    {name} = {name} * {tv.scale!r} + {tv.offset!r}")
            src.append(f"    {name} = {-TILT_LIMIT} if {name} < {-TILT_LIMIT} else {TILT_LIMIT} "
                       f"if {name} > {TILT_LIMIT} else float({name})")
        src.append(f"    return S(t, x, y, p, tip, rng, eraser, b1, b2, tilt_x, tilt_y, {lay.report_id})")
        namespace: dict[str, Any] = {"S": PenSample, "X": self.x, "Y": self.y, "P": self.p, "C": self}
        code = "\n".join(src)
        exec(compile(code, f"<pen layout 0x{lay.report_id:02x} {lay.source}>", "exec"), namespace)
        self.source_code = code
        return namespace["decode"]
