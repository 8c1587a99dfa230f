"""The input side's single consumer: source items in, gestures out (decode, map, smooth, follow the pen).

`PenInput` knows each source's device: HID devices are decoded with their `HidPenDecoder`; sources
that decode themselves (serial tablets) report tablet positions that still need the mapping; the
TUI's mouse, scripts and journal ``pen`` lines are already in canvas coordinates. Each device has
its own `GestureEngine`. It reads no clock and no device: the items carry their times.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from physink_tui.errors import DeviceError
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.pen.gestures import Gesture, GestureConfig, GestureEngine, StrokePoint
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.pen.smoothing import PositionSmoother
from physink_tui.input.sources import RawReport, SampleReady, SourceEnded, SourceItem


@dataclass
class _Device:
    decoder: HidPenDecoder | None
    canvas_space: bool
    engine: GestureEngine
    smoother: PositionSmoother | None
    ended: list[SourceEnded] = field(default_factory=list)


class PenInput:
    """Routes source items to their device's decoder, mapping and gesture engine.

    Args:
        mapping: tablet-to-canvas mapping for tablet-space devices.
        config: gesture thresholds (tip hysteresis included).
        smoothing: average consecutive touching positions (at most half a sample of lag).
    """

    def __init__(self, mapping: TabletMapping | None = None, config: GestureConfig | None = None,
                 smoothing: bool = False) -> None:
        self.mapping = mapping or TabletMapping()
        self.config = config or GestureConfig()
        self.smoothing = smoothing
        self.devices: dict[str, _Device] = {}

    def _new(self, decoder: HidPenDecoder | None, canvas_space: bool) -> _Device:
        return _Device(decoder, canvas_space, GestureEngine(self.config),
                       PositionSmoother() if self.smoothing else None)

    def add_hid_device(self, device_id: str, decoder: HidPenDecoder) -> None:
        """A HID tablet: its reports are decoded, then mapped onto the canvas."""
        self.devices[device_id] = self._new(decoder, canvas_space=False)

    def add_sample_device(self, device_id: str, canvas_space: bool) -> None:
        """A source that sends samples: in canvas coordinates (mouse, script, journal) or tablet ones (serial)."""
        self.devices[device_id] = self._new(None, canvas_space)

    def _device(self, device_id: str) -> _Device:
        try:
            return self.devices[device_id]
        except KeyError:
            known = ", ".join(sorted(self.devices)) or "none"
            raise DeviceError(f"input from unknown device {device_id!r} (known: {known})") from None

    def handle(self, item: SourceItem) -> list[Gesture]:
        """Consume one item; return the gestures it completes."""
        if type(item) is RawReport:
            dev = self._device(item.device)
            if dev.decoder is None:
                raise DeviceError(f"device {item.device!r} sends samples, not HID reports")
            sample = dev.decoder.decode(item.data, item.t)
            return [] if sample is None else self._feed(dev, sample)
        if type(item) is SampleReady:
            return self._feed(self._device(item.device), item.sample)
        if type(item) is SourceEnded:
            dev = self._device(item.device)
            dev.ended.append(item)
            return dev.engine.device_lost(item.t) if item.error is not None or dev.engine.drawing else []
        raise TypeError(f"not a source item: {item!r}")

    def tick(self, t: float) -> list[Gesture]:
        """Time passed to ``t`` without input: the gestures that completes (a dwell), device by device."""
        return [g for dev in self.devices.values() for g in dev.engine.tick(t)]

    def ink(self) -> tuple[tuple[StrokePoint, ...], ...]:
        """The strokes being drawn now, one per device with its pen down (canvas fractions)."""
        return tuple(ink for dev in self.devices.values() if (ink := dev.engine.ink))

    def feed_canvas_sample(self, device_id: str, sample: PenSample) -> list[Gesture]:
        """A sample already in canvas coordinates (journal ``pen`` lines)."""
        dev = self._device(device_id)
        return self._feed(dev, sample)

    def _feed(self, dev: _Device, sample: PenSample) -> list[Gesture]:
        if not dev.canvas_space:
            x, y = self.mapping.to_canvas(sample.x, sample.y)
            sample = sample._replace(x=x, y=y)
        if dev.smoother is not None:
            sample = dev.smoother.apply(sample)
        return dev.engine.feed(sample)
