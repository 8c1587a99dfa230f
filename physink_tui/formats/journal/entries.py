"""The journal's header and entries as frozen values; no checking (see `value_checks`), no JSON, no I/O.

A journal is one `JournalHeader` followed by `JournalEntry` values in time order. The values are built
directly by whoever journals (the session) and by the reader; `value_checks` (over
`physink_tui.formats.json_checks`) says which ones are valid and `codec` turns them into lines.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any

from physink_tui import __version__

FORMAT = "physink-journal"
"""The header's ``"format"`` value."""

FORMAT_VERSION = 1
"""The header's ``"version"``: the one this program writes and the newest it reads."""

PROGRAM = f"physink-tui {__version__}"
"""The header's ``"program"`` as this program writes it: its name and version."""

UNKNOWN_PROGRAM = "unknown"
"""``"program"`` of a header read without one (other programs and people write journals too)."""

DEFAULT_TIP_DOWN = 0.05
"""``tip_thresholds.down`` of a header read without one: libinput's 5 % of the pressure range."""

DEFAULT_TIP_UP = 0.01
"""``tip_thresholds.up`` of a header read without one: libinput's 1 % of the pressure range."""


@dataclass(frozen=True, slots=True)
class JournalDevice:
    """One raw input device whose reports the journal records (``hid`` entries name it by `id`).

    Attributes:
        id: the key in the header's ``devices`` object, e.g. ``"tablet0"``; non-empty, unique in a header.
            The same id as `physink_tui.input.sources.RawReport.device`.
        name: the device name (HID_NAME), or None when unknown.
        bus: the bus type (3 USB, 5 Bluetooth, 0x18 I2C), or None when unknown.
        vid: the vendor id 0..0xffff, or None when unknown (the decoder's vendor quirks key on it).
        pid: the product id 0..0xffff, or None when unknown.
        descriptor: the HID report descriptor, never empty; replay decodes the reports with it.
    """

    id: str
    name: str | None
    bus: int | None
    vid: int | None
    pid: int | None
    descriptor: bytes


@dataclass(frozen=True, slots=True)
class JournalHeader:
    """The journal's first line: everything besides the entries that an exact replay needs.

    Attributes:
        canvas_width: width of the canvas, in canvas units (> 0); pen x is a fraction of it.
        canvas_height: height of the canvas, in canvas units (> 0); pen y is a fraction of it.
        devices: the raw devices, in the order written; ids unique.
        mapping: the tablet-to-canvas mapping as a JSON object: the keys of
            `physink_tui.formats.journal.header_checks.MAPPING_KEYS`, each optional; ``{}`` (the default when a header
            has none) maps the tablet's area onto the whole canvas, one to one. `physink_tui.input.pen.mapping`
            owns its meaning. A deep copy of what was passed, so changing the caller's dict later changes
            nothing; not part of the hash.
        tip_down: tip contact begins when normalised pressure rises above this (0 < tip_down <= 1);
            `DEFAULT_TIP_DOWN` when a header has no ``tip_thresholds``.
        tip_up: tip contact ends when normalised pressure falls below this (0 <= tip_up < tip_down);
            `DEFAULT_TIP_UP` when a header has no ``tip_thresholds``.
        program: the program and version that wrote the journal, e.g. ``"physink-tui 0.1.0"``;
            `UNKNOWN_PROGRAM` when a header read has none.
        vocabulary: the text of the user's vocabulary file (extra verbs and prepositions for phrases, see
            `physink_tui.timeline.phrases.parse_vocabulary`), or "" for none; written only when given.
    """

    canvas_width: float
    canvas_height: float
    devices: tuple[JournalDevice, ...]
    mapping: dict[str, Any] = field(hash=False)
    tip_down: float
    tip_up: float
    program: str = PROGRAM
    vocabulary: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "devices", tuple(self.devices))
        object.__setattr__(self, "mapping", copy.deepcopy(self.mapping))

    def device(self, device_id: str) -> JournalDevice | None:
        """The device with this id, or None.

        >>> h = JournalHeader(800, 600, (JournalDevice("pen0", None, 3, 0x56A, 0x350, b"\\xa1\\xc0"),), {}, 0.05, 0.01)
        >>> h.device("pen0").vid, h.device("pad1")
        (1386, None)
        """
        for dev in self.devices:
            if dev.id == device_id:
                return dev
        return None


@dataclass(frozen=True, slots=True)
class HidEntry:
    """A raw report from a device of the header.

    Attributes:
        t: seconds since the session start (>= 0, never less than the previous entry's).
        dev: the id of a `JournalDevice` of the header.
        data: the report bytes as read, report id first when the device uses ids; never empty.
    """

    t: float
    dev: str
    data: bytes


@dataclass(frozen=True, slots=True)
class PenEntry:
    """A pen sample already in canvas coordinates (mouse, serial and scripted input).

    Attributes:
        t: seconds since the session start (>= 0, never less than the previous entry's).
        x: 0..1 of the canvas width, left to right.
        y: 0..1 of the canvas height, top to bottom.
        p: tip pressure 0..1.
        tip: the tip (or the eraser end) touches.
        range: the pen is in proximity.
        eraser: the eraser end is the one in proximity.
        b1: first barrel button.
        b2: second barrel button.
    """

    t: float
    x: float
    y: float
    p: float
    tip: bool
    range: bool
    eraser: bool
    b1: bool
    b2: bool


@dataclass(frozen=True, slots=True)
class CommandEntry:
    """A command from a TUI key, a pad button or the CLI.

    Attributes:
        t: seconds since the session start (>= 0, never less than the previous entry's).
        name: one of `physink_tui.formats.journal.value_checks.COMMANDS` (mode, play, pause, stop, seek, clear,
            undo, redo, label, simulate, save, load, end).
        args: its arguments: ``("sketch",)`` or ``("demo",)`` for mode, one float (seconds of timeline time,
            >= 0) for seek, ``(target, text)`` for label, ``(path,)`` for save and load, up to two ints (seed
            >= 0, budget >= 1) for simulate, ``()`` for the others (``end``: the session ended at t).
        project: ``load`` only, and required there: the loaded project's JSON object as its file holds it
            (`physink_tui.formats.project.codec`), so that a replay needs no other file; None otherwise. A deep
            copy of what was passed; not part of the hash.
    """

    t: float
    name: str
    args: tuple[str | float, ...] = ()
    project: dict[str, Any] | None = field(default=None, hash=False)

    def __post_init__(self) -> None:
        if self.project is not None:
            object.__setattr__(self, "project", copy.deepcopy(self.project))


@dataclass(frozen=True, slots=True)
class SayEntry:
    """A recognised utterance, handled exactly as speech is.

    Attributes:
        t: seconds since the session start (>= 0, never less than the previous entry's).
        text: what was recognised.
    """

    t: float
    text: str


@dataclass(frozen=True, slots=True)
class DeviceEntry:
    """Devices that appeared after the header (hot-plug), written before their first report.

    Attributes:
        t: seconds since the session start (>= 0, never less than the previous entry's).
        devices: the devices, ids unique within the line; an id already known (a reconnected tablet)
            replaces that device from here on.
    """

    t: float
    devices: tuple[JournalDevice, ...]

    def __post_init__(self) -> None:
        object.__setattr__(self, "devices", tuple(self.devices))


JournalEntry = HidEntry | PenEntry | CommandEntry | SayEntry | DeviceEntry
"""Any line of the journal after the header."""
