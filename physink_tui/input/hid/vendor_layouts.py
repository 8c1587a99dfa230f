"""Pen layouts for vendor protocols no descriptor describes, and the device profile table; no I/O.

What each protocol looks like is taken from the Linux kernel drivers that handle it
(hid-uclogic, hid-kye, hid-waltop, wacom) and checked against real captures:

* UC-Logic/Huion "v1": report 0x07, 8 bytes, after reading string descriptor 0x64; byte 1 has
  tip, two buttons and an in-range bit whose polarity differs by model; X, Y, pressure LE16.
* Huion "v2": report 0x08, 12 bytes, after reading string descriptor 0xC8; X and Y are 24 bits
  split across bytes 2-3/8 and 4-5/9, tilt in bytes 10 and 11; byte 1 0xE0/0xF0 are pad reports.
* Older Wacom (Graphire, Volito, PenStation, Bamboo 1): report 0x02 with proximity and tool type
  in byte 1 (``wacom_graphire_irq``); PenPartner: report 0x01 (``wacom_penpartner_irq``).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from physink_tui.input.hid.descriptor import ReportDescriptor
from physink_tui.input.hid.device_facts import match_device
from physink_tui.input.hid.fixed_layouts import FIXED_DEVICES, fixed_layouts
from physink_tui.input.hid.pen_layout import PenLayout, ValueField, pen_layouts

VID_WACOM = 0x056A
VID_UCLOGIC = 0x5543
VID_HUION = 0x256C
VID_XPPEN = 0x28BD
VID_VEIKK = 0x2FEB
VID_KYE = 0x0458
VID_10MOONS = 0x08F2

# Families whose pens have two barrel buttons and no eraser: their descriptors call the second
# button "Eraser" or "Invert" (hid-uclogic and hid-kye rewrite that bit to BTN_STYLUS2).
TWO_BUTTON_FAMILIES = {VID_UCLOGIC, VID_HUION, VID_XPPEN, VID_VEIKK, VID_KYE, VID_10MOONS}
# Families whose in-range bit polarity differs between models (learnt from the data).
UNCERTAIN_IN_RANGE_FAMILIES = {VID_UCLOGIC, VID_HUION, VID_XPPEN, VID_VEIKK, VID_10MOONS}


@dataclass(frozen=True, slots=True)
class TabletParams:
    """Tablet facts a descriptor may not tell: maxima from a vendor string descriptor or a profile.

    Attributes:
        x_max, y_max: logical maxima of the pen's X and Y.
        p_max: logical maximum of pressure.
        resolution: lines per inch, 0 when unknown.
    """

    x_max: int
    y_max: int
    p_max: int
    resolution: int = 0

    @classmethod
    def from_uclogic_v1(cls, data: bytes) -> TabletParams | None:
        """Parse the reply to USB string descriptor 0x64 (UTF-16LE payload after the 2-byte header).

        Little-endian 16-bit words at payload offsets 2 (X max), 4 (Y max), 8 (pressure max),
        10 (resolution), as hid-uclogic's ``uclogic_params_pen_init_v1`` reads them.
        """
        if len(data) < 12:
            return None
        x, y, p, r = (int.from_bytes(data[i : i + 2], "little") for i in (2, 4, 8, 10))
        if not x or not y:
            return None
        return cls(x, y, p or 1023, r)

    @classmethod
    def from_huion_v2(cls, data: bytes) -> TabletParams | None:
        """Parse the reply to string descriptor 0xC8: 24-bit X and Y maxima at offsets 2 and 5,
        pressure at 8, resolution at 10 (``uclogic_params_pen_init_v2``)."""
        if len(data) < 12:
            return None
        x = int.from_bytes(data[2:5], "little")
        y = int.from_bytes(data[5:8], "little")
        p = int.from_bytes(data[8:10], "little")
        r = int.from_bytes(data[10:12], "little")
        if not x or not y:
            return None
        return cls(x, y, p or 8191, r)


def _v(off: int, size: int, hi: int, lo: int = 0, signed: bool = False) -> ValueField:
    return ValueField(((off, size),), signed, lo, max(hi, lo + 1))


def uclogic_v1_layout(params: TabletParams, report_id: int = 0x07) -> PenLayout:
    """The v1 pen report: in-range polarity is learnt, since models disagree."""
    return PenLayout(
        report_id=report_id, length=8, source="uclogic-v1",
        x=_v(16, 16, params.x_max), y=_v(32, 16, params.y_max), pressure=_v(48, 16, params.p_max),
        tip=8, b1=9, b2=10, in_range=14, learn_in_range=True, in_range_inverted=True,
        frame_byte=(1, 0xF0, (0xE0,)),
    )


def huion_v2_layout(params: TabletParams, report_id: int = 0x08) -> PenLayout:
    """The v2 pen report with 24-bit coordinates and tilt."""
    return PenLayout(
        report_id=report_id, length=12, source="huion-v2",
        x=ValueField(((16, 16), (64, 8)), False, 0, params.x_max),
        y=ValueField(((32, 16), (72, 8)), False, 0, params.y_max),
        pressure=_v(48, 16, params.p_max),
        tilt_x=_v(80, 8, 127, -127, signed=True), tilt_y=_v(88, 8, 127, -127, signed=True),
        tip=8, b1=9, b2=10, in_range=15,
        frame_byte=(1, 0xF0, (0xE0, 0xF0)),
    )


def wacom_graphire_layout(params: TabletParams) -> PenLayout:
    """Graphire-protocol pen report 0x02; tool 0 pen, 1 eraser, 2 mouse, 3 lens."""
    return PenLayout(
        report_id=0x02, length=8, source="wacom-graphire",
        x=_v(16, 16, params.x_max), y=_v(32, 16, params.y_max),
        pressure=ValueField(((48, 8), (56, 2)), False, 0, max(params.p_max, 1)),
        tip=8, b1=9, b2=10, in_range=15, tool=(13, 2), pen_tools=(0, 1), eraser_tools=(1,),
    )


def wacom_penpartner_layout(params: TabletParams) -> PenLayout:
    """PenPartner report 0x01: pressure is a signed byte (-127 = no pressure), eraser bit 5 of byte 5."""
    return PenLayout(
        report_id=0x01, length=7, source="wacom-penpartner",
        x=_v(8, 16, params.x_max), y=_v(24, 16, params.y_max),
        pressure=ValueField(((48, 8),), True, -127, 127),
        in_range=47, b1=46, tool=(45, 1), pen_tools=(0, 1), eraser_tools=(1,),
    )


@dataclass(frozen=True, slots=True)
class Profile:
    """What we know of one tablet model beyond its descriptor.

    Attributes:
        name: the model, for `physink devices` and summaries.
        protocol: ``uclogic-v1``, ``huion-v2``, ``wacom-graphire``, ``wacom-penpartner`` or
            ``descriptor`` (the descriptor is right; only quirks apply).
        params: true maxima, or None to take the descriptor's (or the vendor string's) values.
    """

    name: str
    protocol: str = "descriptor"
    params: TabletParams | None = None


# Keyed by (vid, pid). Maxima from the kernel's wacom_wac.c feature table and uclogic-probe output.
PROFILES: dict[tuple[int, int], Profile] = {
    (VID_WACOM, 0x0000): Profile("Wacom PenPartner", "wacom-penpartner", TabletParams(5040, 3780, 255)),
    (VID_WACOM, 0x0010): Profile("Wacom Graphire", "wacom-graphire", TabletParams(10206, 7422, 511)),
    (VID_WACOM, 0x0011): Profile("Wacom Graphire2 4x5", "wacom-graphire", TabletParams(10206, 7422, 511)),
    (VID_WACOM, 0x0012): Profile("Wacom Graphire2 5x7", "wacom-graphire", TabletParams(13918, 10206, 511)),
    (VID_WACOM, 0x0013): Profile("Wacom Graphire3", "wacom-graphire", TabletParams(10208, 7424, 511)),
    (VID_WACOM, 0x0014): Profile("Wacom Graphire3 6x8", "wacom-graphire", TabletParams(16704, 12064, 511)),
    (VID_WACOM, 0x0015): Profile("Wacom Graphire4 4x5", "wacom-graphire", TabletParams(10208, 7424, 511)),
    (VID_WACOM, 0x0016): Profile("Wacom Graphire4 6x8", "wacom-graphire", TabletParams(16704, 12064, 511)),
    (VID_WACOM, 0x0017): Profile("Wacom BambooFun 4x5", "wacom-graphire", TabletParams(14760, 9225, 511)),
    (VID_WACOM, 0x0018): Profile("Wacom BambooFun 6x8", "wacom-graphire", TabletParams(21648, 13530, 511)),
    (VID_WACOM, 0x0019): Profile("Wacom Bamboo1 Medium", "wacom-graphire", TabletParams(16704, 12064, 511)),
    (VID_WACOM, 0x0060): Profile("Wacom Volito", "wacom-graphire", TabletParams(5104, 3712, 511)),
    (VID_WACOM, 0x0061): Profile("Wacom PenStation2", "wacom-graphire", TabletParams(3250, 2320, 255)),
    (VID_WACOM, 0x0062): Profile("Wacom Volito2 4x5", "wacom-graphire", TabletParams(5104, 3712, 511)),
    (VID_WACOM, 0x0063): Profile("Wacom Volito2 2x3", "wacom-graphire", TabletParams(3248, 2320, 511)),
    (VID_WACOM, 0x0064): Profile("Wacom PenPartner2", "wacom-graphire", TabletParams(3250, 2320, 511)),
    (VID_WACOM, 0x0065): Profile("Wacom Bamboo", "wacom-graphire", TabletParams(14760, 9225, 511)),
    (VID_WACOM, 0x0069): Profile("Wacom Bamboo1", "wacom-graphire", TabletParams(5104, 3712, 511)),
    (VID_WACOM, 0x006A): Profile("Wacom Bamboo1 4x6", "wacom-graphire", TabletParams(14760, 9225, 1023)),
    (VID_WACOM, 0x006B): Profile("Wacom Bamboo1 5x8", "wacom-graphire", TabletParams(21648, 13530, 1023)),
    (VID_HUION, 0x006D): Profile("Huion (v2 protocol)", "huion-v2"),
    (VID_HUION, 0x006E): Profile("Huion (v1 protocol)", "uclogic-v1"),
    (VID_UCLOGIC, 0x0081): Profile("Ugee M708 / UC-Logic 1060", "uclogic-v1", TabletParams(40000, 24000, 2047)),
}

# Fallbacks when neither a profile nor the vendor string gives maxima: ranges then widen with data.
DEFAULT_V2_PARAMS = TabletParams(50800, 31750, 8191)
DEFAULT_GRAPHIRE_PARAMS = TabletParams(10206, 7422, 511)
# Wacom PIDs below this are the Graphire/Volito/PenStation/Bamboo1 generation; newer tablets without a
# standard pen report (Intuos BT, Bamboo touch) speak protocols not built here and get no layout.
OLDER_WACOM_PID_LIMIT = 0x0080


def _declared_v1_params(layouts: dict[int, PenLayout]) -> TabletParams | None:
    """The device's own descriptor usually declares report 0x07 with the true maxima."""
    lay = layouts.get(0x07)
    if lay is None or lay.pressure is None:
        return None
    return TabletParams(lay.x.hi, lay.y.hi, lay.pressure.hi)


def _two_button_fix(lay: PenLayout) -> PenLayout:
    """Bits 1 and 2 of the flags byte are the barrel buttons on two-button, eraserless pens."""
    if lay.tip != (8 if lay.report_id else 0):
        return lay
    base = lay.tip
    declared_b2 = lay.b2 is not None and lay.b2 == base + 2
    if declared_b2 and lay.eraser is None and lay.invert is None:
        return lay
    return replace(lay, b1=base + 1, b2=base + 2, eraser=None, invert=None)


def device_layouts(
    descriptor: ReportDescriptor,
    vid: int | None = None,
    pid: int | None = None,
    params: TabletParams | None = None,
    protocol: str | None = None,
    name: str | None = None,
    notes: list[str] | None = None,
) -> dict[int, PenLayout]:
    """All pen layouts for a device: the descriptor's, patched by vendor knowledge, plus vendor
    reports the descriptor does not describe.

    Args:
        descriptor: the parsed report descriptor as read from the device.
        vid, pid: USB ids, when known.
        params: maxima read from the device at initialisation (string descriptor 0x64 or 0xC8).
        protocol: force a vendor protocol (e.g. ``uclogic-v1`` after a v1 initialisation).
        name: the device's name, to choose a model where one VID:PID covers several.
        notes: warnings for the user are appended here (maxima from device facts or inferred).
    """
    notes = notes if notes is not None else []
    layouts = pen_layouts(descriptor)
    fixed = fixed_layouts(descriptor, vid, pid)
    if fixed:
        model = FIXED_DEVICES[(vid or 0, pid or 0)].name
        notes.append(f"{model}: the descriptor is the device's own vendor one; pen report decoded "
                     "from the layout Linux substitutes for it")
        return {**layouts, **fixed}
    profile = PROFILES.get((vid or 0, pid or 0))
    if vid in TWO_BUTTON_FAMILIES:
        layouts = {rid: _two_button_fix(lay) for rid, lay in layouts.items()}
    if vid in UNCERTAIN_IN_RANGE_FAMILIES:
        layouts = {
            rid: replace(lay, learn_in_range=True) if lay.in_range is not None else lay
            for rid, lay in layouts.items()
        }
    protocol = protocol or (profile.protocol if profile else None)
    params = params or (profile.params if profile else None)
    if vid in (VID_HUION, VID_UCLOGIC, VID_XPPEN, VID_VEIKK) or protocol == "uclogic-v1":
        # the v1 report 0x07 is sent after a v1 initialisation even by tablets whose descriptor
        # declares only the mouse-mode report; where the descriptor declares 0x07 keep its layout
        v1_params = params or _declared_v1_params(layouts)
        if 0x07 not in layouts and (protocol == "uclogic-v1" or v1_params is not None) and v1_params:
            layouts[0x07] = uclogic_v1_layout(v1_params)
        elif 0x07 in layouts and layouts[0x07].length == 8:
            layouts[0x07] = replace(layouts[0x07], frame_byte=(1, 0xF0, (0xE0,)))
    if protocol == "huion-v2" or (vid == VID_HUION and _has_vendor_report(descriptor, 0x08, 12)):
        if 0x08 not in layouts or layouts[0x08].source != "descriptor":
            layouts[0x08] = huion_v2_layout(params or _fact_params(vid, pid, name, notes) or _assumed(vid, pid, notes))
    elif not layouts and vid in (VID_HUION, VID_UCLOGIC) and descriptor.input_report(0x08) is not None:
        # recorded after the kernel switched the tablet on: only the vendor report 0x08 is declared,
        # often shorter than the 12 bytes the tablet sends, and no vendor-init note gives the maxima
        layouts[0x08] = huion_v2_layout(params or _fact_params(vid, pid, name, notes) or _inferred(vid, pid, notes))
    older_wacom = vid == VID_WACOM and (pid or 0) < OLDER_WACOM_PID_LIMIT
    if protocol == "wacom-graphire" or (older_wacom and not layouts and _has_vendor_report(descriptor, 0x02)):
        layouts[0x02] = wacom_graphire_layout(params or DEFAULT_GRAPHIRE_PARAMS)
    if protocol == "wacom-penpartner":
        layouts[0x01] = wacom_penpartner_layout(params or TabletParams(5040, 3780, 255))
    return layouts


def _fact_params(vid: int | None, pid: int | None, name: str | None, notes: list[str]) -> TabletParams | None:
    """Maxima from the device facts table when it can name the model."""
    found = match_device(vid, pid, name)
    if found.fact is None:
        return None
    notes.append(f"maxima from {found.why}: x {found.fact.x_max}, y {found.fact.y_max}, "
                 f"pressure {found.fact.p_max}")
    return TabletParams(found.fact.x_max, found.fact.y_max, found.fact.p_max or DEFAULT_V2_PARAMS.p_max)


def _assumed(vid: int | None, pid: int | None, notes: list[str]) -> TabletParams:
    """The common v2 size when nothing names the model; ranges still widen past it."""
    d = DEFAULT_V2_PARAMS
    notes.append(f"maxima unknown ({match_device(vid, pid).why}): assumed x {d.x_max}, y {d.y_max}, "
                 f"pressure {d.p_max}, the common v2 size (ranges widen if the pen goes further)")
    return d


def _inferred(vid: int | None, pid: int | None, notes: list[str]) -> TabletParams:
    """Maxima no fact gives: the ranges start empty and widen to the largest values seen, as libinput does."""
    why = match_device(vid, pid).why
    notes.append(f"maxima unknown ({why}): x, y and pressure ranges inferred from the largest values seen")
    return TabletParams(1, 1, 1)


def _has_vendor_report(descriptor: ReportDescriptor, report_id: int, min_length: int = 0) -> bool:
    """Whether the descriptor has an input report with this id that is not a standard pen report,
    of at least ``min_length`` bytes (or the report is absent: vendor modes often are)."""
    report = descriptor.input_report(report_id)
    if report is None:
        return report_id == 0x02  # older Wacom: the pen report is not declared at all
    return report.size_bytes >= min_length
