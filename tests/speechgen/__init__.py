"""A speech corpus across synthesisers (espeak-ng, flite, festival, SVOX Pico) for calibrating and checking speech
rejection on voices the thresholds were not chosen on (issue 29); see `corpus`."""
