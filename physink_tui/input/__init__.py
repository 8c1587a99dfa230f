"""Pen input: HID descriptors and decoding, captures, devices; no scene or UI logic."""
