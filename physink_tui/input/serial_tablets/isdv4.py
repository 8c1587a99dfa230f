"""Speaks the Wacom ISDV4 / W8001 serial pen protocol as bytes in, `PenSample`s out; opens no port, reads no clock.

Tablet PCs with a Wacom serial digitizer (W8001, "ISDV4") answer three one-byte commands: ``0`` stops
sampling, ``*`` asks for an 11-byte query reply (the control packet) and ``1`` starts sampling. Every packet
starts with a byte whose bit 7 (the sync bit) is set; every later byte carries 7 data bits with bit 7 clear,
which is what lets a reader find packet boundaries again after noise. The first byte says what follows:

* bit 0x10 set: a touch packet (5, 7 or 13 bytes, depending on the sensor) — not a pen sample, skipped up to
  the next sync byte;
* else bit 0x40 set: a control packet of 11 bytes (the query reply): maxima of X, Y, pressure and tilt;
* else a pen packet of 9 bytes: 0x20 proximity, 0x01 tip, 0x02 side switch 1, 0x04 side switch 2 or eraser.

X and Y are 16 bits split over three bytes (7 + 7 + 2), pressure 10 bits (7 + 3), tilt 7 bits each, in the
same places in pen packets and in the query reply; this follows the Linux kernel's
``drivers/input/touchscreen/wacom_w8001.c`` and xf86-input-wacom's ``isdv4.h`` / ``src/wcmISDV4.c``.
Opening the port, the handshake and the reading thread live in `serial_tablets.reader`.

>>> parser = Isdv4Parser(Isdv4Query(x_max=20000, y_max=15000, p_max=255))
>>> [s] = parser.feed(encode_pen_packet(10000, 3000, 51, tip=True), t=1.5)
>>> s.x, s.y, s.p, s.tip, s.range, s.eraser
(0.5, 0.2, 0.2, True, True, False)
"""

from __future__ import annotations

from dataclasses import dataclass

from physink_tui.errors import DeviceError
from physink_tui.input.pen.sample import PenSample

CMD_STOP = b"0"
"""Stop sampling (W8001_CMD_STOP / ISDV4_STOP)."""
CMD_START = b"1"
"""Start sampling (W8001_CMD_START / ISDV4_SAMPLING)."""
CMD_QUERY = b"*"
"""Ask for the 11-byte query reply (W8001_CMD_QUERY / ISDV4_QUERY)."""

SYNC_BIT = 0x80
"""Set in the first byte of every packet and in no other byte."""
CONTROL_BIT = 0x40
"""First byte of a control packet (the query reply)."""
TOUCH_BIT = 0x10
"""First byte of a touch packet (finger, not pen)."""
PROXIMITY_BIT = 0x20
TIP_BIT = 0x01
SIDE1_BIT = 0x02
SIDE2_BIT = 0x04
"""Second side switch, or the eraser end when the pen comes into proximity with it set."""

PEN_PACKET_LEN = 9
"""W8001_PKTLEN_TPCPEN / ISDV4_PKGLEN_TPCPEN."""
CONTROL_PACKET_LEN = 11
"""W8001_PKTLEN_TPCCTL / ISDV4_PKGLEN_TPCCTL."""

COORD_MAX = 0xFFFF
"""Largest X or Y a packet can carry (7 + 7 + 2 bits)."""
PRESSURE_MAX = 0x3FF
"""Largest pressure a packet can carry (7 + 3 bits)."""


@dataclass(frozen=True, slots=True)
class Isdv4Query:
    """The tablet's answer to the query command: what its values range over.

    Attributes:
        x_max: largest X, in tablet units (100 per mm on W8001 pens); 0 when the tablet has no pen.
        y_max: largest Y, likewise.
        p_max: largest pressure (typically 255 or 1023).
        tilt_x_max: largest raw tilt across X; 0 with ``tilt_y_max`` 0 means no tilt. Read from byte 7 as
            the kernel does (xf86-input-wacom's ``isdv4ParseQuery`` calls byte 7 the Y maximum instead).
        tilt_y_max: largest raw tilt across Y (byte 8).
        version: firmware version, 14 bits (0 when unknown).
    """

    x_max: int
    y_max: int
    p_max: int
    tilt_x_max: int = 0
    tilt_y_max: int = 0
    version: int = 0

    @property
    def has_pen(self) -> bool:
        """The tablet declares a pen area (touch-only ISDV4 panels answer with zero maxima)."""
        return self.x_max > 0 and self.y_max > 0

    @property
    def has_tilt(self) -> bool:
        """The tablet reports tilt: both maxima non-zero, as the kernel and xf86 driver require."""
        return self.tilt_x_max > 0 and self.tilt_y_max > 0

    def summary(self) -> str:
        """One line for listings.

        >>> Isdv4Query(26202, 16325, 255, version=0x105).summary()
        'area 26202 x 16325, pressure 0..255, no tilt, firmware version 261'
        """
        tilt = f"tilt 0..{self.tilt_x_max} x 0..{self.tilt_y_max}" if self.has_tilt else "no tilt"
        area = f"area {self.x_max} x {self.y_max}" if self.has_pen else "no pen (touch only)"
        return f"{area}, pressure 0..{self.p_max}, {tilt}, firmware version {self.version}"

    @classmethod
    def from_bytes(cls, data: bytes) -> Isdv4Query:
        """Parse the 11-byte query reply (extra bytes after it are ignored).

        Raises:
            DeviceError: fewer than 11 bytes, no sync or control bit in byte 0, or a sync bit in a data byte.

        >>> Isdv4Query.from_bytes(encode_query_reply(Isdv4Query(26202, 16325, 255, version=0x1234)))
        Isdv4Query(x_max=26202, y_max=16325, p_max=255, tilt_x_max=0, tilt_y_max=0, version=4660)
        """
        head = bytes(data[:CONTROL_PACKET_LEN])
        if len(head) < CONTROL_PACKET_LEN:
            raise DeviceError(f"ISDV4 query reply {head.hex(' ')!r} is {len(head)} bytes (expected 11)")
        if head[0] & (SYNC_BIT | CONTROL_BIT) != SYNC_BIT | CONTROL_BIT:
            raise DeviceError(
                f"ISDV4 query reply {head.hex(' ')!r} starts with 0x{head[0]:02x} (expected the sync and control bits)"
            )
        if any(b & SYNC_BIT for b in head[1:]):
            raise DeviceError(f"ISDV4 query reply {head.hex(' ')!r} has a sync bit inside (expected 7-bit data bytes)")
        return cls(
            x_max=_coord(head, 1, 5),
            y_max=_coord(head, 3, 3),
            p_max=_pressure(head),
            tilt_x_max=head[7],
            tilt_y_max=head[8],
            version=head[9] << 7 | head[10],
        )


def parse_query(data: bytes) -> Isdv4Query:
    """The query reply in ``data`` (see `Isdv4Query.from_bytes`, which raises `DeviceError`)."""
    return Isdv4Query.from_bytes(data)


FALLBACK_QUERY = Isdv4Query(x_max=COORD_MAX, y_max=COORD_MAX, p_max=PRESSURE_MAX)
"""Used when no query was answered, or for any maximum it gave as 0: the widest values a packet can carry.

Neither the kernel nor xf86-input-wacom has pen fallbacks (the kernel registers no pen when the query fails,
the only 1024x1024 default it has is for early touch panels), so the protocol's own field widths are used:
every sample stays in 0..1, at the price of a smaller area than the tablet really has."""


def _coord(p: bytes | bytearray, hi: int, low_shift: int) -> int:
    """X (bytes 1, 2 and bits 6..5 of byte 6) or Y (bytes 3, 4 and bits 4..3 of byte 6)."""
    return (p[hi] & 0x7F) << 9 | (p[hi + 1] & 0x7F) << 2 | (p[6] >> low_shift) & 0x3


def _pressure(p: bytes | bytearray) -> int:
    """Byte 5 holds the low 7 bits, bits 2..0 of byte 6 the high 3."""
    return (p[6] & 0x07) << 7 | (p[5] & 0x7F)


def _pack(b0: int, x: int, y: int, pressure: int, tilt_x: int, tilt_y: int) -> bytes:
    b6 = (x & 0x3) << 5 | (y & 0x3) << 3 | (pressure >> 7) & 0x7
    return bytes(
        (b0, x >> 9 & 0x7F, x >> 2 & 0x7F, y >> 9 & 0x7F, y >> 2 & 0x7F, pressure & 0x7F, b6, tilt_x, tilt_y)
    )


def _check(name: str, value: int, hi: int) -> None:
    if not 0 <= value <= hi:
        raise ValueError(f"{name} {value!r} is outside 0..{hi}")


def encode_pen_packet(
    x: int,
    y: int,
    pressure: int = 0,
    *,
    proximity: bool = True,
    tip: bool = False,
    side1: bool = False,
    side2: bool = False,
    tilt_x: int = 0,
    tilt_y: int = 0,
) -> bytes:
    """The 9-byte pen packet a tablet sends for these raw values (for tests and virtual serial pens).

    ``side2`` is also how a tablet says "eraser": set when the pen comes into proximity, it means the
    eraser end (see `Isdv4Parser`).

    >>> encode_pen_packet(10000, 3000, 51, tip=True).hex(" ")
    'a1 13 44 05 6e 33 00 00 00'
    """
    for name, value, hi in (("x", x, COORD_MAX), ("y", y, COORD_MAX), ("pressure", pressure, PRESSURE_MAX)):
        _check(name, value, hi)
    _check("tilt_x", tilt_x, 0x7F)
    _check("tilt_y", tilt_y, 0x7F)
    b0 = SYNC_BIT | (PROXIMITY_BIT if proximity else 0)
    b0 |= (TIP_BIT if tip else 0) | (SIDE1_BIT if side1 else 0) | (SIDE2_BIT if side2 else 0)
    return _pack(b0, x, y, pressure, tilt_x, tilt_y)


def encode_query_reply(query: Isdv4Query) -> bytes:
    """The 11-byte control packet a tablet sends in answer to the query command."""
    _check("x_max", query.x_max, COORD_MAX)
    _check("y_max", query.y_max, COORD_MAX)
    _check("p_max", query.p_max, PRESSURE_MAX)
    _check("tilt_x_max", query.tilt_x_max, 0x7F)
    _check("tilt_y_max", query.tilt_y_max, 0x7F)
    _check("version", query.version, 0x3FFF)
    head = _pack(SYNC_BIT | CONTROL_BIT, query.x_max, query.y_max, query.p_max, query.tilt_x_max, query.tilt_y_max)
    return head + bytes((query.version >> 7 & 0x7F, query.version & 0x7F))


class Isdv4Parser:
    """Turns a byte stream from an ISDV4 tablet into pen samples, across any split into chunks.

    It never raises on input: bytes outside a packet and packets cut short by a new sync byte are counted in
    ``bad_bytes`` (the first reason kept in ``first_bad_reason``) and parsing resumes at the next sync byte.
    Touch packets and control packets are counted, not decoded into samples; a control packet (a late query
    reply) replaces the maxima in use.

    The pen's tool follows the kernel's rule, since one bit means both "side switch 2" and "eraser": a pen that
    comes into proximity with that bit set is the eraser end; once in proximity, the bit is the second side
    switch. When an eraser loses the bit while staying in proximity, the eraser leaves (one extra sample out
    of range) and the pen tip arrives. X, Y and pressure are scaled by the query's maxima; a value past one
    (on a packet in proximity) widens that maximum, as libinput does, and the name lands in ``widened``.
    Tilt is given only when the query declares both tilt maxima, in degrees assuming the middle raw value is
    upright and one unit per degree (Wacom's convention on its USB pens; the serial sources only pass raw
    values on).

    Attributes:
        query: the maxima in use (the query given, a control packet seen since, or `FALLBACK_QUERY`).
        bad_bytes: bytes discarded as not belonging to any packet.
        first_bad_reason: why the first of them was discarded, or None.
        pen_packets: pen packets decoded.
        touch_packets: touch packets skipped.
        control_packets: control packets (query replies) seen.
        widened: names of values ("x", "y", "p") whose maximum had to widen.
    """

    def __init__(self, query: Isdv4Query | None = None) -> None:
        self.query = query
        self.bad_bytes = 0
        self.first_bad_reason: str | None = None
        self.pen_packets = 0
        self.touch_packets = 0
        self.control_packets = 0
        self.widened: set[str] = set()
        self._buf = bytearray()
        self._in_touch = False
        self._tool: str | None = None  # None out of proximity, else "pen" or "eraser"
        self._use(query)

    def _use(self, query: Isdv4Query | None) -> None:
        q = query or FALLBACK_QUERY
        self._x_max = q.x_max or FALLBACK_QUERY.x_max
        self._y_max = q.y_max or FALLBACK_QUERY.y_max
        self._p_max = q.p_max or FALLBACK_QUERY.p_max
        self._tilt = ((q.tilt_x_max + 1) / 2, (q.tilt_y_max + 1) / 2) if q.has_tilt else None

    def _bad(self, count: int, reason: str) -> None:
        self.bad_bytes += count
        if self.first_bad_reason is None:
            self.first_bad_reason = reason

    def feed(self, data: bytes, t: float) -> list[PenSample]:
        """Parse ``data`` (any number of bytes, continuing earlier calls); samples get time ``t`` (seconds).

        A packet not yet complete stays buffered for the next call.
        """
        buf = self._buf
        buf += data
        out: list[PenSample] = []
        i, n = 0, len(buf)
        while i < n:
            b0 = buf[i]
            if not b0 & SYNC_BIT:
                if not self._in_touch:
                    self._bad(1, f"byte 0x{b0:02x} without the sync bit outside a packet")
                i += 1
                continue
            self._in_touch = False
            if b0 & TOUCH_BIT:  # touch lengths depend on the sensor: skip to the next sync byte
                self.touch_packets += 1
                self._in_touch = True
                i += 1
                continue
            length = CONTROL_PACKET_LEN if b0 & CONTROL_BIT else PEN_PACKET_LEN
            end = min(n, i + length)
            cut = next((j for j in range(i + 1, end) if buf[j] & SYNC_BIT), None)
            if cut is not None:
                kind = "control" if length == CONTROL_PACKET_LEN else "pen"
                self._bad(cut - i, f"{kind} packet 0x{b0:02x} cut short after {cut - i} bytes by a new sync byte")
                i = cut
                continue
            if end - i < length:
                break  # wait for the rest
            packet = bytes(buf[i:end])
            i = end
            if length == CONTROL_PACKET_LEN:
                self.control_packets += 1
                self.query = Isdv4Query.from_bytes(packet)  # cannot fail: sync, control and data bits checked
                self._use(self.query)
            else:
                self.pen_packets += 1
                self._decode(packet, t, out)
        del buf[:i]
        return out

    def _decode(self, pkt: bytes, t: float, out: list[PenSample]) -> None:
        b0 = pkt[0]
        rdy, tsw, f1, f2 = bool(b0 & PROXIMITY_BIT), bool(b0 & TIP_BIT), bool(b0 & SIDE1_BIT), bool(b0 & SIDE2_BIT)
        rx, ry, rp = _coord(pkt, 1, 5), _coord(pkt, 3, 3), _pressure(pkt)
        if rdy:
            if rx > self._x_max:
                self._x_max = rx
                self.widened.add("x")
            if ry > self._y_max:
                self._y_max = ry
                self.widened.add("y")
            if rp > self._p_max:
                self._p_max = rp
                self.widened.add("p")
        x, y = min(rx / self._x_max, 1.0), min(ry / self._y_max, 1.0)
        tilt_x = tilt_y = None
        if self._tilt is not None:
            tilt_x, tilt_y = pkt[7] - self._tilt[0], pkt[8] - self._tilt[1]
        if self._tool == "eraser" and not f2:
            # the kernel's fake proximity-out: the eraser end leaves, then the tip comes in
            out.append(PenSample(t, x, y, 0.0, False, False, True, False, False, tilt_x, tilt_y, 0))
            self._tool = "pen"
        elif self._tool is None:
            self._tool = "eraser" if f2 else "pen"
        eraser = self._tool == "eraser"
        tip = tsw and rdy
        p = min(rp / self._p_max, 1.0) if tip else 0.0
        out.append(PenSample(t, x, y, p, tip, rdy, eraser, f1 and rdy, f2 and rdy and not eraser, tilt_x, tilt_y, 0))
        if not rdy:
            self._tool = None
