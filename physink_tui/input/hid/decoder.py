"""Turns a device's raw HID reports into `PenSample`s, one at a time, counting what it skips.

Builds the layouts of one device (descriptor plus vendor knowledge), compiles each, and routes
every report by its id. It never raises on a report: truncated, unknown or non-pen reports are
counted by reason, and the first one is remembered for the summary. Batch decoding of whole
captures lives in `batch`; reading devices lives elsewhere.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from physink_tui.errors import DescriptorError
from physink_tui.input.hid.descriptor import ReportDescriptor
from physink_tui.input.hid.pen_decoder import CompiledLayout
from physink_tui.input.hid.pen_layout import PenLayout
from physink_tui.input.hid.vendor_layouts import TabletParams, device_layouts
from physink_tui.input.pen.sample import PenSample


@dataclass
class DecodeStats:
    """Counts of one decoding run.

    Attributes:
        reports: reports read.
        samples: pen samples produced.
        ignored: reports that gave no sample, by reason.
        first_ignored: ``(where, reason)`` of the first ignored report; ``where`` is the capture
            line or the report's index.
        backwards: reports whose timestamp went backwards.
        widened: names of values whose range had to widen past the declared logical range.
        warnings: things the decoder chose for the user to know (descriptor items skipped,
            maxima taken from device facts or inferred from the data), printed in the summary.
    """

    reports: int = 0
    samples: int = 0
    ignored: Counter = field(default_factory=Counter)
    first_ignored: tuple[int, str] | None = None
    backwards: int = 0
    widened: set[str] = field(default_factory=set)
    warnings: list[str] = field(default_factory=list)

    def ignore(self, where: int, reason: str) -> None:
        self.ignored[reason] += 1
        if self.first_ignored is None:
            self.first_ignored = (where, reason)

    def summary(self) -> str:
        """One paragraph for stderr: counts, reasons, first ignored report."""
        lines = [f"{self.reports} reports read, {self.samples} pen samples"]
        lines.extend(f"  warning: {w}" for w in self.warnings)
        for reason, n in sorted(self.ignored.items(), key=lambda kv: (-kv[1], kv[0])):
            lines.append(f"  ignored {n}: {reason}")
        if self.first_ignored is not None:
            where, reason = self.first_ignored
            lines.append(f"  first ignored report at line {where}: {reason}")
        if self.backwards:
            lines.append(f"  {self.backwards} reports with timestamps going backwards")
        if self.widened:
            lines.append(f"  values past the declared logical range (range widened): {', '.join(sorted(self.widened))}")
        return "\n".join(lines)


class HidPenDecoder:
    """Decoder for one device.

    >>> from physink_tui.input.hid.descriptor import ReportDescriptor
    >>> HidPenDecoder(bytes.fromhex("05010902a101c0"))
    Traceback (most recent call last):
    ...
    physink_tui.errors.DescriptorError: descriptor describes no pen report ...
    """

    def __init__(
        self,
        descriptor: bytes,
        vid: int | None = None,
        pid: int | None = None,
        params: TabletParams | None = None,
        protocol: str | None = None,
        name: str | None = None,
    ) -> None:
        self.descriptor = ReportDescriptor.from_bytes(descriptor)
        notes: list[str] = []
        self.layouts: dict[int, PenLayout] = device_layouts(
            self.descriptor, vid, pid, params, protocol, name=name, notes=notes
        )
        if not self.layouts:
            reports = ", ".join(f"0x{r.report_id:02x}" for r in self.descriptor.input_reports()) or "none"
            raise DescriptorError(
                f"descriptor describes no pen report (input reports: {reports}) and no vendor "
                f"protocol is known for {vid or 0:04x}:{pid or 0:04x}"
            )
        self.compiled = {rid: CompiledLayout(lay) for rid, lay in self.layouts.items()}
        self._decoders = {rid: c.decode for rid, c in self.compiled.items()}
        self.uses_ids = self.descriptor.uses_report_ids
        self.known_ids = {rid for (_, rid) in self.descriptor.reports}
        self.stats = DecodeStats(warnings=[*self.descriptor.warnings, *notes])
        self._last_t = float("-inf")

    def decode(self, data: bytes, t: float, where: int = 0) -> PenSample | None:
        """Decode one report read at time ``t``; None (and a counted reason) when it is no pen sample."""
        stats = self.stats
        stats.reports += 1
        if t < self._last_t:
            stats.backwards += 1
        self._last_t = t
        if not data:
            stats.ignore(where, "empty report")
            return None
        rid = data[0] if self.uses_ids else 0
        fn = self._decoders.get(rid)
        if fn is None:
            if rid in self.known_ids:
                stats.ignore(where, f"report 0x{rid:02x} is not a pen report")
            else:
                stats.ignore(where, f"unknown report id 0x{rid:02x}")
            return None
        result = fn(data, t)
        if isinstance(result, str):
            stats.ignore(where, f"{result} 0x{rid:02x}")
            return None
        stats.samples += 1
        return result
