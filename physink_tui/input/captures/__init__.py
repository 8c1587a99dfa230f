"""Captures in the hid-recorder text format: parsing, streaming events, writing."""
