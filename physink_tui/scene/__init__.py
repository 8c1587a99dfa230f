"""Sketch to physical scene (recognise strokes, interpret them, build the world); no I/O, clock or UI."""
