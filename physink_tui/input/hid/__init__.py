"""Tablet HID: report descriptors, pen layouts, decoders, device readers (hidraw, hidapi, pyusb), vendor init and
device facts."""
