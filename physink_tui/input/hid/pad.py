"""Pad buttons (ExpressKeys) in a tablet's reports: which buttons a report says are held; pure over the descriptor,
reads no device. What a button does is the caller's (the kiosk maps them to commands).

Two sources of facts:

- the descriptor: an input report with no pen layout (`HidPenDecoder.layouts`) whose variable one-bit fields carry
  Button-page usages (0x09: button N is usage N) in a pad's application collection (`PAD_APPLICATIONS`: Keypad,
  Tablet Function Keys, or none at all as XP-Pen's Deco 01 has it) — never a Mouse collection, whose buttons are
  a mouse's (tablets in mouse mode);
- the UC-Logic vendor protocols, which describe nothing: in Huion "v2" mode (report 0x08, 12 bytes) and UC-Logic
  "v1" mode (report 0x07) a report whose byte 1 is 0xE0 is a pad report, the held buttons a bitmask in bytes 4-5,
  little-endian, bit 0 being button 1 (seen in a Huion HS610 capture: ``08 e0 01 01 01 00 ...`` while the first key
  is held, ``... 02 00`` the second, ``... 00 00`` on release).
"""

from __future__ import annotations

from physink_tui.input.hid.decoder import HidPenDecoder

BUTTON_PAGE = 0x0009
PAD_APPLICATIONS = (0x0001_0007, 0x000D_0039, 0)
"""Application collections whose buttons are a pad's: Generic Desktop Keypad, Digitizer Tablet Function Keys, none."""
PAD_FRAME = 0xE0
VENDOR_PAD_PROTOCOLS = ("huion-v2", "uclogic-v1")


class PadDecoder:
    """The pad of one tablet.

    Raises:
        DescriptorError: the descriptor describes no pen (nor does a vendor protocol), as `HidPenDecoder`.
    """

    def __init__(self, descriptor: bytes, vid: int | None = None, pid: int | None = None,
                 name: str | None = None) -> None:
        pen = HidPenDecoder(descriptor, vid, pid, name=name)
        self.uses_ids = pen.uses_ids
        self._vendor = {rid for rid, layout in pen.layouts.items() if layout.source in VENDOR_PAD_PROTOCOLS}
        self._bits: dict[int, list[tuple[int, int]]] = {}  # report id -> (bit offset, button number)
        for report in pen.descriptor.input_reports():
            if report.report_id in pen.layouts:
                continue
            for f in report.fields:
                if f.is_constant or not f.is_variable or f.size != 1 or f.application not in PAD_APPLICATIONS:
                    continue
                for i in range(f.count):
                    usage = f.usage_at(i)
                    if usage >> 16 == BUTTON_PAGE and usage & 0xFFFF:
                        self._bits.setdefault(report.report_id, []).append((f.bit_offset + i, usage & 0xFFFF))

    def buttons(self, data: bytes) -> frozenset[int] | None:
        """The buttons (numbered from 1) that ``data`` says are held, or None when it is no pad report."""
        if not data:
            return None
        rid = data[0] if self.uses_ids else 0
        if rid in self._vendor:
            if len(data) < 6 or data[1] != PAD_FRAME:
                return None
            mask = data[4] | data[5] << 8
            return frozenset(i + 1 for i in range(16) if mask >> i & 1)
        bits = self._bits.get(rid)
        if bits is None:
            return None
        return frozenset(n for offset, n in bits if offset // 8 < len(data) and data[offset // 8] >> (offset % 8) & 1)
