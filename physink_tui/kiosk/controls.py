"""Finds the kiosk's controls in the tablet's own reports: a pen tap in a hot zone or a pad button pressed becomes
the command it triggers, and the reports of it are held back from the session; decides nothing about sessions.

The kiosk decodes each report a second time, beside the session, with the same decoder and tip thresholds the
session will use (`HidPenDecoder`, `PenStateMachine`), to know where the pen is. A touch that *begins* in a zone is
a press: its reports, from the touch to the lift, are not passed on (so the session never sees a stroke there),
and lifting the pen inside the same zone triggers the zone's action (lifting elsewhere cancels it, as a button
does). A stroke that begins on the drawing area is the session's even if it wanders into a zone. Hovering is
always passed on. A pad report (`PadDecoder`) is held back; a button going down in it is pressed. The commands are
journaled as what they triggered, so replays never look at zones or pads again.
"""

from __future__ import annotations

from dataclasses import dataclass

from physink_tui.formats.journal.entries import JournalDevice
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.pad import PadDecoder
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.pen.state import PenState, PenStateMachine, TipThresholds
from physink_tui.kiosk.hot_zones import HotZone, HotZones

PASS = "pass"
HOLD = "hold"
PRESS = "press"


@dataclass(frozen=True, slots=True)
class Verdict:
    """What to do with one report: ``pass`` it to the session, ``hold`` it back, or ``press`` (hold it back: the
    zone's button was pressed, ``zone`` says which; or pad buttons went down, ``pad`` says which, lowest first);
    ``touch_began`` is True on the report where a touch began (on the drawing area or in a zone)."""

    what: str
    zone: HotZone | None = None
    touch_began: bool = False
    pad: tuple[int, ...] = ()


class ControlFilter:
    """Follows one tablet's pen through its reports and tells the hot-zone presses apart from drawing.

    Args:
        device: the tablet as the journal names it (its descriptor decodes the reports); None for a tablet whose
            samples come decoded already (serial), which are given to `sample`.
        zones: the hot zones.
        thresholds: the session's tip thresholds (the journal header's).

    Raises:
        DescriptorError: the descriptor describes no pen (the session could not use it either).
    """

    def __init__(self, device: JournalDevice | None, zones: HotZones, thresholds: TipThresholds) -> None:
        self.decoder = self.pad = None
        if device is not None:
            self.decoder = HidPenDecoder(device.descriptor, device.vid, device.pid, name=device.name or None)
            self.pad = PadDecoder(device.descriptor, device.vid, device.pid, name=device.name or None)
        self._held: frozenset[int] = frozenset()
        self.zones = zones
        self._pen = PenStateMachine(thresholds)
        self._pressing: HotZone | None = None  # the zone a touch began in, until the lift

    def report(self, data: bytes, t: float) -> Verdict:
        """The verdict on one report read at ``t``."""
        assert self.decoder is not None and self.pad is not None, "a tablet without a descriptor gives samples"
        buttons = self.pad.buttons(data)
        if buttons is not None:
            pressed, self._held = tuple(sorted(buttons - self._held)), buttons
            return Verdict(PRESS if pressed else HOLD, pad=pressed)
        sample = self.decoder.decode(data, t)
        if sample is None:
            return Verdict(PASS)  # not a pen report: the session decides what it is
        return self.sample(sample)

    def sample(self, sample: PenSample) -> Verdict:
        """The verdict on one pen sample (in tablet space)."""
        was_touching = self._pen.state.in_contact
        self._pen.follow(sample)
        touching = self._pen.state.in_contact
        if touching and not was_touching:
            self._pressing = self.zones.at(sample.x, sample.y)
            return Verdict(PASS if self._pressing is None else HOLD, self._pressing, touch_began=True)
        if self._pressing is None:
            return Verdict(PASS)
        if touching:
            return Verdict(HOLD, self._pressing)
        zone, self._pressing = self._pressing, None  # the lift ends the press
        released_inside = zone.contains(sample.x, sample.y) or self._pen.state is PenState.OUT_OF_RANGE
        return Verdict(PRESS if released_inside else HOLD, zone)
