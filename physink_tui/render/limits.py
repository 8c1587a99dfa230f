"""The picture sizes and frame rates that rendering accepts, in one place: the renderer, the video writer and the
command line's options check against these; no drawing."""

MIN_SIDE = 16
"""Smallest width or height in pixels (H.264 and VP9 code 16x16 macroblocks; smaller is surely a mistake)."""

MAX_SIDE = 7680
"""Largest width or height in pixels (8K UHD's width; anything larger is surely a mistake and would exhaust memory)."""

MAX_FPS = 120
"""Highest frame rate accepted; 30 and 60 are the usual ones."""
