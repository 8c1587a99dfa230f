"""The kiosk on a serial (ISDV4) tablet: the real serial reader over a pty with a fake tablet; the hot zones are
found on the tablet's samples before they are mapped onto the canvas, and the journal holds canvas-space pen lines."""

from __future__ import annotations

import json
import threading
import time
from pathlib import Path

import pytest
from test_serial_reader import QUERY, FakeTablet

from physink_tui.formats.journal.entries import JournalHeader, PenEntry
from physink_tui.formats.journal.reader import read_journal
from physink_tui.input.pen.mapping import TabletMapping, mapping_to_header
from physink_tui.input.serial_tablets.isdv4 import encode_pen_packet
from physink_tui.input.serial_tablets.reader import SerialPenSource
from physink_tui.kiosk.folder_files import JOURNAL
from physink_tui.kiosk.hot_zones import default_zones
from physink_tui.kiosk.service import Kiosk, KioskSettings
from physink_tui.kiosk.store import SessionStore
from physink_tui.render.export import Look


def packet(x: float, y: float, *, tip: bool, proximity: bool = True) -> bytes:
    return encode_pen_packet(round(x * QUERY.x_max), round(y * QUERY.y_max), 600 if tip else 0, tip=tip,
                             proximity=proximity)


def test_a_serial_tablet_draws_on_the_canvas_and_taps_its_end_zone(tmp_path: Path) -> None:
    stroke = [packet(0.2 + 0.02 * i, 0.54, tip=True) for i in range(20)]
    end_tap = [packet(0.875, 0.04, tip=False), packet(0.875, 0.04, tip=True), packet(0.875, 0.04, tip=False)]
    tablet = FakeTablet(packet(0.2, 0.54, tip=False) + b"".join(stroke) + packet(0.6, 0.54, tip=False)
                        + b"".join(end_tap) + packet(0.875, 0.04, tip=False, proximity=False))
    try:
        # the reply ends the handshake as soon as it comes: a generous timeout costs nothing and a loaded machine
        # cannot miss it
        source = SerialPenSource(tablet.path, "serial0", settle_s=0.01, query_timeout=60.0)
        source.open()
        zones = default_zones()
        mapping = TabletMapping(canvas_width=1600, canvas_height=1000, tablet_width=1.6, tablet_height=1.0,
                                area=zones.area)
        header = JournalHeader(1600.0, 1000.0, (), mapping_to_header(mapping), 0.05, 0.01)
        out = tmp_path / "out"
        lines: list[str] = []
        kiosk = Kiosk(SessionStore(out), zones, KioskSettings(look=Look(160, 100, 10)), lines.append)
        runner = threading.Thread(target=kiosk.run, args=(source, None, header), kwargs={"replay": False,
                                                                                         "mapping": mapping})
        runner.start()
        deadline = time.monotonic() + 60  # hang guard
        while not (out / "index.jsonl").exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        kiosk.stop()
        runner.join(timeout=60)
        assert not runner.is_alive()
    finally:
        tablet.close()
    (record,) = [json.loads(line) for line in (out / "index.jsonl").read_text().splitlines()]
    assert record["ended"] == "end zone", lines
    pens = [e for e in read_journal(out / record["session"] / JOURNAL).entries if isinstance(e, PenEntry)]
    touching = [e for e in pens if e.tip]
    assert len(touching) == len(stroke)  # the stroke, and nothing of the tap on the zone
    assert all(e.y == pytest.approx((0.54 - 0.08) / 0.92, abs=1e-3) for e in touching)  # mapped below the strip
    assert touching[0].x < touching[-1].x
