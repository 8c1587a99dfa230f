"""Demonstration to causal timeline (recorder, event DAG, equivalence); no I/O, clock or UI."""
