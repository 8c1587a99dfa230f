"""SIMULATE: searches parameters for a gravity timeline equivalent to the demo's; no I/O, clock or UI."""
