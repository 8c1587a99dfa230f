"""Pen models written for the tests, independent of the virtual pen: hand-drawn input to check the recogniser with."""
