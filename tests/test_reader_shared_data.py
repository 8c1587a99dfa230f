"""Real tablet captures from ../shared/data/hid through the real reader: the same samples as decoding them directly.

The reader reads a SOCK_SEQPACKET socket standing in for /dev/hidrawN (it keeps report boundaries as
hidraw does, whatever the lengths); a writer thread sends the capture's reports. Skipped, saying why,
only when the shared data folder is absent.
"""

from __future__ import annotations

import os
import queue
import socket
import threading

import pytest
from shared_data import shared_path

from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.readers import HidrawReader
from physink_tui.input.sources import RawReport, SourceEnded

SHARED = shared_path("hid", module_level=True)

# one capture per decoding path: UC-Logic v1 with learnt polarity, Huion v2 vendor reports with pad reports
# and an undeclared id, KYE reports longer than declared, XP-Pen tilt, 10moons two reports per position
FILES = [
    "digimend__Huion_K26__if0.hid",
    "digimend__Huion_HS610__if0.hid",
    "digimend__KYE_MousePen_i608X_v2__if0.hid",
    "digimend__XP-Pen_Artist_16_Pro__if1.hid",
    "digimend__10moons_10x6__if2.hid",
]


@pytest.mark.parametrize("name", FILES)
def test_reader_path_gives_the_samples_of_direct_decoding(name: str) -> None:
    capture = Capture.from_file(SHARED / name)
    device = capture.devices[0]
    ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    reader = HidrawReader(os.dup(ours.fileno()), "tablet0")
    ours.close()
    q: queue.Queue = queue.Queue()
    reader.start(q)

    def send() -> None:
        for event in capture.events:
            theirs.sendall(event.data)
        theirs.close()

    writer = threading.Thread(target=send)
    writer.start()
    live = HidPenDecoder(device.descriptor, device.vid, device.pid)
    got = []
    while True:
        item = q.get(timeout=60)  # hang guard
        if isinstance(item, RawReport):
            sample = live.decode(item.data, item.t)
            if sample is not None:
                got.append(sample[1:])  # all but t: the reader stamps its own clock
        elif isinstance(item, SourceEnded):
            break
    writer.join()
    reader.stop()
    direct = HidPenDecoder(device.descriptor, device.vid, device.pid)
    want = [s[1:] for e in capture.events if (s := direct.decode(e.data, e.t)) is not None]
    assert len(got) == len(want) > 0
    assert got == want
    assert live.stats.ignored == direct.stats.ignored
