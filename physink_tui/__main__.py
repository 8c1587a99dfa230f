"""Lets ``python -m physink_tui`` run the ``physink`` command line; all behaviour lives in cli."""

from physink_tui.cli import entry

entry()
