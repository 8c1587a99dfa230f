"""One pen's samples to gestures: the sample (`sample.py`), its tip/range state machine (`state.py`), smoothing
(`smoothing.py`), the tablet-to-canvas mapping (`mapping.py`), the gesture engine (`gestures.py`) and the input side's
single consumer that strings them together (`pen_input.py`)."""
