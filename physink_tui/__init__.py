"""PhysInk TUI: sketch a machine with a pen tablet, demonstrate it, simulate it; this file names the version.

Importing the package imports nothing else, so the pure core (scene, timeline, sim) stays cheap to load.
"""

__version__ = "0.1.0"
