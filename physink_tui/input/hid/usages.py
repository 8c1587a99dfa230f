"""HID usage pages and usages a pen decoder needs, with names for text output; no parsing."""

from __future__ import annotations

PAGE_GENERIC_DESKTOP = 0x01
PAGE_BUTTON = 0x09
PAGE_DIGITIZER = 0x0D
PAGE_WACOM_DIGITIZER = 0xFF0D
"""Wacom's vendor page whose usages mirror the Digitizer page (0x130/0x131 stand for X/Y)."""


def usage(page: int, uid: int) -> int:
    """Return the 32-bit extended usage for a page and a usage id.

    >>> hex(usage(PAGE_DIGITIZER, 0x42))
    '0xd0042'
    """
    return (page << 16) | (uid & 0xFFFF)


# Generic Desktop
GD_POINTER = usage(1, 0x01)
GD_MOUSE = usage(1, 0x02)
GD_X = usage(1, 0x30)
GD_Y = usage(1, 0x31)
GD_WHEEL = usage(1, 0x38)

# Digitizer
DG_DIGITIZER = usage(0x0D, 0x01)
DG_PEN = usage(0x0D, 0x02)
DG_LIGHT_PEN = usage(0x0D, 0x03)
DG_TOUCH_SCREEN = usage(0x0D, 0x04)
DG_TOUCH_PAD = usage(0x0D, 0x05)
DG_WHITEBOARD = usage(0x0D, 0x06)
DG_STYLUS = usage(0x0D, 0x20)
DG_PUCK = usage(0x0D, 0x21)
DG_FINGER = usage(0x0D, 0x22)
DG_TIP_PRESSURE = usage(0x0D, 0x30)
DG_IN_RANGE = usage(0x0D, 0x32)
DG_TOUCH = usage(0x0D, 0x33)
DG_DATA_VALID = usage(0x0D, 0x37)
DG_INVERT = usage(0x0D, 0x3C)
DG_X_TILT = usage(0x0D, 0x3D)
DG_Y_TILT = usage(0x0D, 0x3E)
DG_TIP_SWITCH = usage(0x0D, 0x42)
DG_SECONDARY_TIP_SWITCH = usage(0x0D, 0x43)
DG_BARREL_SWITCH = usage(0x0D, 0x44)
DG_ERASER = usage(0x0D, 0x45)
DG_TABLET_PICK = usage(0x0D, 0x46)
DG_CONTACT_ID = usage(0x0D, 0x51)
DG_SECONDARY_BARREL_SWITCH = usage(0x0D, 0x5A)

BUTTON_1 = usage(PAGE_BUTTON, 1)
BUTTON_2 = usage(PAGE_BUTTON, 2)
BUTTON_3 = usage(PAGE_BUTTON, 3)

PAGE_NAMES = {
    0x01: "Generic Desktop",
    0x06: "Generic Device Controls",
    0x07: "Keyboard",
    0x08: "LED",
    0x09: "Button",
    0x0C: "Consumer",
    0x0D: "Digitizer",
    0x0F: "Physical Input Device",
    0x14: "Auxiliary Display",
    0x20: "Sensor",
    0x59: "Lighting",
    0xFF0D: "Wacom Digitizer",
}

USAGE_NAMES = {
    GD_POINTER: "Pointer",
    GD_MOUSE: "Mouse",
    usage(1, 0x06): "Keyboard",
    GD_X: "X",
    GD_Y: "Y",
    usage(1, 0x32): "Z",
    GD_WHEEL: "Wheel",
    usage(1, 0x3A): "Counted Buffer",
    DG_DIGITIZER: "Digitizer",
    DG_PEN: "Pen",
    DG_LIGHT_PEN: "Light Pen",
    DG_TOUCH_SCREEN: "Touch Screen",
    DG_TOUCH_PAD: "Touch Pad",
    DG_WHITEBOARD: "Whiteboard",
    usage(0x0D, 0x0E): "Device Configuration",
    DG_STYLUS: "Stylus",
    DG_PUCK: "Puck",
    DG_FINGER: "Finger",
    DG_TIP_PRESSURE: "Tip Pressure",
    usage(0x0D, 0x31): "Barrel Pressure",
    DG_IN_RANGE: "In Range",
    DG_TOUCH: "Touch",
    usage(0x0D, 0x34): "Untouch",
    usage(0x0D, 0x35): "Tap",
    usage(0x0D, 0x36): "Quality",
    DG_DATA_VALID: "Data Valid",
    usage(0x0D, 0x38): "Transducer Index",
    usage(0x0D, 0x3B): "Battery Strength",
    DG_INVERT: "Invert",
    DG_X_TILT: "X Tilt",
    DG_Y_TILT: "Y Tilt",
    usage(0x0D, 0x3F): "Azimuth",
    usage(0x0D, 0x40): "Altitude",
    usage(0x0D, 0x41): "Twist",
    DG_TIP_SWITCH: "Tip Switch",
    DG_SECONDARY_TIP_SWITCH: "Secondary Tip Switch",
    DG_BARREL_SWITCH: "Barrel Switch",
    DG_ERASER: "Eraser",
    DG_TABLET_PICK: "Tablet Pick",
    usage(0x0D, 0x47): "Confidence",
    usage(0x0D, 0x48): "Width",
    usage(0x0D, 0x49): "Height",
    DG_CONTACT_ID: "Contact Id",
    usage(0x0D, 0x54): "Contact Count",
    usage(0x0D, 0x55): "Contact Max",
    DG_SECONDARY_BARREL_SWITCH: "Secondary Barrel Switch",
    usage(0x0D, 0x5B): "Transducer Serial Number",
}


def canonical(u: int) -> int:
    """Map a Wacom vendor-page usage onto the standard usage it mirrors; others pass unchanged.

    >>> canonical(usage(0xFF0D, 0x130)) == GD_X, canonical(usage(0xFF0D, 0x42)) == DG_TIP_SWITCH
    (True, True)
    """
    if u >> 16 != PAGE_WACOM_DIGITIZER:
        return u
    uid = u & 0xFFFF
    if uid in (0x130, 0x131):
        return usage(PAGE_GENERIC_DESKTOP, uid - 0x100)
    return usage(PAGE_DIGITIZER, uid)


def usage_name(u: int) -> str:
    """A readable name such as ``Digitizer.Tip Switch`` or ``0xff00.0x0001``."""
    page, uid = u >> 16, u & 0xFFFF
    mirrored = canonical(u)
    if u in USAGE_NAMES:
        return USAGE_NAMES[u]
    if page == PAGE_WACOM_DIGITIZER and mirrored in USAGE_NAMES:
        return f"Wacom {USAGE_NAMES[mirrored]}"
    if page == PAGE_BUTTON:
        return f"B{uid}"
    return f"{PAGE_NAMES.get(page, f'0x{page:04x}')}.0x{uid:04x}"
