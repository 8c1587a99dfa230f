"""Stroke recognition: one stroke (or an X's two) to a primitive with beautified geometry; no interpretation."""
