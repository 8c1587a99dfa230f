"""Data shipped with the package: the bundled demo capture; no code."""
