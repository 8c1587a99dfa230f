"""One pen's samples to gestures: the sample, its tip/range state machine, smoothing, the tablet-to-canvas
mapping and the gesture engine."""
