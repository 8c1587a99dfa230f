"""The Textual control panel (`physink tui`, `physink demo` on a terminal); the only package that imports Textual."""
