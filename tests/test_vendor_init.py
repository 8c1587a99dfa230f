"""Vendor initialisation against a fake USB device answering string descriptor requests with composed bytes.

The replies are built here field by field (header, then the little-endian maxima at the offsets hid-uclogic
reads), not copied from any device.
"""

from __future__ import annotations

import errno

import pytest

from physink_tui.errors import DeviceError
from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.hidraw import UDEV_INSTALL
from physink_tui.input.hid.reference_descriptors import REFERENCE_DEVICES
from physink_tui.input.hid.vendor_init import (
    VendorInit,
    find_vendor_init,
    initialise,
    initialise_usb,
    needs_vendor_init,
)
from physink_tui.input.hid.vendor_layouts import TabletParams

usb_core = pytest.importorskip("usb.core")


def string_reply(payload: bytes) -> bytes:
    """A USB string descriptor: bLength, bDescriptorType 3, payload."""
    return bytes([2 + len(payload), 3]) + payload


def text_reply(text: str) -> bytes:
    return string_reply(text.encode("utf-16-le"))


def v2_reply(x: int, y: int, p: int, res: int, extra: bytes = bytes([3, 0x0D, 0x10, 1, 4, 0x3C, 0x3E])) -> bytes:
    """24-bit X and Y maxima at 2 and 5, 16-bit pressure at 8 and resolution at 10, then model bytes."""
    return string_reply(x.to_bytes(3, "little") + y.to_bytes(3, "little") + p.to_bytes(2, "little")
                        + res.to_bytes(2, "little") + extra)


def v1_reply(x: int, y: int, p: int, res: int) -> bytes:
    """16-bit X, Y at 2 and 4, a zero word at 6, pressure at 8, resolution at 10."""
    words = (x, y, 0, p, res)
    return string_reply(b"".join(w.to_bytes(2, "little") for w in words))


class FakeTablet:
    """Answers GET_DESCRIPTOR(STRING) from a table; anything else stalls, like a real device (EPIPE)."""

    def __init__(self, strings: dict[int, bytes | Exception]) -> None:
        self.strings = strings
        self.asked: list[int] = []

    def ctrl_transfer(self, bm_request_type, b_request, w_value=0, w_index=0, length=None, timeout=None):
        assert (bm_request_type, b_request, w_value >> 8, w_index) == (0x80, 6, 3, 0x0409)
        index = w_value & 0xFF
        self.asked.append(index)
        answer = self.strings.get(index)
        if answer is None:
            raise usb_core.USBError("Pipe error", errno=errno.EPIPE)
        if isinstance(answer, Exception):
            raise answer
        return bytearray(answer[:length])


def test_a_v2_tablet_answers_0xc8_and_0x64_is_never_read() -> None:
    tablet = FakeTablet({0xC8: v2_reply(50800, 31750, 8191, 5080), 0x64: v1_reply(1, 1, 1, 1)})
    init = initialise(tablet, "256c:006d")
    assert init == VendorInit("huion-v2", TabletParams(50800, 31750, 8191, 5080), tablet.strings[0xC8])
    assert 0x64 not in tablet.asked and tablet.asked.index(0xC8) >= 0


def test_24_bit_maxima_beyond_16_bits() -> None:
    init = initialise(FakeTablet({0xC8: v2_reply(0x1_2345, 0x1_0000, 8191, 0)}))
    assert (init.params.x_max, init.params.y_max) == (0x1_2345, 0x1_0000)


def test_a_v1_tablet_stalls_on_0xc8_and_answers_0x64() -> None:
    tablet = FakeTablet({0x64: v1_reply(40000, 25000, 2047, 4000)})
    init = initialise(tablet)
    assert init.protocol == "uclogic-v1" and init.params == TabletParams(40000, 25000, 2047, 4000)
    assert tablet.asked[-2:] == [0xC8, 0x64]


def test_a_model_name_answered_for_every_unknown_string_is_not_parameters() -> None:
    name = text_reply("TABLET-MODEL-0123")  # 36 bytes of UTF-16LE text: long enough to pass for v2
    tablet = FakeTablet({0xC8: name, 0x64: v1_reply(32000, 20000, 1023, 2540)})
    assert initialise(tablet).protocol == "uclogic-v1"
    assert initialise(FakeTablet({0xC8: name, 0x64: name, 0xC9: name})) is None


def test_short_or_wrong_type_replies_are_not_v2() -> None:
    short = v2_reply(50800, 31750, 8191, 5080, extra=b"")  # 12 bytes: below the 18 v2 needs
    wrong_type = bytes([0x13, 0x02]) + v2_reply(50800, 31750, 8191, 5080)[2:]
    for reply in (short, wrong_type):
        assert initialise(FakeTablet({0xC8: reply})) is None


def test_zero_maxima_are_not_parameters() -> None:
    assert initialise(FakeTablet({0xC8: v2_reply(0, 31750, 8191, 0), 0x64: v1_reply(0, 0, 0, 0)})) is None


def test_transition_firmware_is_not_asked_for_v2() -> None:
    tablet = FakeTablet({0xC9: text_reply("HUION_T153_160607"), 0xC8: v2_reply(50800, 31750, 8191, 5080),
                         0x64: v1_reply(40000, 25000, 2047, 4000)})
    assert initialise(tablet).protocol == "uclogic-v1"
    assert 0xC8 not in tablet.asked


def test_a_time_out_is_a_string_not_answered() -> None:
    timeout = usb_core.USBTimeoutError("Operation timed out", errno=errno.ETIMEDOUT)
    tablet = FakeTablet({0xC8: timeout, 0x64: v1_reply(40000, 25000, 2047, 4000)})
    assert initialise(tablet).protocol == "uclogic-v1"


@pytest.mark.parametrize(("code", "words"), [
    (errno.EACCES, ["no permission", UDEV_INSTALL]),
    (errno.EBUSY, ["busy"]),
    (errno.ENODEV, ["disappeared"]),
    (errno.EIO, ["reading string descriptor 0xc9 failed"]),
])
def test_transfer_errors_become_one_clear_device_error(code: int, words: list[str]) -> None:
    fail = usb_core.USBError("libusb says no", errno=code)
    with pytest.raises(DeviceError) as info:
        initialise(FakeTablet({0xC9: fail, 0xC8: fail, 0x64: fail}), "256c:006d")
    message = str(info.value)
    assert "256c:006d" in message and "\n" not in message
    assert all(w in message for w in words)


def test_which_vendors_need_it() -> None:
    assert all(needs_vendor_init(v) for v in (0x256C, 0x5543, 0x28BD, 0x2FEB))
    assert not any(needs_vendor_init(v) for v in (0x056A, 0x0458, 0x172F, 0x1234))


def test_the_capture_comment_round_trips_and_feeds_the_decoder() -> None:
    init = VendorInit("huion-v2", TabletParams(50800, 31750, 8191, 5080))
    ref = REFERENCE_DEVICES["huion-v2"]
    text = f"# {init.comment()}\nR: {len(ref.descriptor)} {ref.descriptor.hex(' ')}\nI: 3 256c 006d\n"
    (device,) = Capture.from_text(text).devices
    back = find_vendor_init(device.comments)
    assert back is not None and (back.protocol, back.params) == (init.protocol, init.params)
    decoder = HidPenDecoder(device.descriptor, device.vid, device.pid, back.params, back.protocol)
    assert decoder.layouts[0x08].x.hi == 50800 and decoder.layouts[0x08].pressure.hi == 8191


@pytest.mark.parametrize("text", [
    "physink record 0.1.0: /dev/hidraw0",
    "physink vendor-init: protocol=mystery x_max=1 y_max=1 p_max=1",
    "physink vendor-init: protocol=huion-v2 x_max=0 y_max=1 p_max=1",
    "physink vendor-init: protocol=huion-v2 x_max=ten y_max=1 p_max=1",
])
def test_other_comments_are_not_vendor_inits(text: str) -> None:
    assert VendorInit.from_comment(text) is None


class FakeFound(FakeTablet):
    bus, address = 2, 9


def test_initialise_usb_finds_the_device_by_bus_and_address(monkeypatch) -> None:
    import usb.util

    disposed = []
    monkeypatch.setattr(usb.util, "dispose_resources", disposed.append)
    tablet = FakeFound({0x64: v1_reply(40000, 25000, 2047, 4000)})

    def find(idVendor, idProduct, custom_match):  # pyusb's keyword names
        assert (idVendor, idProduct) == (0x256C, 0x006E)
        return tablet if custom_match(tablet) else None

    assert initialise_usb(0x256C, 0x006E, 2, 9, find=find).protocol == "uclogic-v1"
    assert disposed == [tablet]
    with pytest.raises(DeviceError, match="does not see the device on bus 3"):
        initialise_usb(0x256C, 0x006E, 3, 9, find=find)


def test_initialise_usb_without_libusb_says_so() -> None:
    def find(**kwargs):
        raise usb_core.NoBackendError("No backend available")

    with pytest.raises(DeviceError, match="no libusb backend"):
        initialise_usb(0x256C, 0x006D, find=find)
