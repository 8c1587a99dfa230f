"""Speech input: recordings and the microphone to grammar-restricted commands, offline; acting on them is the
session's."""
