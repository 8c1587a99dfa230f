"""Interpretation: recognised strokes read in the context of the scene (bodies, joints, springs, ropes, X pairs)."""
